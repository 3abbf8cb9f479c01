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
constexpr std::size_t kWorkspaceIntervals = 2000;

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
  // Inner state: the ray's direction and extent.
  double t = 0.0;
  double ct = 1.0;
  double st = 0.0;
  double r_max = 1.0;
  gsl_integration_workspace* inner = nullptr;
  int inner_status = GSL_SUCCESS;
};

// Per N, along the ray at angle t of the ellipse frame, r = r_max sin chi:
// p r dr = ((n + 1) / (pi mu)) r_max^2 cos^(2n+1) chi sin chi dchi, times the component of v/|v|
// (F1, F2) or of rho x v/|v| (M).
double integrand(double chi, void* params) {
  const auto& pb = *static_cast<const Problem*>(params);
  const double r = pb.r_max * std::sin(chi);
  const double xe = r * pb.ct;
  const double ye = r * pb.st;
  const double x = pb.cpsi * xe - pb.spsi * ye;  // slip frame
  const double y = pb.spsi * xe + pb.cpsi * ye;
  const double vx = pb.s - pb.sigma * y;
  const double vy = pb.sigma * x;
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
  return weight / (kPi * pb.mu) * pb.r_max * pb.r_max * std::sin(chi) * f;
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
  // the ray through the ICR).
  const double r_near = pb.r_c * std::cos(t - pb.t_c);
  int status = GSL_SUCCESS;
  if (r_near > 0.0 && r_near < pb.r_max) {
    double points[3] = {0.0, std::asin(r_near / pb.r_max), kPi / 2};
    status = gsl_integration_qagp(&f, points, 3, kInnerAbsTol, kInnerRelTol, kWorkspaceIntervals, pb.inner,
                                  &result, &error);
  } else {
    status = gsl_integration_qags(&f, 0.0, kPi / 2, kInnerAbsTol, kInnerRelTol, kWorkspaceIntervals,
                                  pb.inner, &result, &error);
  }
  if (status != GSL_SUCCESS && status != GSL_EROUND) pb.inner_status = status;
  return result;
}

double integrate(Problem pb) {
  Workspace outer = make_workspace();
  Workspace inner = make_workspace();
  pb.inner = inner.get();
  gsl_function f{&outer_integrand, &pb};
  // Break at the ICR's direction (both ends), the opposite one, and the major axis (t = 0, pi),
  // where r_max^2 / mu peaks over a width ~mu.
  std::array<double, 7> points{};
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
  for (std::size_t i = 1; i < n; ++i) {  // insertion sort of at most 7 points
    for (std::size_t j = i; j > 0 && points[j - 1] > points[j]; --j) std::swap(points[j - 1], points[j]);
  }
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

LawPromises ExactReferenceLaw::promises() const {
  LawPromises p;
  p.F1_in_Omega = Parity::even;
  p.F2_in_Omega = Parity::even;
  p.M_in_Omega = Parity::odd;
  p.pi_periodic_in_psi = true;
  p.psi_mirror = true;
  p.dissipative = true;
  p.bounded = true;
  p.exact_pure_spin = true;
  p.pure_spin_factor = pressure_pure_spin_factor(pressure_);
  p.min_axis_ratio = kExactReferenceMinAxisRatio;
  p.whole_domain = true;  // no GSL failure seen in its domain (1,600 seeded points)
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
