#pragma once
// The equations of motion (2)-(5) of the paper with the dots restored (docs/model.md), in the
// body frame C xi1 xi2 xi3 (origin at the centre of mass, the shape's axes, J the full central
// inertia tensor of dynamics/body/body.h; diag(A, A, C) for today's bodies of revolution):
//
//   Eq. (2)  m (v' + omega x v) = -m g gamma + N gamma + F
//   Eq. (3)  J omega' + omega x J omega = r x (N gamma + F) - M gamma
//   Eq. (4)  gamma' + omega x gamma = 0
//   Eq. (5)  eps' = u . gamma,   u = v + omega x r   (velocity of the contact point r)
//   Eq. (6)  N = lambda |eps|^(3/2) for eps < 0, else 0 (dynamics/contact/hertz_contact.h)
//   Eq. (7)  F = -F1 e1 - F2 e2, torque -M gamma, from the friction law; none when N = 0.
//
// The contact point and the principal radii come from the body's shape (dynamics/shapes/shape.h):
// the patch by the section hypothesis has the semi-axes sqrt(2 |eps| R_major), sqrt(2 |eps| R_minor)
// along the shape's `major` direction and the one across it (the Dupin indicatrix); with
// patch = "hertz" the two radii go to Hertz's ellipse (dynamics/contact/hertz_ellipse.h) and the
// torque that makes the contact conservative is dynamics/shapes/hertz_orientation_torque.h's.
// Today's bodies of revolution (Body::axisymmetric) keep today's arithmetic bit for bit: the
// contact from dynamics/shapes/contact_geometry.h, the Hertz contact from dynamics/contact/hertz_patch.h and
// J applied component-wise (the same operations in the same order as before shapes existed). A
// diagonal J (any shape) is applied component-wise too; a full J as a matrix, with its inverse
// computed once.
//
// The pose (dynamics/body/state.h) rides along: X' = (R(q) v)_1,2 and q' = q (0, omega)/2, R(q)
// the rotation of the normalised quaternion; nothing else reads it.
//
// e1 is the direction of u - (u.gamma) gamma (the slip of the contact point), U its magnitude;
// e2 = gamma x e1; Omega = omega . gamma. When U = 0, e1 is the major axis of the patch (psi = 0),
// so the choice is deterministic. r and the patch come from dynamics/shapes/contact_geometry.h; psi is the
// angle from e1 to the major axis, CCW about gamma, in [0, pi): the law gets it as the direction
// (cos psi, sin psi) = (major.e1, major.e2), scaled to unit length; no angle is formed
// (friction/patch_angle.h), psi.radians() forms it for the outputs.
//
// gamma is renormalised where it is read (forces, contact point, eps'); eq. (4) itself moves the
// stored gamma, which conserves |gamma| exactly, so its drift is only the integrator's error.
// The state also carries W_slide' = F1 U and W_spin' = M Omega (dynamics/body/state.h).
//
// Energy: E = m v^2/2 + omega.J omega/2 + m g h + (2/5) lambda |eps|^(5/2), h = eps - r.gamma the
// height of the centre of mass; along solutions E' = -(F1 U + M Omega) exactly. With
// [contact] patch = "hertz" the patch, N and the spring energy come from dynamics/contact/hertz_patch.h
// (lambda then depends on gamma3, and the torque that makes that contact conservative is added).

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products
#include <optional>
#include <string>

#include "dynamics/body/body.h"
#include "dynamics/shapes/contact_geometry.h"
#include "dynamics/shapes/toroidal_disk.h"
#include "dynamics/contact/hertz_contact.h"
#include "dynamics/contact/hertz_patch.h"
#include "dynamics/core/observer.h"
#include "dynamics/core/pole_watch.h"
#include "dynamics/core/shadow_point.h"
#include "dynamics/body/state.h"
#include "dynamics/body/stick.h"
#include "friction/law.h"

namespace frictionlab::dynamics {

/// What the right-hand side computes about the contact for one state (also the output columns).
struct ContactState {
  Eigen::Vector3d gamma;   ///< upward unit vertical, body frame
  Eigen::Vector3d major;   ///< major axis of the patch (unit, contact plane): the principal
                           ///< direction of the larger radius of curvature
  /// Contact point r (from the centre of mass, body frame) and principal radii. For a body that is
  /// not Body::axisymmetric, R_meridian holds R_major and R_parallel R_minor, and z the shape-frame
  /// third coordinate of the contact point.
  ContactPoint point;
  Eigen::Vector3d u;       ///< velocity of the contact point, m/s
  Eigen::Vector3d e1;      ///< slip direction (unit, in the contact plane)
  double U = 0.0;          ///< slip speed |u - (u.gamma) gamma|, m/s
  double Omega = 0.0;      ///< spin omega.gamma, 1/s
  double N = 0.0;          ///< normal force, N
  bool in_contact = false; ///< eps < 0
  double a = 0.0;          ///< major semi-axis of the patch, m (0 out of contact)
  double b = 0.0;          ///< minor semi-axis, m
  friction::PatchAngle psi;  ///< from e1 to the major axis: its direction (cos, sin) as the law
                             ///< reads it; psi.radians() in [0, pi), formed only when asked for
  friction::FrictionForces friction;  ///< F1, F2 (N), M (N m); zero out of contact
  /// The power the friction force takes from the slip, -F.u_t (W): F1 U where e1 is the slip's
  /// direction; in the stick and creep modes, where e1 is not, the dot product itself.
  double slide_power = 0.0;
  Eigen::Vector3d force;   ///< total contact force N gamma + F, body frame, N
  Eigen::Vector3d torque;  ///< contact torque about the centre of mass, N m
};

struct RunSummary;  // dynamics/body/simulation.h

/// The body's discrete mode (dynamics/core/run_loop.h; docs/dynamics.md §5 "stick"), set by the
/// run's monitor (dynamics/body/simulation.cpp). Default: free, the equations of the header comment.
struct BodyMode {
  /// Stick: the contact rolls without slip and without spin; the friction is the wrench that keeps
  /// it so (dynamics/body/stick.h), not the law's.
  bool stick = false;
  /// Creep at the limit (after an exit from stick or a refused entry): while the slip and the spin
  /// are both below their floors (U < departure_slip, |Omega| < departure_spin: the stagnation
  /// region), the law is evaluated in the direction of creep (dynamics/core/limit_set.h), which the
  /// monitor updates between steps, not in the slip's own direction, whose dynamics is stiff there.
  bool departing = false;
  double departure_alpha = 0.0;  ///< slip direction from the major axis, rad
  double departure_beta = 0.0;   ///< elevation, tan beta = a Omega / U, rad
  double departure_slip = 0.0;   ///< m/s
  double departure_spin = 0.0;   ///< 1/s
  /// The slip held on its slow manifold (dynamics/body/slip_hold.h): where the slip is small, the
  /// spin is not and the slip's own dynamics is stiff, the tangential friction force is the one
  /// that keeps the slip's rate at `slip_rate` (body frame, m/s^2, set by the monitor between
  /// steps), the spin moment the law's at the state's slip; the spin stays free.
  bool hold = false;
  Eigen::Vector3d slip_rate = Eigen::Vector3d::Zero();
  /// After the zero slip of a law discontinuous there was held (slip_hold.h): the law sees the slip
  /// along `slip_exit` (body frame, unit, the direction in which it starts) with the state's own
  /// spin, not along the residue of the hold, whose direction is rounding noise; the monitor ends
  /// the mode between steps once the slip reaches `departure_slip` (or turns back).
  bool slip_departing = false;
  Eigen::Vector3d slip_exit = Eigen::Vector3d::Zero();
  /// The spin of a law discontinuous in the spin held at zero (slip_hold.h): the spin moment is the
  /// one that keeps the spin's rate at `spin_rate` (1/s^2, set by the monitor between steps), the
  /// force the law's at the state's slip and zero spin; the slip stays free.
  bool spin_hold = false;
  double spin_rate = 0.0;
  /// After it: the law sees the spin with the sign `spin_exit` (+1 or -1) until the monitor ends
  /// the mode (the spin reaches `departure_spin` or turns back).
  bool spin_departing = false;
  double spin_exit = 0.0;

  /// No mode is on: the friction is the law's at the contact's own slip and spin.
  [[nodiscard]] bool free() const {
    return !(stick || departing || hold || slip_departing || spin_hold || spin_departing);
  }
};

/// The right-hand side: a small const functor holding its parameters and the law chosen once.
/// No heap allocation per call. Not copyable by accident of the law reference: the law must
/// outlive it. It is a model of the integration loop (dynamics/core/run_loop.h): the types and the
/// members after "The model interface" below; its events are dynamics/body/simulation.h's.
class BodyOnPlane {
 public:
  // The model interface of dynamics/run_loop.h.
  static constexpr int kSize = StateLayout::kSize;
  static constexpr int kPoseFreeSize = StateLayout::kPoseFreeSize;
  using State = StateVector;
  using Contact = ContactState;
  using Mode = BodyMode;
  using Summary = RunSummary;
  class Monitor;  // the body's events, dynamics/body/simulation.cpp

  /// Throws std::invalid_argument for invalid plane parameters.
  BodyOnPlane(Body body, const PlaneContact& plane, const friction::FrictionLaw& law);

  /// dx/dt at (t, x). Throws what the law throws (invalid input, e.g. a non-finite state).
  void operator()(double t, const StateVector& x, StateVector& dxdt) const;
  /// dx/dt at x from its contact quantities `c` = contact_state(x) (for callers that inspect `c`
  /// first, e.g. dynamics/core/pole_watch.h): operator() is contact_state followed by this.
  void derivatives(const StateVector& x, const ContactState& c, StateVector& dxdt) const;
  /// The same without the pose's rates: dxdt's components from StateLayout::kPoseFreeSize on are
  /// left as they were (run.pose = false, dynamics/core/run_loop.h).
  void derivatives_without_pose(const StateVector& x, const ContactState& c, StateVector& dxdt) const;

  /// The contact quantities at x (the same code path as operator()).
  [[nodiscard]] ContactState contact_state(const StateVector& x) const {
    ContactState c;
    contact_state(x, c);
    return c;
  }
  /// The same, written over `c` (every field): for a caller that keeps it (the integrator's
  /// right-hand side keeps its latest, dynamics/body/simulation.cpp), without copying the result.
  void contact_state(const StateVector& x, ContactState& c) const { contact_state(x, c, true); }
  /// The same, with the law's friction or none (`with_friction` false: F1 = F2 = M = 0).
  void contact_state(const StateVector& x, ContactState& c, bool with_friction) const;
  /// The contact in stick or departing (see BodyMode): the friction is the stick wrench, or the
  /// law's in the exit direction. Throws what the law throws.
  void contact_in_mode(const StateVector& x, const BodyMode& mode, ContactState& c) const;
  /// The law's friction at the contact c (its patch, load and frame) for the tangential slip
  /// `slip` (m/s, in the contact plane) and the spin Omega (1/s) instead of c's own, in the slip
  /// frame e1 (the slip's direction; c.major at zero slip) with the patch angle psi, both returned.
  /// Throws what the law throws.
  [[nodiscard]] friction::FrictionForces law_at_slip(const ContactState& c, const Eigen::Vector3d& slip, double Omega,
                                                     Eigen::Vector3d& e1, friction::PatchAngle& psi) const;
  /// What the stick and slip-hold solves need at x (dynamics/body/stick.h); `c` =
  /// contact_state(x, c, false), the contact without friction.
  [[nodiscard]] StickProblem stick_problem(const StateVector& x, const ContactState& c) const;
  /// Adds the friction `f` of the law, in the slip frame (e1, gamma x e1), to c's force and torque.
  static void add_friction(ContactState& c, const Eigen::Vector3d& e1, const friction::FrictionForces& f);
  /// The body's inertia tensor J about the centre of mass, kg m^2.
  [[nodiscard]] Eigen::Matrix3d inertia_tensor() const { return diagonal_ ? Eigen::Matrix3d(inertia_.asDiagonal()) : J_; }

  /// Total mechanical energy (J), see the header comment; `c` must be contact_state(x).
  [[nodiscard]] double energy(const StateVector& x, const ContactState& c) const;
  [[nodiscard]] double energy(const StateVector& x) const { return energy(x, contact_state(x)); }
  /// m v^2/2 + omega.J omega/2 (J).
  [[nodiscard]] double kinetic_energy(const StateVector& x) const;

  // The model interface of dynamics/core/run_loop.h (the mode changes the friction only: contact()).
  void contact(const StateVector& x, const BodyMode& mode, ContactState& c) const {
    if (mode.free()) {
      contact_state(x, c);
    } else {
      contact_in_mode(x, mode, c);  // dynamics/body/stick_contact.cpp
    }
  }
  void derivatives(const StateVector& x, const ContactState& c, const BodyMode& /*mode*/, StateVector& dxdt) const {
    derivatives(x, c, dxdt);
  }
  void derivatives_without_pose(const StateVector& x, const ContactState& c, const BodyMode& /*mode*/,
                                StateVector& dxdt) const {
    derivatives_without_pose(x, c, dxdt);
  }
  [[nodiscard]] double energy(const StateVector& x, const BodyMode& /*mode*/) const { return energy(x); }
  /// The shape coordinates of the contact for the watch of the law's poles (dynamics/core/pole_watch.h):
  /// in contact from the patch; out of contact the patch has shrunk to nothing (s = inf) and b/a
  /// is its limit as the depth goes to 0, sqrt(R_min/R_max) of the principal radii.
  [[nodiscard]] static PoleWatch::Point pole_point(const ContactState& c);
  /// The contact at x as the shadow laws see it (dynamics/core/shadow_observer.h); `c` =
  /// contact(x, mode). Never throws.
  [[nodiscard]] ShadowPoint shadow_point(const StateVector& x, const ContactState& c, const BodyMode& mode) const;
  /// The friction at a state, in one line (for failure messages only; never throws).
  [[nodiscard]] std::string describe_friction(const StateVector& x, const BodyMode& mode) const;
  [[nodiscard]] double friction_coefficient() const { return plane_.k; }

  [[nodiscard]] const Body& body() const { return body_; }
  [[nodiscard]] const PlaneContact& plane() const { return plane_; }
  [[nodiscard]] const friction::FrictionLaw& law() const { return law_; }
  /// Where the point contact of the shape ends: a toroidal disk whose face reaches the plane
  /// (penetration depth >= ToroidalDisk::face_clearance(gamma), dynamics/shapes/toroidal_disk.h). A
  /// message saying so, or empty while the point contact holds. `c` = contact_state(x).
  [[nodiscard]] std::string point_contact_end(const StateVector& x, const ContactState& c) const;
  /// The rule point_contact_end() applies, for the summary.
  static constexpr const char* kFlatFaceRule =
      "in contact with the penetration depth |eps| >= the face clearance rho (1 - |gamma3|) of the toroidal disk";

  /// Today's contact geometry of a Body::axisymmetric body (std::logic_error for another body).
  [[nodiscard]] const ContactGeometry& geometry() const;
  /// The central inertia tensor J (body axes, kg m^2) and its inverse.
  [[nodiscard]] const Eigen::Matrix3d& inertia() const { return J_; }
  [[nodiscard]] const Eigen::Matrix3d& inverse_inertia() const { return J_inv_; }
  /// J omega (kg m^2/s): component-wise for a diagonal J (the bits of today's bodies).
  [[nodiscard]] Eigen::Vector3d angular_momentum(const Eigen::Vector3d& w) const {
    return diagonal_ ? Eigen::Vector3d(inertia_.cwiseProduct(w)) : Eigen::Vector3d(J_ * w);
  }
  /// J^-1 t (1/s^2 for a torque t in N m): component-wise for a diagonal J.
  [[nodiscard]] Eigen::Vector3d apply_inverse_inertia(const Eigen::Vector3d& t) const {
    return diagonal_ ? Eigen::Vector3d(inv_inertia_.cwiseProduct(t)) : Eigen::Vector3d(J_inv_ * t);
  }

 private:
  // The contact point, patch and normal contact of a body that is not Body::axisymmetric.
  void shape_contact(const Eigen::Vector3d& gamma, double eps, ContactState& c, PatchShape& patch,
                     Eigen::Vector3d& hertz_torque) const;

  Body body_;
  PlaneContact plane_;
  const friction::FrictionLaw& law_;
  std::optional<ContactGeometry> geometry_;  ///< set for a Body::axisymmetric body
  const shapes::ToroidalDisk* disk_ = nullptr;  ///< the shape, when it is a toroidal disk
  std::optional<HertzNormalContact> hertz_;  ///< set when plane.patch = hertz
  bool diagonal_ = true;         ///< J is diagonal
  Eigen::Vector3d inertia_;      ///< the diagonal of J, (A, A, C) for a body of revolution
  Eigen::Vector3d inv_inertia_;  ///< its reciprocals
  Eigen::Matrix3d J_;
  Eigen::Matrix3d J_inv_;
};

/// A sample and an observer of the body's runs (dynamics/core/observer.h).
using Sample = SampleOf<BodyOnPlane>;
using Observer = ObserverOf<BodyOnPlane>;

}  // namespace frictionlab::dynamics
