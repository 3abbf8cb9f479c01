#include "dynamics/body/slip_hold.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <Eigen/SVD>

namespace frictionlab::dynamics {

double largest_slip_response(const StickProblem& p, const Eigen::Vector3d& t1) {
  const Eigen::Matrix3d G = slip_response(p, t1);
  const double m = 0.5 * (G(0, 0) + G(1, 1));
  const double d = 0.5 * (G(0, 0) - G(1, 1));
  const double off = 0.5 * (G(0, 1) + G(1, 0));
  return m + std::sqrt(d * d + off * off);
}

double zero_slip_resistance(const BodyOnPlane& sys, const ContactState& c, const Eigen::Vector3d& e) {
  const double U = kZeroSlipRatio * c.a * std::max(std::abs(c.Omega), 1.0);
  Eigen::Vector3d e1;
  friction::PatchAngle psi;
  const friction::FrictionForces f = sys.law_at_slip(c, U * e, c.Omega, e1, psi);
  const Eigen::Vector3d force = -f.F1 * e1 - f.F2 * c.gamma.cross(e1);
  return -force.dot(e);
}

double zero_spin_speed(const ContactState& c) { return kZeroSlipRatio * std::max(c.U / c.a, 1.0); }

double zero_spin_resistance(const BodyOnPlane& sys, const ContactState& c, double sign) {
  const Eigen::Vector3d slip = c.u - c.u.dot(c.gamma) * c.gamma;
  Eigen::Vector3d e1;
  friction::PatchAngle psi;
  return sign * sys.law_at_slip(c, slip, sign * zero_spin_speed(c), e1, psi).M;
}

HeldSlip held_slip(const BodyOnPlane& sys, const ContactState& c, const StickProblem& p,
                   const Eigen::Vector3d& slip_rate, const Eigen::Vector3d& start) {
  HeldSlip out;
  const double kN = sys.plane().k * c.N;
  const double scale = c.a * std::abs(c.Omega);  // a |Omega|: the slip of s = 1, m/s
  if (!(kN > 0.0) || !(scale > 0.0)) return out;
  const Eigen::Vector3d t1 = c.major;
  const Eigen::Vector3d t2 = c.gamma.cross(t1);
  const SlipHoldForce hold = slip_hold_force(p, slip_rate);
  // The residual in the contact plane's coordinates (t1, t2), in units of kN, at the slip w.
  const auto residual = [&](const Eigen::Vector2d& w) -> Eigen::Vector2d {
    Eigen::Vector3d e1;
    friction::PatchAngle psi;
    const Eigen::Vector3d slip = w[0] * t1 + w[1] * t2;
    const friction::FrictionForces f = sys.law_at_slip(c, slip, c.Omega, e1, psi);
    ++out.evaluations;
    const Eigen::Vector3d law_force = -f.F1 * e1 - f.F2 * c.gamma.cross(e1);
    const Eigen::Vector3d r = (law_force - hold.force0 - f.M * hold.force_per_M) / kN;
    return {r.dot(t1), r.dot(t2)};
  };
  constexpr double kResidual = 1e-11;
  constexpr int kIterations = 40;
  const double h = 1e-7 * scale;  // the finite-difference step: s changes by 1e-7
  Eigen::Vector2d w(start.dot(t1), start.dot(t2));
  Eigen::Vector2d r = residual(w);
  Eigen::Matrix2d J;
  for (int it = 0; it < kIterations && r.allFinite(); ++it) {
    for (int j = 0; j < 2; ++j) {
      Eigen::Vector2d wj = w;
      wj[j] += h;
      J.col(j) = (residual(wj) - r) / h;
    }
    if (r.norm() <= kResidual) {
      out.found = true;
      break;
    }
    const Eigen::Vector2d step = J.partialPivLu().solve(-r);
    if (!step.allFinite()) break;
    double lambda = 1.0;
    Eigen::Vector2d trial = w + step;
    Eigen::Vector2d r_trial = residual(trial);
    for (int halvings = 0; halvings < 30 && !(r_trial.norm() < r.norm()); ++halvings) {
      lambda *= 0.5;
      trial = w + lambda * step;
      r_trial = residual(trial);
    }
    if (!(r_trial.norm() < r.norm())) break;  // no descent: no manifold here
    w = trial;
    r = r_trial;
    if (w.norm() > kHoldMaxRatio * scale) break;
  }
  if (!out.found) return out;
  out.slip = w[0] * t1 + w[1] * t2;
  out.ratio = w.norm() / scale;
  if (out.ratio > kHoldMaxRatio) {
    out.found = false;
    return out;
  }
  // The slip's relaxation rate: the response G times the law's stiffness dF/dw (kN J, N s/m);
  // bounded by their largest eigenvalue and singular value.
  const Eigen::JacobiSVD<Eigen::Matrix2d> svd(J);
  out.stiffness = largest_slip_response(p, t1) * kN * svd.singularValues()[0];
  return out;
}

}  // namespace frictionlab::dynamics
