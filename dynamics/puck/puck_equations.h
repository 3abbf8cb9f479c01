#pragma once
// The equations of motion of the puck (docs/puck.md), in the fixed horizontal frame:
//
//   m v' = F = -F1 e1 - F2 e2,     I omega' = -M,     x' = v,     heading' = omega,
//   W_slide' = F1 U,               W_spin' = M Omega,
//
// with U = |v|, e1 = v/U, e2 = z x e1 (z up), Omega = omega, psi the angle from e1 to the major
// axis (the heading) counter-clockwise, reduced to [0, pi), N = m g, and F1, F2, M from the friction
// law (friction/law.h) at (U, Omega, a, b, psi, N, k). The patch turns with the body, so psi
// changes as it spins, and F2 (zero for a circle) bends the path of an elliptic patch.
// Energy E = m v^2/2 + I omega^2/2 (the plane is horizontal and rigid); along solutions
// E' = -(F1 U + M Omega): F2 does no work.
//
// Holds (sticking, dynamics/puck/puck_run.h): once the slip speed has fallen below its threshold
// the velocity is held at 0 (v' = 0), once the spin has, omega is (omega' = 0): no other
// tangential force or torque acts on the puck, so zero friction keeps a held component at rest,
// and the friction set of every law contains zero. With both held the puck is at rest. A held
// slip gives the law U = 0 (e1 the major axis, psi = 0), a held spin Omega = 0.

#include <Eigen/Core>

#include <string>

#include "dynamics/core/observer.h"
#include "dynamics/core/pole_watch.h"
#include "dynamics/core/shadow_point.h"
#include "dynamics/puck/puck.h"
#include "dynamics/puck/puck_state.h"
#include "friction/law.h"

namespace frictionlab::dynamics::puck {

/// Components held at zero (sticking).
struct Holds {
  bool slip = false;  ///< v held at 0
  bool spin = false;  ///< omega held at 0
};

/// What the right-hand side computes about the contact for one state (also the output columns).
struct PuckContact {
  Eigen::Vector2d e1;      ///< slip direction (unit; the major axis when U = 0)
  double U = 0.0;          ///< slip speed |v|, m/s
  double Omega = 0.0;      ///< spin, 1/s
  double psi = 0.0;        ///< angle from e1 to the major axis, rad, [0, pi)
  double N = 0.0;          ///< normal force m g, N
  friction::FrictionForces friction;  ///< F1, F2 (N), M (N m)
  Eigen::Vector2d force;   ///< -F1 e1 - F2 e2, N
};

struct PuckRunSummary;  // dynamics/puck/puck_run.h

/// A model of the integration loop (dynamics/core/run_loop.h): the types and the members after "The
/// model interface" below; its events (the stops of slip and spin, held) are
/// dynamics/puck/puck_run.h's.
class PuckOnPlane {
 public:
  // The model interface of dynamics/core/run_loop.h: the mode is which components are held.
  static constexpr int kSize = PuckLayout::kSize;
  using State = PuckState;
  using Contact = PuckContact;
  using Mode = Holds;
  using Summary = PuckRunSummary;
  class Monitor;  // dynamics/puck/puck_run.cpp

  /// Throws std::invalid_argument for an invalid puck, k or g (naming the scenario key).
  PuckOnPlane(const Puck& puck, double k, double g, const friction::FrictionLaw& law);

  /// The contact at x. Throws what the law throws.
  [[nodiscard]] PuckContact contact(const PuckState& x, Holds holds = {}) const;
  /// dx/dt at x from c = contact(x, holds).
  void derivatives(const PuckState& x, const PuckContact& c, Holds holds, PuckState& dxdt) const;
  /// contact followed by derivatives.
  void operator()(const PuckState& x, Holds holds, PuckState& dxdt) const { derivatives(x, contact(x, holds), holds, dxdt); }

  /// m v^2/2 + I omega^2/2 (J): the whole mechanical energy.
  [[nodiscard]] double energy(const PuckState& x) const;

  // The model interface of dynamics/run_loop.h.
  void contact(const PuckState& x, const Holds& holds, PuckContact& c) const { c = contact(x, holds); }
  [[nodiscard]] double energy(const PuckState& x, const PuckContact& /*c*/) const { return energy(x); }
  [[nodiscard]] double energy(const PuckState& x, const Holds& /*holds*/) const { return energy(x); }
  [[nodiscard]] double kinetic_energy(const PuckState& x) const { return energy(x); }
  [[nodiscard]] PoleWatch::Point pole_point(const PuckContact& c) const {
    return PoleWatch::patch_point(c.U, c.Omega, puck_.a, puck_.b, c.psi);
  }
  /// The contact as the shadow laws see it (dynamics/core/shadow_observer.h): always in contact,
  /// its friction the law's at the contact's (held) slip and spin. Never throws.
  [[nodiscard]] ShadowPoint shadow_point(const PuckState& /*x*/, const PuckContact& c, const Holds& /*holds*/) const {
    ShadowPoint p;
    p.in_contact = true;
    p.input = {c.U, c.Omega, puck_.a, puck_.b, c.psi, c.N, k_};  // what contact() hands the law
    p.own = c.friction;
    p.own_known = true;
    return p;
  }
  /// The friction at a state, in one line (for failure messages only; never throws).
  [[nodiscard]] std::string describe_friction(const PuckState& x, const Holds& holds) const;
  [[nodiscard]] double friction_coefficient() const { return k_; }

  [[nodiscard]] const Puck& puck() const { return puck_; }
  [[nodiscard]] double k() const { return k_; }
  [[nodiscard]] double g() const { return g_; }
  [[nodiscard]] const friction::FrictionLaw& law() const { return law_; }

 private:
  Puck puck_;
  double k_;
  double g_;
  const friction::FrictionLaw& law_;
};

/// A sample and an observer of the puck's runs (dynamics/core/observer.h); the sample's mode is the holds.
using PuckSample = SampleOf<PuckOnPlane>;
using PuckObserver = ObserverOf<PuckOnPlane>;

}  // namespace frictionlab::dynamics::puck
