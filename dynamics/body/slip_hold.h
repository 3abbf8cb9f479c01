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
