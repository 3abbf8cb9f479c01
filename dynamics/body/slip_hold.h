#pragma once
// The slip held on its slow manifold (docs/dynamics.md §5 "slip hold"): where the contact rolls
// with a small slip while it spins, the slip's own dynamics is stiff. Near zero slip every coupled
// law's force grows like kN s (s = U/(a |Omega|): k N (3 pi/8) s for a Hertz pressure on a circle,
// k N s for a uniform one), so the slip relaxes at a rate ~ g k N/(a |Omega|) (g the body's slip
// response, dynamics/body/stick.h): ~8e5 1/s for the 15 g tippe top near the end of its spin,
// against the body's own rates of ~10 1/s. The explicit integrator then crawls at the relaxation's
// time scale. On the slow manifold the slip w* is where the law's force equals the
// force that keeps the slip's rate at the manifold's own (the fast direction has relaxed):
//     F_law(w*, Omega) = F_hold(M_law(w*, Omega)),
// F_hold(M) the force of slip_hold_force (affine in the spin moment M, which stays the law's). The
// mode integrates the body with F_hold and the law's M at the state's slip, the slip's rate set
// between steps to the rate of w* plus the rate that closes the slip's gap to w* within a step:
// no impulse, the holding force does the work, counted as friction's (its power -F.u_t). The
// reduction's error is of the order of the ratio of the time scales, 1/(lambda T). The mode is
// entered where lambda is stiff both against the body's slow time T (the reduction is accurate)
// and against the step just taken (the integrator's steps are held by it: otherwise, e.g. where the
// contact's normal vibration holds them, holding the slip gains nothing).
//
// A law whose force does not vanish with the slip (`decoupled`: kN along any slip however small)
// has no such manifold: its slip stops in finite time and then the force jumps with the slip's sign
// (an explicit integrator chatters). Its slow manifold is the zero slip itself (Filippov's sliding
// mode): the same mode holds U = 0 with the same force (w* = 0, the spin free with the law's moment)
// for as long as that force lies within what the law resists at zero slip (its force in the limit
// U -> 0+ in the direction the slip would start), and leaves at the located time where it does not.
// The spin likewise: a law discontinuous in the spin (`decoupled`: M0 sign(Omega)) has its spin
// held at zero while the body slips, with the moment that keeps it there and the law's force, for
// as long as that moment is within the law's M0.

#include <Eigen/Core>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/body/stick.h"

namespace frictionlab::dynamics {

/// The numbers of the mode (docs/dynamics.md §5 "slip hold").
inline constexpr double kHoldStiffness = 1e3;      ///< enter where lambda T >= this (T: the body's slow time)
inline constexpr double kHoldStayFactor = 0.25;    ///< stay while lambda T >= this x kHoldStiffness
inline constexpr double kHoldEntryRatio = 0.5;     ///< enter only where s = U/(a |Omega|) < this
inline constexpr double kHoldMaxRatio = 10.0;      ///< no manifold beyond s = this (F ~ kN: not stiff)
inline constexpr double kHoldStepStiffness = 2.0;  ///< enter where lambda h >= this (h: the step just taken)

/// A law resists a vanishing slip with at least this fraction of kN: it is discontinuous at zero slip
/// (`decoupled`). At s = U/(a |Omega|) = kZeroSlipRatio a coupled law's force is ~kZeroSlipRatio kN.
inline constexpr double kDiscontinuousResistance = 1e-6;
inline constexpr double kZeroSlipRatio = 1e-12;  ///< the slip ratio at which the limit U -> 0+ is read

/// The law's resistance to a slip that starts along `e` (a unit vector in the contact plane) at the
/// contact `c` with its own spin: -F.e, N, for the slip s = kZeroSlipRatio (U = s a max(|Omega|, 1 1/s)). The force of a law continuous at zero slip vanishes there; a discontinuous
/// law's is its limit U -> 0+ (kN for `decoupled`).
[[nodiscard]] double zero_slip_resistance(const BodyOnPlane& sys, const ContactState& c, const Eigen::Vector3d& e);

/// The law's resistance to a spin that starts with the sign `sign` (+1 or -1) at the contact `c`
/// with its own slip: sign M, N m, for a|Omega|/U = kZeroSlipRatio (|Omega| = kZeroSlipRatio
/// max(U/a, 1 1/s)). A coupled law's moment vanishes there; `decoupled`'s is M0.
[[nodiscard]] double zero_spin_resistance(const BodyOnPlane& sys, const ContactState& c, double sign);
/// The spin at which zero_spin_resistance reads the law, 1/s.
[[nodiscard]] double zero_spin_speed(const ContactState& c);

/// The slip on the slow manifold at one state.
struct HeldSlip {
  bool found = false;           ///< the solve converged with s* <= kHoldMaxRatio
  Eigen::Vector3d slip = Eigen::Vector3d::Zero();  ///< w*, tangential, m/s (body frame)
  double ratio = 0.0;           ///< s* = |w*|/(a |Omega|)
  double stiffness = 0.0;       ///< lambda: relaxation rate of the slip at w*, 1/s
  int evaluations = 0;          ///< law evaluations spent
};

/// w* at the contact `c` (contact_state(x, c, false): the contact without friction) with the stick
/// problem `p` (BodyOnPlane::stick_problem), for the slip rate `slip_rate` (m/s^2), by Newton's
/// method from `start` (a tangential slip, m/s) with a finite-difference Jacobian and a halving line
/// search, to a residual of 1e-11 kN.
[[nodiscard]] HeldSlip held_slip(const BodyOnPlane& sys, const ContactState& c, const StickProblem& p,
                                 const Eigen::Vector3d& slip_rate, const Eigen::Vector3d& start);

/// The largest eigenvalue of the tangential block of the slip response G (dynamics/body/stick.h),
/// 1/kg: the rate of the slip per unit force and time.
[[nodiscard]] double largest_slip_response(const StickProblem& p, const Eigen::Vector3d& t1);

}  // namespace frictionlab::dynamics
