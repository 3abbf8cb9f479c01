#include "friction/exact_reference_law.h"


#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "friction/exact_law.h"
#include "friction/gsl_error_policy.h"
#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

constexpr double kPi = std::numbers::pi;
// Requested errors, dimensionless (per kN, per kNa). The inner integrals are tighter so that
// their noise does not stall the outer ones; they also stop at 1e-13 relative, as near the major
// axis of a slender patch they are ~1/mu and 1e-14 absolute would be below round-off.
constexpr double kOuterAbsTol = 1e-12;
constexpr double kInnerAbsTol = 1e-14;
constexpr double kInnerRelTol = 1e-13;
// When GSL stops on round-off (GSL_EROUND), its error estimate (usually pessimistic) must still
// be below this, the accuracy the reference promises; otherwise the call throws.
constexpr double kAcceptedAbsError = 1e-10;
// An inner integral that GSL ends with a failure code is kept if its error estimate is below this
// (integrated over the 2 pi of the outer integral, within kAcceptedAbsError).
constexpr double kAcceptedInnerError = kAcceptedAbsError / (2.0 * kPi);
constexpr std::size_t kWorkspaceIntervals = 2000;
// Inner breaks graded towards the ray's closest approach to the ICR (outer_integrand): at distances
// h 4^k from it, h its distance from the chord, and no closer than kFinestBreak r_max (a transition
// that sharp is a jump to rounding). Without them GSL stopped on round-off (error estimates up to
// 2e-9) or reported "singularity" for rays within 1e-8 .. 1e-15 of an ICR inside the patch and
// near its rim or on its major axis (found by fuzzing, 2026-11).
constexpr double kFinestBreak = 1e-15;
constexpr double kGradeRatio = 4.0;
// Grading starts where the near-singularity is this close to the chord (relative to r_max).
constexpr double kGradeFrom = 0.25;
constexpr std::size_t kMaxInnerBreaks = 64;
// Outer breaks graded about the feet of rim_feet (integrate()) up to this distance from them.
constexpr double kOuterGradeTo = 0.05;
constexpr std::size_t kMaxOuterBreaks = 224;  // 5 + 4 feet x (1 + 2 log_4(kOuterGradeTo/kFinestBreak))

struct WorkspaceDeleter {
  void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
};
using Workspace = std::unique_ptr<gsl_integration_workspace, WorkspaceDeleter>;

Workspace make_workspace() {
  Workspace w(gsl_integration_workspace_alloc(kWorkspaceIntervals));
  if (!w) throw std::runtime_error("exact-reference: cannot allocate a GSL workspace");
  return w;
}


enum class Component { kF1, kF2, kM };

struct Problem {
  // Dimensionless: a = 1, b = mu, slip velocity of the centre (s, 0) with s = U/(a|Omega|),
  // spin sign sigma.
  double s = 0.0;
  double sigma = 1.0;
  double mu = 1.0;
  double cpsi = 1.0;
  double spsi = 0.0;
  double r_c = 0.0;  // ICR in polar coordinates of the ellipse frame
  double t_c = 0.0;
  Component component = Component::kF1;
  Pressure pressure = Pressure::hertz;
  // Inner state: the ray's direction and extent, and where the ICR is seen from it: c = r_near e_t
  // + q n_t (e_t = (cos t, sin t), n_t = (-sin t, cos t)), gap = r_max - r_near.
  double t = 0.0;
  double ct = 1.0;
  double st = 0.0;
  double r_max = 1.0;
  double r_near = 0.0;
  double q = 0.0;
  double gap = 1.0;
  gsl_integration_workspace* inner = nullptr;
  int inner_status = GSL_SUCCESS;
};

// Per N, along the ray at angle t of the ellipse frame, r = r_max sin chi:
// p r dr = ((n + 1) / (pi mu)) r_max^2 cos^(2n+1) chi sin chi dchi, times the component of v/|v|
// (F1, F2) or of rho x v/|v| (M).
// v = sigma J w, w = rho - c = (r - r_near) e_t - q n_t: formed from the position relative to the
// ICR along the ray, not as rho - c, and near the chord's end r - r_near = gap - r_max (1 - sin chi)
// with 1 - sin chi = 2 sin^2(pi/4 - chi/2): for an ICR within 1e-12 of the rim, r = r_max sin chi
// itself carries rounding of 1e-16 on a distance of 1e-12, which made the integrand noisy and GSL
// stop on round-off.
double integrand(double chi, void* params) {
  const auto& pb = *static_cast<const Problem*>(params);
  const double sc = std::sin(chi);
  const double r = pb.r_max * sc;
  double u = r - pb.r_near;
  if (sc > 0.5) {
    const double h = std::sin(0.25 * kPi - 0.5 * chi);
    u = pb.gap - 2.0 * pb.r_max * h * h;
  }
  const double wxe = u * pb.ct + pb.q * pb.st;  // ellipse frame
  const double wye = u * pb.st - pb.q * pb.ct;
  const double vx = -pb.sigma * (pb.spsi * wxe + pb.cpsi * wye);  // slip frame
  const double vy = pb.sigma * (pb.cpsi * wxe - pb.spsi * wye);
  const double xe = r * pb.ct;
  const double ye = r * pb.st;
  const double x = pb.cpsi * xe - pb.spsi * ye;
  const double y = pb.spsi * xe + pb.cpsi * ye;
  const double nv = std::hypot(vx, vy);
  if (nv == 0.0) return 0.0;  // the ICR itself: a set of measure zero
  double f = 0.0;
  switch (pb.component) {
    case Component::kF1: f = vx / nv; break;
    case Component::kF2: f = vy / nv; break;
    case Component::kM: f = (x * vy - y * vx) / nv; break;
  }
  const double c = std::cos(chi);
  double weight = 0.0;  // (n + 1) cos^(2n+1) chi
  switch (pb.pressure) {
    case Pressure::hertz: weight = 1.5 * c * c; break;
    case Pressure::uniform: weight = c; break;
    case Pressure::punch: weight = 0.5; break;
  }
  return weight / (kPi * pb.mu) * pb.r_max * pb.r_max * sc * f;
}

double outer_integrand(double t, void* params) {
  auto& pb = *static_cast<Problem*>(params);
  pb.t = t;
  pb.ct = std::cos(t);
  pb.st = std::sin(t);
  pb.r_max = 1.0 / std::sqrt(pb.ct * pb.ct + pb.st * pb.st / (pb.mu * pb.mu));
  gsl_function f{&integrand, &pb};
  double result = 0.0;
  double error = 0.0;
  // Break at the ray's closest approach to the ICR, where v/|v| turns fastest (and jumps, on
  // the ray through the ICR): along the ray it turns by pi over a length ~d (the ICR's distance
  // from the ray) about r_near, a near-singularity at r_near +- i d. Where that is near the chord
  // [0, r_max], breaks graded geometrically about its projection r0 resolve the boundary layer.
  const double r_near = pb.r_c * std::cos(t - pb.t_c);
  const double d = pb.r_c * std::abs(std::sin(t - pb.t_c));
  pb.r_near = r_near;
  pb.q = pb.r_c * std::sin(pb.t_c - t);
  pb.gap = pb.r_max - r_near;
  const double r0 = std::clamp(r_near, 0.0, pb.r_max);
  const double h = std::max(std::hypot(r_near - r0, d), kFinestBreak * pb.r_max);
  std::array<double, kMaxInnerBreaks> r_breaks{};
  std::size_t n = 0;
  if (r0 > 0.0 && r0 < pb.r_max) r_breaks[n++] = r0;
  if (h < kGradeFrom * pb.r_max) {
    for (double x = h; x < pb.r_max && n + 2 <= r_breaks.size(); x *= kGradeRatio) {
      if (r0 - x > 0.0) r_breaks[n++] = r0 - x;
      if (r0 + x < pb.r_max) r_breaks[n++] = r0 + x;
    }
  }
  std::sort(r_breaks.begin(), r_breaks.begin() + static_cast<std::ptrdiff_t>(n));
  std::array<double, kMaxInnerBreaks + 2> points{};
  std::size_t np = 0;
  points[np++] = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double chi = std::asin(r_breaks[i] / pb.r_max);
    if (chi > points[np - 1] && chi < kPi / 2) points[np++] = chi;
  }
  points[np++] = kPi / 2;
  int status = GSL_SUCCESS;
  if (np > 2) {
    // Plain adaptive Gauss-Kronrod on each piece: graded, they are smooth on their own scale, and
    // the extrapolation of QAGP stopped on round-off at 2e-10 near the tip of a slender patch.
    for (std::size_t i = 0; i + 1 < np; ++i) {
      double piece = 0.0;
      double piece_error = 0.0;
      const int st = gsl_integration_qag(&f, points[i], points[i + 1], kInnerAbsTol / static_cast<double>(np - 1),
                                         kInnerRelTol, kWorkspaceIntervals, GSL_INTEG_GAUSS21, pb.inner, &piece,
                                         &piece_error);
      if (st != GSL_SUCCESS) status = st;
      result += piece;
      error += piece_error;
    }
  } else {
    status = gsl_integration_qags(&f, 0.0, kPi / 2, kInnerAbsTol, kInnerRelTol, kWorkspaceIntervals,
                                  pb.inner, &result, &error);
  }
  // GSL stops on round-off (EROUND) or on a subinterval at the limit of resolution (ESING) where
  // the ray passes within rounding of the ICR and the jump of v/|v| is a few ulps from its break:
  // the estimate is then ~1e-14. A result is kept if its error estimate is below
  // kAcceptedInnerError, whatever the status.
  if (status != GSL_SUCCESS && !(error <= kAcceptedInnerError)) pb.inner_status = status;
  return result;
}

// The rim points P at which a ray's closest approach to the ICR c lies on the rim:
// P.(c - P) = 0 (P on the circle over the diameter from the centre to c). There the chord ends
// inside the traction's boundary layer or just before it, and the outer integrand has a kink,
// softened only on the scale of the ICR's distance from that ray: an ICR near the rim puts such a
// point within ~1e-5 of its own direction, where GSL stopped on round-off without a break there.
// On the rim (cos theta, mu sin theta) the condition is a trigonometric polynomial g(theta) of
// degree 2, so at most 4 points: its sign changes on a fine grid, refined by bisection, and its
// local minima of |g| near 0 without a sign change (a near-tangency: two close roots). Returned as
// polar angles of the ellipse frame.
constexpr int kFootGrid = 2048;
struct RimFeet {
  std::array<double, 8> t{};
  std::size_t count = 0;
};
RimFeet rim_feet(double mu, double cx, double cy) {
  const auto g = [&](double th) {
    const double x = std::cos(th);
    const double y = mu * std::sin(th);
    return x * (x - cx) + y * (y - cy);
  };
  const auto polar = [&](double th) { return std::atan2(mu * std::sin(th), std::cos(th)); };
  RimFeet out;
  const double step = 2.0 * kPi / kFootGrid;
  double g_prev = g(-step);
  double g_here = g(0.0);
  for (int i = 0; i < kFootGrid && out.count < out.t.size(); ++i) {
    const double th = i * step;
    const double g_next = g(th + step);
    if ((g_here > 0.0) != (g_next > 0.0)) {  // a root in [th, th + step]
      double a = th;
      double b = th + step;
      const bool a_positive = g_here > 0.0;
      for (int it = 0; it < 60; ++it) {
        const double m = 0.5 * (a + b);
        ((g(m) > 0.0) == a_positive ? a : b) = m;
      }
      out.t[out.count++] = polar(0.5 * (a + b));
    } else if (std::abs(g_here) < std::abs(g_prev) && std::abs(g_here) <= std::abs(g_next) &&
               std::abs(g_here) < 2.0 * step * (1.0 + std::hypot(cx, cy))) {
      out.t[out.count++] = polar(th);  // a near-tangency: its kinks are within a grid step
    }
    g_prev = g_here;
    g_here = g_next;
  }
  return out;
}

double integrate(Problem pb) {
  Workspace outer = make_workspace();
  Workspace inner = make_workspace();
  pb.inner = inner.get();
  gsl_function f{&outer_integrand, &pb};
  // Break at the ICR's direction (both ends), the opposite one, and the major axis (t = 0, pi),
  // where r_max^2 / mu peaks over a width ~mu.
  std::array<double, kMaxOuterBreaks> points{};
  std::size_t n = 0;
  points[n++] = pb.t_c;
  points[n++] = pb.t_c + kPi;
  points[n++] = pb.t_c + 2.0 * kPi;
  for (int k = -2; k <= 4; ++k) {
    const double axis = k * kPi;
    if (axis > pb.t_c && axis < pb.t_c + 2.0 * kPi && std::abs(axis - pb.t_c - kPi) > 1e-12) {
      points[n++] = axis;
    }
  }
  if (pb.r_c > 0.0) {
    // And where the rays' closest approach to the ICR crosses the rim (rim_feet), graded about
    // it where that makes a sharp feature: across a foot t* the closest approach r_near(t) passes
    // the chord's end r_max(t), and the traction's boundary layer (half-width d, the ICR's distance
    // from the ray) with it, within delta of t*: the least of d/|D'| and sqrt(2 d/|D''|),
    // D = r_near - r_max (the second where D' vanishes: at a vertex of the patch). Without these,
    // GSL stopped on round-off (error estimates up to 5e-9) for an ICR within ~1e-3 of the rim,
    // where delta falls to 1e-6.
    const RimFeet feet = rim_feet(pb.mu, pb.r_c * std::cos(pb.t_c), pb.r_c * std::sin(pb.t_c));
    const double e2 = (1.0 - pb.mu) * (1.0 + pb.mu) / (pb.mu * pb.mu);  // 1/mu^2 - 1
    const auto in_range = [&](double x) { return pb.t_c + std::remainder(x - pb.t_c - kPi, 2.0 * kPi) + kPi; };
    for (std::size_t k = 0; k < feet.count; ++k) {
      const double x = in_range(feet.t[k]);  // in [t_c, t_c + 2 pi]
      if (!(x > pb.t_c && x < pb.t_c + 2.0 * kPi) || n == points.size()) continue;
      points[n++] = x;
      // r_max = A^(-1/2), A = 1 + e2 sin^2 x; r_near = r_c cos(x - t_c)
      const double A = 1.0 + e2 * std::sin(x) * std::sin(x);
      const double A1 = e2 * std::sin(2.0 * x);
      const double A2 = 2.0 * e2 * std::cos(2.0 * x);
      const double r1 = -0.5 * A1 / (A * std::sqrt(A));
      const double r2 = (0.75 * A1 * A1 / A - 0.5 * A2) / (A * std::sqrt(A));
      const double d = pb.r_c * std::abs(std::sin(x - pb.t_c));
      const double D1 = -pb.r_c * std::sin(x - pb.t_c) - r1;
      const double D2 = -pb.r_c * std::cos(x - pb.t_c) - r2;
      const double delta = std::min(d / std::abs(D1), std::sqrt(2.0 * d / std::abs(D2)));
      for (double w = std::max(delta, kFinestBreak); w < kOuterGradeTo && n + 2 <= points.size(); w *= kGradeRatio) {
        for (const double y : {in_range(x - w), in_range(x + w)}) {
          if (y > pb.t_c && y < pb.t_c + 2.0 * kPi) points[n++] = y;
        }
      }
    }
  }
  std::sort(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(n));
  // Plain adaptive Gauss-Kronrod on each piece (no extrapolation, which the mild log-type
  // behaviour at the ICR's direction can mislead); each piece gets a share of the tolerance.
  double result = 0.0;
  double error = 0.0;
  int status = GSL_SUCCESS;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    double piece = 0.0;
    double piece_error = 0.0;
    const int st = gsl_integration_qag(&f, points[i], points[i + 1],
                                       kOuterAbsTol / static_cast<double>(n - 1), 0.0,
                                       kWorkspaceIntervals, GSL_INTEG_GAUSS21, outer.get(), &piece,
                                       &piece_error);
    if (st != GSL_SUCCESS) status = st;
    result += piece;
    error += piece_error;
  }
  if ((status != GSL_SUCCESS && !(status == GSL_EROUND && error < kAcceptedAbsError)) ||
      pb.inner_status != GSL_SUCCESS) {
    const int bad = pb.inner_status != GSL_SUCCESS ? pb.inner_status : status;
    // A domain error (ValueError in Python): the quadrature cannot compute the law at this input.
    throw std::domain_error(std::string("exact-reference: GSL integration failed: ") +
                             gsl_strerror(bad));
  }
  return result;
}

}  // namespace

std::vector<LawParameter> ExactReferenceLaw::parameters() {
  return {LawParameter::choice("pressure", pressure_names(), "hertz",
                               "the normal pressure over the patch (docs/pressure-models.md): hertz, uniform, punch")};
}

// Every property of the exact law (it integrates its definition), to this quadrature's accuracy and
// on its range of axis ratios; whole_domain: no GSL failure seen there (6,000 inputs fuzzed towards
// the rim and the axes).
LawPromises ExactReferenceLaw::promises() const {
  LawPromises p = ExactLaw(pressure_).promises();
  p.min_axis_ratio = kExactReferenceMinAxisRatio;
  p.tolerance = kExactReferenceAccuracy;
  return p;
}

FrictionForces ExactReferenceLaw::do_evaluate(const ContactInput& in) const {
  const double mu = in.b / in.a;
  if (mu < kExactReferenceMinAxisRatio) {
    throw std::invalid_argument("friction input b = " + support::shortest(in.b) +
                                " is invalid for exact-reference: the axis ratio b/a = " + support::shortest(mu) +
                                " is below " + support::shortest(kExactReferenceMinAxisRatio) +
                                ", the smallest for which its GSL quadrature is accurate to " +
                                support::shortest(kExactReferenceAccuracy) + " (use 'exact', accurate down to b/a = 1e-12)");
  }
  const double kN = in.k * in.N;
  if (kN == 0.0) return {};
  if (in.Omega == 0.0) {
    if (in.U == 0.0) return {};  // indeterminate at U = Omega = 0: documented as zero
    return {kN, 0.0, 0.0};       // pure sliding
  }
  const double s = slip_ratio(in.U, in.a, in.Omega);
  if (std::isinf(s)) return {kN, 0.0, 0.0};  // s > 1.8e308: pure sliding to within 1e-616
  use_gsl_status_codes();
  Problem pb;
  pb.s = s;
  pb.sigma = in.Omega > 0.0 ? 1.0 : -1.0;
  pb.mu = mu;
  pb.pressure = pressure_;
  const PatchAngle::CosSin axis = in.psi.cos_sin();
  pb.cpsi = axis.c;
  pb.spsi = axis.s;
  // ICR c = (0, sigma s) in the slip frame, c' = sigma s (sin psi, cos psi) in the ellipse frame.
  const double cx = pb.sigma * pb.s * pb.spsi;
  const double cy = pb.sigma * pb.s * pb.cpsi;
  pb.r_c = std::hypot(cx, cy);
  pb.t_c = (pb.r_c > 0.0) ? std::atan2(cy, cx) : 0.0;

  FrictionForces out;
  pb.component = Component::kF1;
  out.F1 = kN * integrate(pb);
  pb.component = Component::kF2;
  out.F2 = kN * integrate(pb);
  pb.component = Component::kM;
  out.M = kN * in.a * integrate(pb);
  return out;
}

}  // namespace frictionlab::friction
