#include "dynamics/core/limit_set.h"

#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace frictionlab::dynamics {
namespace {

constexpr double kPi = std::numbers::pi;

// The same direction with beta in [-pi/2, pi/2]: a step of the search past a pole comes down on
// the other side of it (alpha turned by pi).
SlipDirection wrapped(SlipDirection d) {
  if (d.beta > 0.5 * kPi) {
    d.beta = kPi - d.beta;
    d.alpha += kPi;
  } else if (d.beta < -0.5 * kPi) {
    d.beta = -kPi - d.beta;
    d.alpha += kPi;
  }
  d.beta = std::clamp(d.beta, -0.5 * kPi, 0.5 * kPi);
  return d;
}

// The unit vector of d in the coordinates (x, y, a Omega).
Eigen::Vector3d unit(const SlipDirection& d) {
  const bool pole = std::abs(d.beta) >= 0.5 * kPi;
  const double cb = pole ? 0.0 : std::cos(d.beta);
  const double sb = pole ? std::copysign(1.0, d.beta) : std::sin(d.beta);
  return {cb * std::cos(d.alpha), cb * std::sin(d.alpha), sb};
}

// 1/sqrt(d^T Q d): the weight of the margin at d (1 without a metric).
double weight(const SlipDirection& d, const Eigen::Matrix3d* metric) {
  if (!metric) return 1.0;
  const Eigen::Vector3d u = unit(d);
  return 1.0 / std::sqrt(u.dot(*metric * u));
}

}  // namespace

LimitSet::LimitSet(const friction::FrictionLaw& law, double k, double N, double a, double b)
    : law_(law), k_(k), N_(N), a_(a), b_(b), kN_(k * N) {
  degenerate_ = !(kN_ > 0.0);
  if (!degenerate_) {
    const double up = support({0.0, 0.5 * kPi});
    const double down = support({0.0, -0.5 * kPi});
    degenerate_ = !(std::min(up, down) > kDegenerateSpin);
  }
}

friction::FrictionForces LimitSet::evaluate(const SlipDirection& d) const {
  // Unit (U, a Omega); exact zeros on the pure-slip circle and at the pure spins.
  const bool pole = std::abs(d.beta) >= 0.5 * kPi;
  const double U = pole ? 0.0 : std::cos(d.beta);
  const double Omega = d.beta == 0.0 ? 0.0 : (pole ? std::copysign(1.0, d.beta) : std::sin(d.beta)) / a_;
  // psi: from e1 (at alpha from the major axis) to the major axis, -alpha; folded to [0, pi) as
  // a direction (cos psi, sin psi) with sin psi >= 0.
  double c = std::cos(d.alpha), s = -std::sin(d.alpha);
  if (s < 0.0 || (s == 0.0 && c < 0.0)) {
    c = -c;
    s = -s;
  }
  return law_.evaluate({U, Omega, a_, b_, friction::PatchAngle::from_direction(c, s + 0.0), N_, k_});
}

double LimitSet::support(const SlipDirection& d) const {
  const friction::FrictionForces f = evaluate(d);
  const bool pole = std::abs(d.beta) >= 0.5 * kPi;
  const double U = pole ? 0.0 : std::cos(d.beta);
  const double aOmega = pole ? std::copysign(1.0, d.beta) : std::sin(d.beta);
  return (f.F1 * U + f.M / a_ * aOmega) / kN_;
}

PatchWrench LimitSet::resistance(const SlipDirection& d) const {
  const friction::FrictionForces f = evaluate(d);
  // F1 e1 + F2 e2 in the patch frame: e1 = (cos alpha, sin alpha), e2 = (-sin alpha, cos alpha).
  const double ca = std::cos(d.alpha), sa = std::sin(d.alpha);
  return {(f.F1 * ca - f.F2 * sa) / kN_, (f.F1 * sa + f.F2 * ca) / kN_, f.M / (kN_ * a_)};
}

SlipDirection LimitSet::creep_direction(const PatchWrench& rho_SI, const SlipDirection& start,
                                        const Eigen::Matrix3d& response, bool& found, long& evaluations) const {
  found = false;
  if (degenerate_) return start;
  const Eigen::Vector3d target(rho_SI.Fx / kN_, rho_SI.Fy / kN_, rho_SI.M / (kN_ * a_));
  // The slip's rate w = G (rho* - rho(d)) in the tangent frame of the sphere at d: (w.e_alpha,
  // w.e_beta) / |w| vanishes where w is along d; lambda = w.d.
  const auto rate = [&](const SlipDirection& d, double& lambda) -> Eigen::Vector2d {
    const PatchWrench r = resistance(d);
    ++evaluations;
    const Eigen::Vector3d w = response * (target - Eigen::Vector3d(r.Fx, r.Fy, r.M));
    const double ca = std::cos(d.alpha), sa = std::sin(d.alpha), cb = std::cos(d.beta), sb = std::sin(d.beta);
    lambda = w.dot(Eigen::Vector3d(cb * ca, cb * sa, sb));
    const double norm = w.norm();
    return Eigen::Vector2d(w.dot(Eigen::Vector3d(-sa, ca, 0.0)), w.dot(Eigen::Vector3d(-sb * ca, -sb * sa, cb))) /
           (norm > 0.0 ? norm : 1.0);
  };
  constexpr int kIterations = 30;
  constexpr double kStep = 1e-7;  // rad, the finite-difference step
  SlipDirection d = start;
  double lambda = 0.0;
  Eigen::Vector2d r = rate(d, lambda);
  for (int it = 0; it < kIterations && r.allFinite(); ++it) {
    if (r.norm() <= kDirectionTolerance) {
      found = lambda > 0.0;
      return d;
    }
    Eigen::Matrix2d J;
    double unused = 0.0;
    J.col(0) = (rate({d.alpha + kStep, d.beta}, unused) - r) / kStep;
    J.col(1) = (rate({d.alpha, d.beta + kStep}, unused) - r) / kStep;
    const Eigen::Vector2d step = J.partialPivLu().solve(-r);
    if (!step.allFinite()) break;
    // Halve a step that does not reduce the residual.
    double scale = 1.0;
    SlipDirection next{d.alpha + step[0], std::clamp(d.beta + step[1], -0.5 * kPi, 0.5 * kPi)};
    double next_lambda = 0.0;
    Eigen::Vector2d next_r = rate(next, next_lambda);
    for (int h = 0; h < 20 && !(next_r.norm() < r.norm()); ++h) {
      scale *= 0.5;
      next = {d.alpha + scale * step[0], std::clamp(d.beta + scale * step[1], -0.5 * kPi, 0.5 * kPi)};
      next_r = rate(next, next_lambda);
    }
    if (!(next_r.norm() < r.norm())) break;
    d = next;
    r = next_r;
    lambda = next_lambda;
  }
  return d;
}

double LimitSet::margin(const PatchWrench& rho, const SlipDirection& d) const {
  const bool pole = std::abs(d.beta) >= 0.5 * kPi;
  const double cb = pole ? 0.0 : std::cos(d.beta);
  const double sb = pole ? std::copysign(1.0, d.beta) : std::sin(d.beta);
  const double dot = (rho.Fx * std::cos(d.alpha) + rho.Fy * std::sin(d.alpha)) * cb + rho.M * sb;
  return support(d) - dot;
}

double LimitSet::objective(const PatchWrench& rho, const SlipDirection& d, const Eigen::Matrix3d* metric) const {
  return margin(rho, d) * weight(d, metric);
}

SlipDirection LimitSet::nelder_mead(const PatchWrench& rho, const Eigen::Matrix3d* metric, SlipDirection start,
                                    double size, double& best, long& evaluations) const {
  // Nelder-Mead on (alpha, beta) with the standard coefficients (reflection 1, expansion 2,
  // contraction 1/2, shrink 1/2).
  std::array<SlipDirection, 3> p = {start, wrapped({start.alpha + size, start.beta}),
                                    wrapped({start.alpha, start.beta + (start.beta > 0.0 ? -size : size)})};
  std::array<double, 3> f{};
  long n = 0;
  for (int i = 0; i < 3; ++i) {
    f[i] = objective(rho, p[i], metric);
    ++n;
  }
  const auto order = [&] {
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2 - i; ++j)
        if (f[j + 1] < f[j]) {
          std::swap(f[j], f[j + 1]);
          std::swap(p[j], p[j + 1]);
        }
  };
  while (n < kMaxSearchEvaluations) {
    order();
    const double da = std::max(std::abs(p[1].alpha - p[0].alpha), std::abs(p[2].alpha - p[0].alpha));
    const double db = std::max(std::abs(p[1].beta - p[0].beta), std::abs(p[2].beta - p[0].beta));
    if (std::max(da, db) < kDirectionTolerance) break;
    const SlipDirection c{0.5 * (p[0].alpha + p[1].alpha), 0.5 * (p[0].beta + p[1].beta)};
    const auto along = [&](double t) {
      return wrapped({c.alpha + t * (p[2].alpha - c.alpha), c.beta + t * (p[2].beta - c.beta)});
    };
    const SlipDirection r = along(-1.0);
    const double fr = objective(rho, r, metric);
    ++n;
    if (fr < f[0]) {
      const SlipDirection e = along(-2.0);
      const double fe = objective(rho, e, metric);
      ++n;
      if (fe < fr) {
        p[2] = e;
        f[2] = fe;
      } else {
        p[2] = r;
        f[2] = fr;
      }
      continue;
    }
    if (fr < f[1]) {
      p[2] = r;
      f[2] = fr;
      continue;
    }
    const SlipDirection k = fr < f[2] ? along(-0.5) : along(0.5);
    const double fk = objective(rho, k, metric);
    ++n;
    if (fk < std::min(fr, f[2])) {
      p[2] = k;
      f[2] = fk;
      continue;
    }
    for (int i = 1; i < 3; ++i) {
      p[i] = wrapped({0.5 * (p[0].alpha + p[i].alpha), 0.5 * (p[0].beta + p[i].beta)});
      f[i] = objective(rho, p[i], metric);
      ++n;
    }
  }
  order();
  evaluations += n;
  best = f[0];
  return p[0];
}

double LimitSet::margin_at(const PatchWrench& rho_SI, const SlipDirection& d) const {
  if (degenerate_) return -std::numeric_limits<double>::infinity();
  return margin({rho_SI.Fx / kN_, rho_SI.Fy / kN_, rho_SI.M / (kN_ * a_)}, wrapped(d));
}

LimitSetTest LimitSet::test(const PatchWrench& rho_SI, const SlipDirection* warm) const {
  return search(rho_SI, warm, nullptr);
}

LimitSetTest LimitSet::test(const PatchWrench& rho_SI, const SlipDirection* warm, const Eigen::Matrix3d& metric) const {
  return search(rho_SI, warm, &metric);
}

LimitSetTest LimitSet::follow(const PatchWrench& rho_SI, const SlipDirection& warm, const Eigen::Matrix3d& metric) const {
  LimitSetTest out;
  if (degenerate_) {
    out.margin = -std::numeric_limits<double>::infinity();
    return out;
  }
  const PatchWrench rho{rho_SI.Fx / kN_, rho_SI.Fy / kN_, rho_SI.M / (kN_ * a_)};
  out.direction = nelder_mead(rho, &metric, wrapped(warm), 1e-2, out.margin, out.evaluations);
  return out;
}

LimitSetTest LimitSet::search(const PatchWrench& rho_SI, const SlipDirection* warm, const Eigen::Matrix3d* metric) const {
  LimitSetTest out;
  if (degenerate_) {
    out.margin = -std::numeric_limits<double>::infinity();
    return out;
  }
  const PatchWrench rho{rho_SI.Fx / kN_, rho_SI.Fy / kN_, rho_SI.M / (kN_ * a_)};
  const auto consider = [&](double m, const SlipDirection& d) {
    if (m < out.margin || out.evaluations == 0) {
      out.margin = m;
      out.direction = d;
    }
  };
  // The pure-slip circle: D = kN there (friction/law.h), so the margin is 1 - rho_F.e(alpha): its
  // minimum lies along rho_F; weighted, it is found on a grid of kCircleGrid angles refined by
  // golden sections (no law evaluation).
  const SlipDirection slip{std::atan2(rho.Fy, rho.Fx), 0.0};
  consider(objective(rho, slip, metric), slip);
  out.evaluations = 1;
  if (metric) {
    const auto on_circle = [&](double alpha) {
      const SlipDirection d{alpha, 0.0};
      return (1.0 - rho.Fx * std::cos(alpha) - rho.Fy * std::sin(alpha)) * weight(d, metric);
    };
    constexpr int kCircleGrid = 256;
    const double h = 2.0 * kPi / kCircleGrid;
    double best_alpha = 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kCircleGrid; ++i) {
      const double f = on_circle(i * h);
      if (f < best) {
        best = f;
        best_alpha = i * h;
      }
    }
    double lo = best_alpha - h, hi = best_alpha + h;
    const double phi = 0.5 * (std::sqrt(5.0) - 1.0);
    while (hi - lo > kDirectionTolerance) {
      const double x1 = hi - phi * (hi - lo), x2 = lo + phi * (hi - lo);
      if (on_circle(x1) < on_circle(x2)) {
        hi = x2;
      } else {
        lo = x1;
      }
    }
    const SlipDirection d{0.5 * (lo + hi), 0.0};
    consider(objective(rho, d, metric), d);
    ++out.evaluations;
  }
  for (const double pole : {0.5 * kPi, -0.5 * kPi}) {
    const SlipDirection d{0.0, pole};
    consider(objective(rho, d, metric), d);
    ++out.evaluations;
  }
  // The grid off those lines.
  SlipDirection grid_best;
  double grid_min = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kGridAlpha; ++i) {
    for (int j = 1; j <= kGridBeta; ++j) {
      for (const double sign : {1.0, -1.0}) {
        const SlipDirection d{2.0 * kPi * i / kGridAlpha, sign * 0.5 * kPi * j / (kGridBeta + 1)};
        const double m = objective(rho, d, metric);
        ++out.evaluations;
        if (m < grid_min) {
          grid_min = m;
          grid_best = d;
        }
      }
    }
  }
  consider(grid_min, grid_best);
  double m = 0.0;
  SlipDirection d = nelder_mead(rho, metric, grid_best, 0.5 * kPi / (kGridBeta + 1), m, out.evaluations);
  consider(m, d);
  if (warm) {
    d = nelder_mead(rho, metric, wrapped(*warm), 1e-2, m, out.evaluations);
    consider(m, d);
  }
  return out;
}

}  // namespace frictionlab::dynamics
