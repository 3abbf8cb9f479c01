#include "friction/exact_law.h"

// Implementation notes. The derivation, the choice of every constant below and the measured
// accuracy and cost are in docs/exact-law.md; this file only says what each piece does.
//
// Dimensionless problem: lengths in units of a, forces per kN, moment per kNa, Omega > 0
// (F1 and F2 are even in Omega, M is odd: the sign is applied at the end, so the symmetry is
// exact). Ellipse frame: x along the major axis. Normalised frame: (x, y/mu), where the patch is
// the unit disc. The ICR is c' = s (sin psi, cos psi) in the ellipse frame and
// c~ = (p, q) = s (sin psi, cos psi / mu) in the normalised frame, rho = |c~|.
// A line through the ICR with normalised direction e = (C, S) = (cos tau, sin tau) has the
// ellipse-frame direction v = (C, mu S), of length L = sqrt(C^2 + mu^2 S^2). With
// D = 1 - (e x c~)^2 (> 0 iff the line meets the patch) the force and moment are
//   G' = -(3/4) ∫ D (e.c~) v / L dtau,   H = (3/4) ∫ D [ X / L + D L / 4 ] dtau,
//   X = (1 - mu^2) S C (e x c~)(e.c~),
// over the tau in [0, pi) with D > 0; F1 = -G_y, F2 = G_x (G = R(psi) G'), M = H.

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "friction/support/number_format.h"

namespace frictionlab::friction {
namespace {

constexpr double kPi = std::numbers::pi;

// Two doubles side by side (the GCC/Clang vector extension: SSE2 on x86-64, NEON on arm64, two
// scalars elsewhere) for the quadrature loops whose nodes are independent: each lane rounds as the
// scalar code would, and the square roots and divisions of two nodes issue together.
using Lanes = double __attribute__((vector_size(16)));
Lanes lanes_sqrt(Lanes x) {
#if defined(__SSE2__)
  return _mm_sqrt_pd(x);
#else
  return Lanes{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

// Above this slip ratio s the fast-slip expansion replaces quadrature: its first neglected terms
// are O(s^-3) kNa in M and O(s^-4) kN in F1, F2 (measured: M s / (d3/5) = 1 + c/s^2 with
// c ~ 0.1 to 0.3), i.e. below 1e-24 here.
constexpr double kFastSlipRatio = 1e8;
// ICR outside: either the closed-form whole period minus the gap of directions that miss the
// patch, or quadrature over the window of directions that hit it. Up to rho = |c~| = 2 the law
// takes whichever interval keeps the integrand's singularities further away (fewer nodes);
// beyond, always the window. The whole-period terms grow like rho^4 while the result is O(1):
// the subtraction costs up to ~5e-14 at rho = 2 (2e-13 if this were raised to rho = 3, for 20%
// fewer nodes in that band). The moments also grow like ln(1/mu), so for slender patches the
// subtraction is allowed only up to rho = 1.5: at rho = 2 it cost up to 1.3e-13 for mu < 1e-4
// (measured against the window), at rho = 1.5 (1.5/2)^4 of that.
constexpr double kMaxGapRho2 = 4.0;
constexpr double kSlenderAxisRatio = 0.01;
constexpr double kMaxGapRho2Slender = 2.25;
// Moments of 1/L: AGM + upward recurrence for mu below this (the recurrence divides by
// e^2 = 1 - mu^2 >= 0.75, so it loses at most a factor ~2), periodic trapezoid rule above
// (its error ~ exp(-2 N atanh(mu)): N graded by mu below).
constexpr double kAgmMaxAxisRatio = 0.5;
// The trapezoid's nodes per period pi, fewer for rounder patches: the least of these sizes with
// 2 N atanh(mu) >= 38.5, i.e. mu at least kTrapezoidMinAxisRatio[i] for kTrapezoidSizes[i].
// Measured against long-double sums of 4096 nodes (the moments I_0..I_3 below, mu from 0.5 to 1):
// largest relative error 7.4e-16 (N = 32 at mu = 0.5, as before the sizes were graded), 3e-16 at
// each size's least mu; one size smaller there gives 1e-14 to 7e-14.
constexpr std::array<int, 5> kTrapezoidSizes = {12, 16, 20, 24, 32};
constexpr std::array<double, 5> kTrapezoidMinAxisRatio = {0.93, 0.85, 0.75, 0.7, 0.0};
// A Gauss-Legendre panel is used with n nodes only if every singularity of the integrand lies
// outside the Bernstein ellipse with rho_B^(-(2n - kPolynomialDegree)) = kRuleTolerance.
// kPolynomialDegree: on a short window the integrand is, to leading order, a polynomial of
// degree up to 6 in rho t (D = 1 - rho^2 sin^2 phi appears twice, and (1 + d.c^) ~ sin^2 phi),
// whose growth on the Bernstein ellipse costs up to that many orders of the rule; 4 is the
// smallest value that keeps the measured error at round-off (2 lets it reach 2e-13).
constexpr double kRuleTolerance = 1e-15;
constexpr int kPolynomialDegree = 4;
// The Weierstrass substitution puts poles of order up to 8 at t = +-i; the rule is chosen as if
// they were this much closer to the real axis. Calibrated on 30,000 random cases against a run
// with kRuleTolerance = 1e-20: 0.5 keeps the error at round-off, 0.6 lets it reach 4e-14.
constexpr double kWeierstrassPoleMargin = 0.5;
// Largest rule tried on a whole interval before it is graded.
constexpr int kMaxSinglePanelRule = 24;
// Graded panels about the projection of a near-real branch point at distance d: edges at
// d * kGradeFirst * kGradeRatio^k (so every panel has rho_B >= (sqrt 4 + 1)/(sqrt 4 - 1) = 3).
constexpr double kGradeFirst = 1.0;
constexpr double kGradeRatio = 4.0;
constexpr int kMaxPanelsPerSide = 40;  // 4^40 d > 1 for any d >= kExactMinAxisRatio / 4

// ---------------------------------------------------------------------------------------------
// Gauss-Legendre rules, built once (Newton on the three-term recurrence, in long double).

constexpr std::array<int, 21> kRuleSizes = {4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14,
                                            15, 16, 18, 20, 22, 24, 28, 32, 40, 48};
constexpr int kMaxRuleSize = 48;

struct GaussRule {
  int n = 0;
  // smallest (|z-1| + |z+1|)/2 of a singularity z the rule tolerates, for an integrand without
  // (sigma[0]) or with (sigma[1]) the polynomial factor of degree kPolynomialDegree
  std::array<double, 2> sigma{};
  std::array<double, kMaxRuleSize> x{};
  std::array<double, kMaxRuleSize> w{};
};

struct GaussTable {
  std::array<GaussRule, kRuleSizes.size()> rules{};

  GaussTable() {
    for (std::size_t r = 0; r < kRuleSizes.size(); ++r) {
      GaussRule& g = rules[r];
      g.n = kRuleSizes[r];
      const int n = g.n;
      for (int i = 0; i < n; ++i) {
        long double x = std::cos(std::numbers::pi_v<long double> * (i + 0.75L) / (n + 0.5L));
        long double dp = 1.0L;
        for (int it = 0; it < 100; ++it) {
          long double p0 = 1.0L;
          long double p1 = x;
          for (int k = 2; k <= n; ++k) {
            const long double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
            p0 = p1;
            p1 = p2;
          }
          dp = n * (x * p1 - p0) / (x * x - 1.0L);
          const long double dx = p1 / dp;
          x -= dx;
          if (std::fabs(dx) < 1e-19L) break;
        }
        g.x[static_cast<std::size_t>(i)] = static_cast<double>(x);
        g.w[static_cast<std::size_t>(i)] = static_cast<double>(2.0L / ((1.0L - x * x) * dp * dp));
      }
      for (int with_poly = 0; with_poly < 2; ++with_poly) {
        const double order = 2.0 * n - (with_poly ? kPolynomialDegree : 0);
        const double rho = std::pow(kRuleTolerance, -1.0 / order);
        g.sigma[static_cast<std::size_t>(with_poly)] = 0.5 * (rho + 1.0 / rho);
      }
    }
  }
};

const GaussTable& gauss_table() {
  static const GaussTable table;
  return table;
}

// ---------------------------------------------------------------------------------------------
// Whole-period moments M_ij = ∫_0^pi cos^i sin^j / L dtau (i, j even, i + j <= 6).

struct Moments {
  double m20, m02, m40, m22, m04, m60, m42, m24, m06;
};

// Per size N: sin^2 at the nodes k pi/N, k = 0 .. N/2 (the integrands are even about pi/2), and
// the trapezoid weights pi/N (halved at both ends, doubled for the mirrored half) times 1, sin^2,
// sin^4, sin^6: the moments need only I_n = ∫_0^pi sin^(2n)/L, n <= 3.
struct TrapezoidTable {
  struct Rule {
    int half = 0;
    std::array<double, kTrapezoidSizes.back() / 2 + 1> s2{}, w0{}, w1{}, w2{}, w3{};
  };
  std::array<Rule, kTrapezoidSizes.size()> rule{};
  TrapezoidTable() {
    for (std::size_t r = 0; r < kTrapezoidSizes.size(); ++r) {
      const int n = kTrapezoidSizes[r];
      Rule& R = rule[r];
      R.half = n / 2;
      for (int k = 0; k <= n / 2; ++k) {
        const auto kk = static_cast<std::size_t>(k);
        const double t = std::sin(kPi * k / n);
        const double s2 = (2 * k == n) ? 1.0 : t * t;
        const double w = ((k == 0 || 2 * k == n) ? 1.0 : 2.0) * kPi / n;
        R.s2[kk] = s2;
        R.w0[kk] = w;
        R.w1[kk] = w * s2;
        R.w2[kk] = w * s2 * s2;
        R.w3[kk] = w * s2 * s2 * s2;
      }
    }
  }
};

// M_ij from I_n = ∫_0^pi sin^(2n)/L, n <= 3, with cos^2 = 1 - sin^2 (the largest cancellation, in
// m60 at mu = 1, loses a factor ~5 in relative rounding).
void set_from_sine_moments(Moments& m, double I0, double I1, double I2, double I3) {
  m.m20 = I0 - I1;
  m.m02 = I1;
  m.m40 = I0 - 2.0 * I1 + I2;
  m.m22 = I1 - I2;
  m.m04 = I2;
  m.m60 = I0 - 3.0 * I1 + 3.0 * I2 - I3;
  m.m42 = I1 - 2.0 * I2 + I3;
  m.m24 = I2 - I3;
  m.m06 = I3;
}

Moments moments(double mu, double e2) {
  Moments m{};
  if (mu < kAgmMaxAxisRatio) {
    // K(e) and (K - E)/e^2 by the arithmetic-geometric mean, without cancellation:
    // K = pi / (2 AGM(1, mu)), (K - E)/e^2 = K sum_n 2^(n-1) c_n^2 / e^2.
    double a = 0.5 * (1.0 + mu);
    double b = std::sqrt(mu);
    double c = 0.5 * (1.0 - mu);
    double r = (1.0 - mu) / (4.0 * (1.0 + mu));  // c_1^2 / e^2
    double sum = 0.5 + r;
    double weight = 1.0;
    for (int it = 0; it < 64 && c > 1e-18 * a; ++it) {
      const double a1 = 0.5 * (a + b);
      const double b1 = std::sqrt(a * b);
      const double c1 = c * c / (4.0 * a1);
      r *= c * c / (16.0 * a1 * a1);
      weight *= 2.0;
      sum += weight * r;
      a = a1;
      b = b1;
      c = c1;
    }
    const double K = kPi / (2.0 * a);
    // I_n = ∫_0^pi sin^(2n) / L: I_0 = 2K, I_1 = 2(K - E)/e^2, then
    // (2n + 1) e^2 I_(n+1) = 2n (1 + e^2) I_n - (2n - 1) I_(n-1).
    const double I0 = 2.0 * K;
    const double I1 = 2.0 * K * sum;
    const double I2 = (2.0 * (1.0 + e2) * I1 - I0) / (3.0 * e2);
    const double I3 = (4.0 * (1.0 + e2) * I2 - 3.0 * I1) / (5.0 * e2);
    set_from_sine_moments(m, I0, I1, I2, I3);
  } else {
    static const TrapezoidTable table;
    std::size_t r = 0;
    while (mu < kTrapezoidMinAxisRatio[r]) ++r;
    const TrapezoidTable::Rule& R = table.rule[r];
    double I0 = 0.0;
    double I1 = 0.0;
    double I2 = 0.0;
    double I3 = 0.0;
    for (int k = 0; k <= R.half; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const double f = 1.0 / std::sqrt(1.0 - e2 * R.s2[kk]);
      I0 += R.w0[kk] * f;
      I1 += R.w1[kk] * f;
      I2 += R.w2[kk] * f;
      I3 += R.w3[kk] * f;
    }
    set_from_sine_moments(m, I0, I1, I2, I3);
  }
  return m;
}

struct Result {
  double g1 = 0.0;  // G' along the major axis, per N
  double g2 = 0.0;  // G' along the minor axis, per N
  double h = 0.0;   // H per N a
};

// The whole-period integrals, polynomials in c~ = (p, q): exact for the ICR inside or on the
// rim, and the analytic continuation (D < 0 on the gap) when it is outside.
Result whole_period(const Moments& m, double mu, double e2, double p, double q) {
  const double p2 = p * p;
  const double q2 = q * q;
  const double mu2 = mu * mu;
  Result r;
  r.g1 = -0.75 * p * (m.m20 - q2 * m.m40 - (p2 - 2.0 * q2) * m.m22);
  r.g2 = -0.75 * mu * q * (m.m02 - (q2 - 2.0 * p2) * m.m22 - p2 * m.m04);
  const double dx = e2 * ((q2 - p2) * (m.m22 - q2 * m.m42 - p2 * m.m24) +
                          2.0 * p2 * q2 * (m.m42 - m.m24));
  const double dd = m.m20 + mu2 * m.m02 - 2.0 * q2 * (m.m40 + mu2 * m.m22) -
                    2.0 * p2 * (m.m22 + mu2 * m.m04) + q2 * q2 * (m.m60 + mu2 * m.m42) +
                    6.0 * p2 * q2 * (m.m42 + mu2 * m.m24) + p2 * p2 * (m.m24 + mu2 * m.m06);
  r.h = 0.75 * (dx + 0.25 * dd);
  return r;
}

// The same for the flat punch (p ~ (1 - r^2)^(-1/2)): the chord factor is D^0 = 1, the prefactor
// (n + 1) B_n / pi = 1/2 and the chord's second moment 1/(2n + 3) = 1/2 (docs/pressure-models.md),
// so G' is linear and H quadratic in (p, q).
Result whole_period_punch(const Moments& m, double mu, double e2, double p, double q) {
  const double mu2 = mu * mu;
  Result r;
  r.g1 = -0.5 * p * m.m20;
  r.g2 = -0.5 * mu * q * m.m02;
  r.h = 0.5 * (e2 * (q * q - p * p) * m.m22 +
               0.5 * (m.m20 + mu2 * m.m02 - q * q * (m.m40 + mu2 * m.m22) - p * p * (m.m22 + mu2 * m.m04)));
  return r;
}

// ---------------------------------------------------------------------------------------------
// Composite Gauss-Legendre over t in [-T, T], t = tan(phi/2) (Weierstrass: no trigonometric
// function per node), the direction being e(phi) = cos phi u0 + sin phi u1 with u1 = -J u0.

struct Point {
  double re, im;
};

// (|z - 1| + |z + 1|) / 2 for z relative to the panel [x0, x1] mapped to [-1, 1]: the Bernstein
// ellipse through z has rho_B = sigma + sqrt(sigma^2 - 1).
double bernstein_sigma(double x0, double x1, Point z) {
  const double h = 0.5 * (x1 - x0);
  const double xr = (z.re - 0.5 * (x0 + x1)) / h;
  const double yi = z.im / h;
  return 0.5 * (std::sqrt((xr - 1.0) * (xr - 1.0) + yi * yi) +
                std::sqrt((xr + 1.0) * (xr + 1.0) + yi * yi));
}

struct Singularities {
  std::array<Point, 8> z{};
  int count = 0;
};

// The integrand's singularities in the upper half t-plane (with their mirror images): the pole
// of the Weierstrass substitution at t = i, and the branch points of L, where the direction is
// isotropic for the Euclidean metric of the ellipse frame: tau = pi/2 + i atanh(mu) (mod pi).
Singularities singularities(double u0x, double u0y, double mu, double e) {
  Singularities s;
  s.z[0] = {0.0, kWeierstrassPoleMargin};
  s.count = 1;
  if (e > 0.0) {
    // phi = tau0 - tau; x = tau0 - pi/2 reduced to (-pi/2, pi/2]:
    // t1 = tan((x + i atanh mu)/2) = (e sin x + i mu) / (e cos x + 1).
    double sx = -u0x;
    double cx = u0y;
    if (cx < 0.0) {
      sx = -sx;
      cx = -cx;
    }
    const double den = e * cx + 1.0;
    const Point t1{e * sx / den, mu / den};
    const double n2 = t1.re * t1.re + t1.im * t1.im;
    const Point t2{-t1.re / n2, t1.im / n2};  // the same direction, phi + pi
    s.z[1] = t1;
    s.z[2] = t2;
    s.count = 3;
  }
  return s;
}

const GaussRule* choose_rule(double x0, double x1, const Singularities& sing, int max_n,
                             bool with_poly) {
  double sigma = 1e300;
  for (int k = 0; k < sing.count; ++k) {
    sigma = std::min(sigma, bernstein_sigma(x0, x1, sing.z[static_cast<std::size_t>(k)]));
  }
  const GaussTable& table = gauss_table();
  for (const GaussRule& g : table.rules) {
    if (g.n > max_n) break;
    if (g.sigma[with_poly ? 1 : 0] <= sigma) return &g;
  }
  return nullptr;
}

struct Panel {
  double x0, x1;
  const GaussRule* rule;
};

constexpr int kMaxRefineDepth = 12;
struct Panels {
  std::array<Panel, 4 * kMaxPanelsPerSide + 2> p;  // the first count set; not zeroed (per call)
  int count = 0;
};

// Panels covering [-T, T]: one if a rule of at most kMaxSinglePanelRule nodes suffices,
// otherwise graded geometrically towards the projection of the nearest singularity.
void build_panels(double T, const Singularities& sing, bool with_poly, Panels& out, bool refine = false) {
  out.count = 0;
  if (const GaussRule* g = choose_rule(-T, T, sing, kMaxSinglePanelRule, with_poly)) {
    out.p[0] = {-T, T, g};
    out.count = 1;
    return;
  }
  // The nearest singularity in the sense of the Bernstein ellipse.
  std::size_t nearest = 0;
  double best = 1e300;
  for (int k = 0; k < sing.count; ++k) {
    const double sg = bernstein_sigma(-T, T, sing.z[static_cast<std::size_t>(k)]);
    if (sg < best) {
      best = sg;
      nearest = static_cast<std::size_t>(k);
    }
  }
  const Point z = sing.z[nearest];
  const double xc = std::clamp(z.re, -T, T);
  const double d0 = std::hypot(z.re - xc, z.im);
  std::array<double, kMaxPanelsPerSide + 1> left{};
  std::array<double, kMaxPanelsPerSide + 1> right{};
  auto grade = [&](double len, std::array<double, kMaxPanelsPerSide + 1>& edge) {
    int n = 0;
    double a = kGradeFirst * d0;
    while (n < kMaxPanelsPerSide - 1 && a < len) {
      edge[static_cast<std::size_t>(n++)] = a;
      a *= kGradeRatio;
    }
    edge[static_cast<std::size_t>(n++)] = len;
    return n;
  };
  const int nl = (xc > -T) ? grade(xc + T, left) : 0;
  const int nr = (xc < T) ? grade(T - xc, right) : 0;
  const GaussTable& table = gauss_table();
  const int max_n = table.rules.back().n;
  // refine: a panel that no rule covers (another singularity near it) is halved until one does.
  auto add = [&](auto&& self, double x0, double x1, int depth) -> void {
    const GaussRule* g = choose_rule(x0, x1, sing, max_n, with_poly);
    if (!g && refine && depth < kMaxRefineDepth && out.count + 2 < static_cast<int>(out.p.size())) {
      const double xm = 0.5 * (x0 + x1);
      self(self, x0, xm, depth + 1);
      self(self, xm, x1, depth + 1);
      return;
    }
    out.p[static_cast<std::size_t>(out.count++)] = {x0, x1, g ? g : &table.rules.back()};
  };
  for (int i = nl - 1; i >= 0; --i) {
    const double x0 = xc - left[static_cast<std::size_t>(i)];
    const double x1 = (i == 0) ? xc : xc - left[static_cast<std::size_t>(i - 1)];
    add(add, x0, x1, 0);
  }
  for (int i = 0; i < nr; ++i) {
    const double x0 = (i == 0) ? xc : xc + right[static_cast<std::size_t>(i - 1)];
    add(add, x0, xc + right[static_cast<std::size_t>(i)], 0);
  }
}

// Calls f(cos phi, sin phi, weight dphi) on the panels' nodes two at a time, in Lanes, in order; a
// panel with an odd node count repeats its last node at weight 0 (a finite integrand there: it
// adds exactly 0; a Gauss weight is never 0, so a caller may also skip such a lane).
template <class F>
void for_each_node_pair(const Panels& panels, F&& f) {
  for (int k = 0; k < panels.count; ++k) {
    const Panel& pn = panels.p[static_cast<std::size_t>(k)];
    const double m = 0.5 * (pn.x0 + pn.x1);
    const double h = 0.5 * (pn.x1 - pn.x0);
    const GaussRule& g = *pn.rule;
    for (int i = 0; i < g.n; i += 2) {
      const bool pair = i + 1 < g.n;
      const auto i0 = static_cast<std::size_t>(i);
      const auto i1 = pair ? i0 + 1 : i0;
      const Lanes x = {g.x[i0], g.x[i1]};
      const Lanes wg = {g.w[i0], pair ? g.w[i1] : 0.0};
      const Lanes t = m + h * x;
      const Lanes iq = 1.0 / (1.0 + t * t);
      f((1.0 - t * t) * iq, 2.0 * t * iq, 2.0 * h * wg * iq);
    }
  }
}

// Half-widths, in the Weierstrass parameter, of the gap (|phi| < acos(1/rho)) and of the window
// (|phi| < asin(1/rho)); and the directions u0 at their centres.
double gap_half_width(double rho) { return std::sqrt((rho - 1.0) / (rho + 1.0)); }
double window_half_width(double rho) { return 1.0 / (rho + std::sqrt((rho - 1.0) * (rho + 1.0))); }

// The smallest Bernstein sigma of the integrand's singularities over [-T, T]: the larger, the
// fewer nodes.
double difficulty_sigma(double T, const Singularities& sing) {
  double sigma = 1e300;
  for (int k = 0; k < sing.count; ++k) {
    sigma = std::min(sigma, bernstein_sigma(-T, T, sing.z[static_cast<std::size_t>(k)]));
  }
  return sigma;
}

// ICR outside, the gap of directions that miss the patch,
// e(phi) = cos phi n + sin phi c^, n = J c^, |phi| < acos(1/rho), with the same (continued)
// integrand as the whole period, where D = 1 - rho^2 cos^2 phi < 0.
// kPunch: the flat punch's integrand (chord factor 1 in place of D, prefactor 1/2, chord moment
// 1/2); otherwise Hertz's.
template <bool kPunch>
Result gap_integral(double mu, double e2, double p, double q, double rho) {
  const double cx = p / rho;
  const double cy = q / rho;
  const double u0x = -cy;  // n = J c^
  const double u0y = cx;
  const double T = gap_half_width(rho);  // tan(acos(1/rho) / 2)
  Panels panels;
  build_panels(T, singularities(u0x, u0y, mu, std::sqrt(e2)), false, panels);
  const double rho2 = rho * rho;
  Lanes g1 = {0.0, 0.0};
  Lanes g2 = {0.0, 0.0};
  Lanes h = {0.0, 0.0};
  for_each_node_pair(panels, [&](Lanes cphi, Lanes sphi, Lanes w) {
    const Lanes C = cphi * u0x + sphi * cx;
    const Lanes S = cphi * u0y + sphi * cy;
    const Lanes L = lanes_sqrt(C * C + mu * mu * S * S);
    const Lanes iL = 1.0 / L;
    const Lanes D = 1.0 - rho2 * cphi * cphi;
    const Lanes chord = kPunch ? Lanes{1.0, 1.0} : D;
    const Lanes a = w * chord * rho * sphi * iL;  // e.c~ = rho sin phi
    g1 += a * C;
    g2 += a * mu * S;
    const Lanes X = -e2 * rho2 * S * C * cphi * sphi;  // e x c~ = -rho cos phi
    h += w * chord * (X * iL + (kPunch ? 0.5 : 0.25) * D * L);
  });
  const double k = kPunch ? 0.5 : 0.75;
  return {-k * (g1[0] + g1[1]), -k * (g2[0] + g2[1]), k * (h[0] + h[1])};
}

// The frame of an ICR outside the patch at c' = (p, q), |c'| = rho, in the normalised ellipse
// frame: the window's central direction u0 = -c^ (from the ICR towards the patch) and n = J c^.
struct IcrFrame {
  double u0x, u0y, nx, ny;
};
IcrFrame icr_frame(double p, double q, double rho) {
  const double cx = p / rho;
  const double cy = q / rho;
  return {-cx, -cy, -cy, cx};
}

// A window direction e = cos phi u0 + sin phi n (two in the lanes) in the normalised ellipse frame:
// (C, S), L = |(C, mu S)|, and 1 + d.c^ = num/den (d = v/|v|, c^ = c'/|c'|) without
// cancellation: as (Ls + v.c')/(Ls) where v.c' > 0, else as (d x c^)^2/(1 - d.c^), using
// Lagrange's identity (Ls)^2 (d x c^)^2 = (v x c')^2 = cross2 = mu^2 rho^2 sin^2 phi. (Ls - v.c'
// alone cancels to nothing where d is nearly along c^, which a slit (mu ~ 1e-9) sees at O(1)
// angles.) qm = mu^2 q: v.c' = C p + S qm.
struct WindowDirection {
  Lanes C, S, L, num, den;
};
WindowDirection window_direction(Lanes cphi, Lanes sphi, double u0x, double u0y, double nx, double ny, double mu2,
                                 double p, double qm, double s, Lanes cross2) {
  WindowDirection d;
  d.C = cphi * u0x + sphi * nx;
  d.S = cphi * u0y + sphi * ny;
  d.L = lanes_sqrt(d.C * d.C + mu2 * d.S * d.S);
  const Lanes Ls = d.L * s;
  const Lanes vc = d.C * p + d.S * qm;
  const auto along = vc > 0.0;
  d.num = along ? Ls + vc : cross2;
  d.den = along ? Ls : Ls * (Ls - vc);
  return d;
}

// ICR outside: the window of directions that hit the patch,
// e(phi) = -cos phi c^ + sin phi n, |phi| < asin(1/rho), oriented from the ICR towards the patch.
// The moment uses rho . (w/|w| + c'/|c'|) in place of rho . w/|w| (the same integral, since the
// pressure's centroid is the centre), which removes a cancellation of O(s) terms to O(1/s).
template <bool kPunch>
Result window_integral(double mu, double e2, double p, double q, double rho, double s) {
  const auto [u0x, u0y, nx, ny] = icr_frame(p, q, rho);
  const double T = window_half_width(rho);  // tan(asin(1/rho) / 2)
  Panels panels;
  build_panels(T, singularities(u0x, u0y, mu, std::sqrt(e2)), true, panels);
  const double rho2 = rho * rho;
  const double mu2 = mu * mu;
  const double mr2 = mu2 * rho2;
  const double qm = mu2 * q;  // v.c' = C p + mu^2 S q
  Lanes g1 = {0.0, 0.0};
  Lanes g2 = {0.0, 0.0};
  Lanes h = {0.0, 0.0};
  for_each_node_pair(panels, [&](Lanes cphi, Lanes sphi, Lanes w) {
    const auto [C, S, L, num, den] = window_direction(cphi, sphi, u0x, u0y, nx, ny, mu2, p, qm, s, mr2 * sphi * sphi);
    const Lanes inv = 1.0 / (L * den);  // one division per node
    const Lanes iL = inv * den;
    const Lanes D = 1.0 - rho2 * sphi * sphi;
    const Lanes chord = kPunch ? Lanes{1.0, 1.0} : D;
    const Lanes a = w * chord * cphi * iL;
    g1 += a * C;
    g2 += a * mu * S;
    const Lanes one_plus = num * inv * L;
    h += w * one_plus * chord * (s * rho * cphi + L * (rho2 * cphi * cphi + (kPunch ? 0.5 : 0.25) * D));
  });
  const double k = kPunch ? 0.5 : 0.75;
  return {k * rho * (g1[0] + g1[1]), k * rho * (g2[0] + g2[1]), k * (h[0] + h[1])};
}

// ---------------------------------------------------------------------------------------------
// Uniform pressure, p = N/(pi a b): by the divergence theorem (docs/pressure-models.md §3), with
// w = rho - c, w/|w| = grad |w| and 3|w| = div(w |w|), the patch integrals become rim integrals.
// Ellipse frame, units of a, Omega > 0, ICR c = s (sin psi, cos psi); rim rho(t) = (cos t, mu sin t),
// outward n ds = (mu cos t, sin t) dt:
//   G' = (1/(pi mu)) ∮ (|w| - |c|) n ds,
//   H  = (1/(pi mu)) ∮ f [ (1/3) rho.n + (2/3) c.n ] ds,   f = |w| + chat.w,
// any constant |c| and chat allowed (∮ n ds = 0; the pressure's centroid is the centre). Taken so
// that no O(s) terms cancel: |w| - |c| = (|rho|^2 - 2 rho.c)/(|w| + |c|), and for |c| > 1 (ICR
// outside the unit circle, hence the patch) chat = c/|c|, f = (chat x rho)^2/(|w| - chat.w) = O(1/s).

// Above this imaginary distance a zero of |rho(t) - c|^2 does not split the rim.
constexpr double kRimSplitDistance = 0.25;
// No zero nearer than kRimSplitDistance: the periodic trapezoid rule with N = exponent/d nodes
// (error ~ exp(-N d) times the integrand's growth in the strip), d capped so that N >= 12.
constexpr double kRimTrapezoidExponent = 32.0;
constexpr double kRimTrapezoidMaxDistance = 3.0;
// Where the lower bound on the zeros' distance (uniform_rim) is at least this, the rule uses the
// bound and skips the zeros (then N <= 46): a few more nodes, never fewer, and no complex square
// roots and logarithms. Measured on the benchmark set (docs/benchmarks.md), ICRs with
// 2 < |c~| < 10: ~470 ns per call with 2.0, ~320 ns with 0.7, no gain below.
constexpr double kRimZeroFreeDistance = 0.7;
// Below this a zero is on the rim to round-off: a kink |t - x| sqrt(g), analytic on each side of
// the split, so it is left out of the rule choice.
constexpr double kRimOnEdge = 1e-14;

struct RimZeros {
  std::array<std::complex<double>, 4> z{};  // e^(it)
  std::array<double, 4> x{};                // real parts (set by the graded branch)
  std::array<double, 4> d{};                // |imaginary parts|
  int count = 0;
  // The first `conjugate_free` come from the first quadratic below; the others are their complex
  // conjugates t -> conj(t) (the same x and d).
  int conjugate_free = 0;
};

// The complex zeros t = x +- i d of |rho(t) - c|^2 = (cos t - c1)^2 + (mu sin t - c2)^2: with
// z = e^(it), cos t - c1 = +-i (mu sin t - c2) reads
// (1 -+ mu) z^2 - 2 (c1 -+ i c2) z + (1 +- mu) = 0.
RimZeros rim_zeros(double mu, double c1, double c2) {
  using Complex = std::complex<double>;
  RimZeros out;
  const auto add = [&](Complex z, double r2) {
    if (!(r2 > 0.0) || !std::isfinite(r2)) return;
    const double d = 0.5 * std::abs(std::log(r2));
    if (d > 30.0) return;  // too far to matter
    out.z[static_cast<std::size_t>(out.count)] = z;  // its real part t = arg z only when needed
    out.d[static_cast<std::size_t>(out.count)] = d;
    ++out.count;
  };
  // Real arithmetic where a and c are real (std::complex's * and / would call the C99 Annex G
  // routines, which dominated the cost).
  for (const double sg : {1.0, -1.0}) {
    const double a = 1.0 - sg * mu;
    const double c = 1.0 + sg * mu;
    const double br = -2.0 * c1;
    const double bi = 2.0 * sg * c2;
    const Complex disc = std::sqrt(Complex(br * br - bi * bi - 4.0 * a * c, 2.0 * br * bi));
    const Complex qp(-0.5 * (br + disc.real()), -0.5 * (bi + disc.imag()));
    const Complex qm(-0.5 * (br - disc.real()), -0.5 * (bi - disc.imag()));
    const double np = std::norm(qp);
    const double nm = std::norm(qm);
    const Complex q = np >= nm ? qp : qm;
    const double nq = np >= nm ? np : nm;
    if (nq == 0.0) continue;
    if (a > 0.0) add(q / a, nq / (a * a));
    add(Complex(c * q.real() / nq, -c * q.imag() / nq), (c * c) / nq);
    if (sg > 0.0) out.conjugate_free = out.count;
  }
  return out;
}

// (|z - 1| + |z + 1|)/2 style singularity of a piece centred at m: the Weierstrass image
// u = tan((t - m)/2) of t = x + i d, i.e. (sin D + i sinh d)/(cos D + cosh d), D = x - m.
// With cos x, sin x, cosh d, sinh d of the zero and cos m, sin m of the piece, computed once each
// (per zero and piece, these trigonometric and hyperbolic functions were the graded branch's
// largest cost).
struct ZeroTrig {
  double cx, sx, ch, sh;
};
Point weierstrass_image(const ZeroTrig& z, double cm, double sm) {
  const double cD = z.cx * cm + z.sx * sm;
  const double sD = z.sx * cm - z.cx * sm;
  const double den = cD + z.ch;
  return {sD / den, z.sh / den};
}

// The rim integrands at one node (cos t, sin t) with weight wgt, accumulated into r.
struct RimIntegrand {
  double mu, c1, c2, cn, h1, h2;
  bool use_hat;
  void add(double ct, double st, double wgt, Result& r) const {
    const double r1 = ct;
    const double r2 = mu * st;
    const double w1 = r1 - c1;
    const double w2 = r2 - c2;
    const double wn = std::sqrt(w1 * w1 + w2 * w2);
    const double nx = mu * ct;
    const double ny = st;
    const double num = wgt * (r1 * r1 + r2 * r2 - 2.0 * (r1 * c1 + r2 * c2));
    double gt = 0.0;
    double f = wn;
    if (use_hat) {  // one division for both quotients
      const double cross = h1 * r2 - h2 * r1;
      const double den = wn - (h1 * w1 + h2 * w2);
      const double inv = 1.0 / ((wn + cn) * den);
      gt = num * den * inv;
      f = cross * cross * (wn + cn) * inv;
    } else {
      gt = num / (wn + cn);
    }
    r.g1 += gt * nx;
    r.g2 += gt * ny;
    r.h += wgt * f * (mu / 3.0 + (2.0 / 3.0) * (c1 * nx + c2 * ny));
  }
};

// cos and sin of the trapezoid step 2 pi/n for every even n the rule can ask for (n <= 2 ceil(16/0.25)),
// computed once (as they were per call).
struct RimStep {
  double c, s;
};
struct RimSteps {
  static constexpr int kMaxHalf = static_cast<int>(0.5 * kRimTrapezoidExponent / kRimSplitDistance) + 1;
  std::array<RimStep, kMaxHalf + 1> step{};
  // cosh(2 d_h), d_h = kRimTrapezoidExponent/(2h) the distance for which the rule takes n = 2h:
  // the zero-free bound's n without acosh
  std::array<double, kMaxHalf + 1> cosh_2d{};
  RimSteps() {
    for (int h = 1; h <= kMaxHalf; ++h) {
      const double dt = 2.0 * kPi / (2 * h);
      step[static_cast<std::size_t>(h)] = {std::cos(dt), std::sin(dt)};
      cosh_2d[static_cast<std::size_t>(h)] = std::cosh(kRimTrapezoidExponent / h);
    }
  }
};
const RimSteps& rim_steps() {
  static const RimSteps steps;
  return steps;
}

Result uniform_rim(double mu, double c1, double c2) {
  const double cn2 = c1 * c1 + c2 * c2;
  const double cn = std::sqrt(cn2);
  const bool use_hat = cn > 1.0;
  const RimIntegrand integrand{mu, c1, c2, cn, use_hat ? c1 / cn : 0.0, use_hat ? c2 / cn : 0.0, use_hat};
  const double scale = 1.0 / (kPi * mu);
  // A zero t = x + i d has c1 + i c2 = cos t +- i mu sin t, so |c|^2 <= (1 + mu^2) cosh(2d)
  // (Cauchy-Schwarz, |cos t|^2 + |sin t|^2 = cosh 2d). Where this lower bound on d is at least
  // kRimZeroFreeDistance the rule takes it (a few more nodes than the zeros would ask for, but
  // no zeros to find).
  const double ratio = cn2 / (1.0 + mu * mu);
  const RimSteps& steps = rim_steps();
  double d_min = kRimTrapezoidMaxDistance;
  int half = 0;  // n/2, from the bound
  RimZeros zeros;
  if (ratio >= std::cosh(2.0 * kRimZeroFreeDistance)) {
    // the least n = 2h with d_h <= min(bound, cap): h from ceil(16/3) = 6 up
    half = static_cast<int>(std::ceil(0.5 * kRimTrapezoidExponent / kRimTrapezoidMaxDistance));
    while (half < RimSteps::kMaxHalf && ratio < steps.cosh_2d[static_cast<std::size_t>(half)]) ++half;
  } else {
    zeros = rim_zeros(mu, c1, c2);
    for (int k = 0; k < zeros.count; ++k) d_min = std::min(d_min, zeros.d[static_cast<std::size_t>(k)]);
  }
  if (half > 0 || d_min >= kRimSplitDistance) {
    // No zero near the rim: the periodic trapezoid rule converges like exp(-N d_min); nodes by
    // rotation (no trigonometric function per node).
    const int n = half > 0 ? 2 * half : 2 * static_cast<int>(std::ceil(0.5 * kRimTrapezoidExponent / d_min));
    const double dt = 2.0 * kPi / n;
    const RimStep& step = steps.step[static_cast<std::size_t>(n / 2)];
    const double cd = step.c;
    const double sd = step.s;
    double ct = 1.0;
    double st = 0.0;
    Result r;
    for (int i = 0; i < n; ++i) {
      integrand.add(ct, st, dt, r);
      const double c_next = ct * cd - st * sd;
      st = st * cd + ct * sd;
      ct = c_next;
    }
    return {scale * r.g1, scale * r.g2, scale * r.h};
  }
  std::array<ZeroTrig, 4> trig{};
  for (int k = 0; k < zeros.count; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    const std::complex<double> z = zeros.z[kk];
    zeros.x[kk] = std::atan2(z.imag(), z.real());
    const double iz = 1.0 / std::abs(z);
    trig[kk] = {z.real() * iz, z.imag() * iz, std::cosh(zeros.d[kk]), std::sinh(zeros.d[kk])};
  }
  // Split points: the real parts of near zeros, sorted, deduplicated (modulo 2 pi).
  std::array<double, 4> split{};
  int n_split = 0;
  for (int k = 0; k < zeros.count; ++k) {
    if (zeros.d[static_cast<std::size_t>(k)] >= kRimSplitDistance) continue;
    const double x = zeros.x[static_cast<std::size_t>(k)];
    bool seen = false;
    for (int j = 0; j < n_split; ++j) {
      if (std::abs(std::remainder(x - split[static_cast<std::size_t>(j)], 2.0 * kPi)) < 1e-12) seen = true;
    }
    if (!seen) split[static_cast<std::size_t>(n_split++)] = x;
  }
  for (int i = 1; i < n_split; ++i) {  // insertion sort of at most 4
    for (int j = i; j > 0 && split[static_cast<std::size_t>(j - 1)] > split[static_cast<std::size_t>(j)]; --j) {
      std::swap(split[static_cast<std::size_t>(j - 1)], split[static_cast<std::size_t>(j)]);
    }
  }
  // Pieces: each arc between consecutive split points, halved (every piece then has at most one
  // near zero, at one of its ends, and is at most pi long); with no split point, two halves.
  std::array<double, 9> edge{};
  int n_edge = 0;
  if (n_split == 0) {
    edge = {0.0, kPi, 2.0 * kPi};
    n_edge = 3;
  } else {
    for (int j = 0; j < n_split; ++j) {
      const double a = split[static_cast<std::size_t>(j)];
      const double b = (j + 1 < n_split) ? split[static_cast<std::size_t>(j + 1)] : split[0] + 2.0 * kPi;
      edge[static_cast<std::size_t>(n_edge++)] = a;
      edge[static_cast<std::size_t>(n_edge++)] = 0.5 * (a + b);
    }
    edge[static_cast<std::size_t>(n_edge++)] = split[0] + 2.0 * kPi;
  }
  Result acc;
  Panels panels;
  // Pieces at most pi/2 long: the Weierstrass variable's poles at +-i then stay far from them.
  for (int i = 0; i + 1 < n_edge; ++i) {
    const double a = edge[static_cast<std::size_t>(i)];
    const double b = edge[static_cast<std::size_t>(i + 1)];
    if (!(b > a)) continue;
    const int parts = static_cast<int>(std::ceil((b - a) / (0.5 * kPi) - 1e-9));
    for (int j = 0; j < parts; ++j) {
    const double t0 = a + (b - a) * j / parts;
    const double t1 = (j + 1 == parts) ? b : a + (b - a) * (j + 1) / parts;
    const double m = 0.5 * (t0 + t1);
    const double T = std::tan(0.25 * (t1 - t0));
    const double cm = std::cos(m);
    const double sm = std::sin(m);
    Singularities sing;
    sing.z[0] = {0.0, kWeierstrassPoleMargin};
    sing.count = 1;
    for (int k = 0; k < zeros.count; ++k) {
      const double d = zeros.d[static_cast<std::size_t>(k)];
      if (d < kRimOnEdge) continue;
      sing.z[static_cast<std::size_t>(sing.count++)] = weierstrass_image(trig[static_cast<std::size_t>(k)], cm, sm);
    }
    build_panels(T, sing, false, panels);
    for_each_node_pair(panels, [&](Lanes cphi, Lanes sphi, Lanes wgt) {  // one node at a time, in order
      for (int l = 0; l < 2 && wgt[l] != 0.0; ++l) {
        integrand.add(cm * cphi[l] - sm * sphi[l], sm * cphi[l] + cm * sphi[l], wgt[l], acc);
      }
    });
    }
  }
  return {scale * acc.g1, scale * acc.g2, scale * acc.h};
}

// Uniform pressure, slender patches: the rim integrals folded by the patch's two mirror symmetries
// (docs/pressure-models.md §3). uniform_rim's G'_2 = (1/(pi mu)) ∮ (|w| - |c|) sin t dt is an
// O(mu) integral of O(1) terms divided by mu, so its rounding grows like 1e-16/mu (at b/a = 1e-12,
// F1 reached 1.00008 kN and went negative at tiny slip). Pairing each rim point with its mirror
// images removes the cancellation exactly: with T1(t) = |w(t)| + |w(pi - t)| and
// T2(t) = |w(t)| + |w(-t)|, |w(t)|^2 - |w(pi - t)|^2 = -4 c1 cos t and
// |w(t)|^2 - |w(-t)|^2 = -4 mu c2 sin t, so
//   G'_1 = -(2 c1/pi) ∮ cos^2 t / T1 dt,   G'_2 = -(2 c2/pi) ∮ sin^2 t / T2 dt,
//   H = (1/(3 pi)) ∮ |w| dt + (2/3) c.G'                                    (|c| <= 1),
//   H = (1/(3 pi)) ∮ g dt + (4/(3 pi |c|)) (c1^2 ∮ cos^2 t g1/T1 dt + c2^2 ∮ sin^2 t g2/T2 dt)
//                                                                            (|c| > 1),
// g = |w| - |c| = (|rho|^2 - 2 rho.c)/(|w| + |c|), g1 = g(t) + g(pi - t) = T1 - 2|c|,
// g2 = g(t) + g(-t) = T2 - 2|c| (the |c| > 1 form keeps the O(s) terms of H from cancelling, as
// chat does in uniform_rim). No 1/mu is left, and G' = -(c1 P1, c2 P2) with P1, P2 > 0, so
// F1 = s (sin^2 psi P1 + cos^2 psi P2) >= 0 by construction. The integrands have the four
// symmetries, so t runs over [0, pi/2] with the four images of each node; their singularities are
// the zeros of |rho(t) - c|^2 (rim_zeros) and their mirror images, folded into [0, pi/2].

// The route is taken below this axis ratio; above, uniform_rim, whose error (~1e-16/mu) is at most
// ~1e-12 there, is kept so that those outputs stay as they were, bit for bit.
constexpr double kRimFoldedMaxAxisRatio = 1e-4;

// A rim angle folded into [0, pi/2] by t -> -t, t -> pi - t (mod 2 pi).
double fold_rim_angle(double x) {
  const double t = std::abs(std::remainder(x, 2.0 * kPi));  // [0, pi]
  return t > 0.5 * kPi ? kPi - t : t;
}

// The four images of the rim node (cos t, sin t), t in [0, pi/2], accumulated with weight wgt.
struct FoldedRimIntegrand {
  double mu, c1, c2, cn;
  bool use_hat;
  struct Sums {
    double s1 = 0.0;  // ∫ cos^2 t (1/T1(t) + 1/T1(-t))
    double s2 = 0.0;  // ∫ sin^2 t (1/T2(t) + 1/T2(pi - t))
    double sh = 0.0;  // ∫ sum of |w| (|c| <= 1) or of g (|c| > 1) over the images
    double h1 = 0.0;  // ∫ cos^2 t (g1(t)/T1(t) + g1(-t)/T1(-t))   (|c| > 1)
    double h2 = 0.0;  // ∫ sin^2 t (g2(t)/T2(t) + g2(pi - t)/T2(pi - t))   (|c| > 1)
  };
  void add(double ct, double st, double wgt, Sums& r) const {
    const double x0 = ct - c1;   // t and -t
    const double x1 = -ct - c1;  // pi - t and pi + t
    const double y0 = mu * st - c2;
    const double y1 = -mu * st - c2;
    const double w0 = std::sqrt(x0 * x0 + y0 * y0);  // t
    const double w1 = std::sqrt(x0 * x0 + y1 * y1);  // -t
    const double w2 = std::sqrt(x1 * x1 + y0 * y0);  // pi - t
    const double w3 = std::sqrt(x1 * x1 + y1 * y1);  // pi + t
    const double t1a = w0 + w2;
    const double t1b = w1 + w3;
    const double t2a = w0 + w1;
    const double t2b = w2 + w3;
    const double c2t = ct * ct;
    const double s2t = st * st;
    r.s1 += wgt * c2t * (1.0 / t1a + 1.0 / t1b);
    r.s2 += wgt * s2t * (1.0 / t2a + 1.0 / t2b);
    if (!use_hat) {
      r.sh += wgt * (w0 + w1 + w2 + w3);
      return;
    }
    const double r2 = c2t + mu * mu * s2t;  // |rho|^2
    const double a = 2.0 * ct * c1;          // 2 rho.c = +-a +-b over the images
    const double b = 2.0 * mu * st * c2;
    const double g0 = (r2 - a - b) / (w0 + cn);
    const double g1 = (r2 - a + b) / (w1 + cn);
    const double g2 = (r2 + a - b) / (w2 + cn);
    const double g3 = (r2 + a + b) / (w3 + cn);
    r.sh += wgt * (g0 + g1 + g2 + g3);
    r.h1 += wgt * c2t * ((g0 + g2) / t1a + (g1 + g3) / t1b);
    r.h2 += wgt * s2t * ((g0 + g1) / t2a + (g2 + g3) / t2b);
  }
};

Result uniform_rim_folded(double mu, double c1, double c2) {
  const double cn2 = c1 * c1 + c2 * c2;
  const double cn = std::sqrt(cn2);
  const bool use_hat = cn > 1.0;
  const FoldedRimIntegrand integrand{mu, c1, c2, cn, use_hat};
  FoldedRimIntegrand::Sums sums;
  // The zeros' distances, or the lower bound on them, as in uniform_rim (the mirror images have
  // the same distances).
  const double ratio = cn2 / (1.0 + mu * mu);
  const RimSteps& steps = rim_steps();
  double d_min = kRimTrapezoidMaxDistance;
  int half = 0;
  RimZeros zeros;
  if (ratio >= std::cosh(2.0 * kRimZeroFreeDistance)) {
    half = static_cast<int>(std::ceil(0.5 * kRimTrapezoidExponent / kRimTrapezoidMaxDistance));
    while (half < RimSteps::kMaxHalf && ratio < steps.cosh_2d[static_cast<std::size_t>(half)]) ++half;
  } else {
    zeros = rim_zeros(mu, c1, c2);
    for (int k = 0; k < zeros.count; ++k) d_min = std::min(d_min, zeros.d[static_cast<std::size_t>(k)]);
  }
  if (half > 0 || d_min >= kRimSplitDistance) {
    // The periodic trapezoid rule of uniform_rim, with n rounded up to a multiple of 4 so that its
    // nodes are closed under the symmetries: t_j = 2 pi j/n, j = 0 .. n/4; the nodes t = 0 and
    // pi/2 have two distinct images, not four, and are weighted 1/2.
    const int n0 = half > 0 ? 2 * half : 2 * static_cast<int>(std::ceil(0.5 * kRimTrapezoidExponent / d_min));
    const int n = 4 * ((n0 + 3) / 4);
    const double dt = 2.0 * kPi / n;
    const double cd = std::cos(dt);
    const double sd = std::sin(dt);
    double ct = 1.0;
    double st = 0.0;
    for (int j = 0; j <= n / 4; ++j) {
      if (4 * j == n) {  // t = pi/2 exactly
        ct = 0.0;
        st = 1.0;
      }
      integrand.add(ct, st, (j == 0 || 4 * j == n) ? 0.5 * dt : dt, sums);
      const double c_next = ct * cd - st * sd;
      st = st * cd + ct * sd;
      ct = c_next;
    }
  } else {
    // Graded Gauss-Legendre panels on [0, pi/2], split at the folded real parts of the near zeros
    // and each arc halved, as uniform_rim does on the whole rim. A zero at x + i d stands for
    // x' + i d, -x' + i d and pi - x' + i d near [0, pi/2] (x' = fold_rim_angle(x)).
    // The zeros of the first quadratic only: the others are their conjugates (the same x, d).
    zeros.count = zeros.conjugate_free;
    std::array<double, 4> folded{};
    for (int k = 0; k < zeros.count; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const std::complex<double> z = zeros.z[kk];
      folded[kk] = fold_rim_angle(std::atan2(z.imag(), z.real()));
    }
    std::array<double, 6> split{};
    int n_split = 0;
    split[static_cast<std::size_t>(n_split++)] = 0.0;
    split[static_cast<std::size_t>(n_split++)] = 0.5 * kPi;
    for (int k = 0; k < zeros.count; ++k) {
      if (zeros.d[static_cast<std::size_t>(k)] >= kRimSplitDistance) continue;
      const double x = folded[static_cast<std::size_t>(k)];
      bool seen = false;
      for (int j = 0; j < n_split; ++j) {
        if (std::abs(x - split[static_cast<std::size_t>(j)]) < 1e-12) seen = true;
      }
      if (!seen) split[static_cast<std::size_t>(n_split++)] = x;
    }
    std::sort(split.begin(), split.begin() + n_split);
    Panels panels;
    for (int i = 0; i + 1 < n_split; ++i) {
      const double a = split[static_cast<std::size_t>(i)];
      const double b = split[static_cast<std::size_t>(i + 1)];
      for (int j = 0; j < 2; ++j) {  // the arc halved: at most one near zero, at one end
        const double t0 = j == 0 ? a : 0.5 * (a + b);
        const double t1 = j == 0 ? 0.5 * (a + b) : b;
        if (!(t1 > t0)) continue;
        const double m = 0.5 * (t0 + t1);
        const double T = std::tan(0.25 * (t1 - t0));
        const double cm = std::cos(m);
        const double sm = std::sin(m);
        Singularities sing;
        sing.z[0] = {0.0, kWeierstrassPoleMargin};
        sing.count = 1;
        for (int k = 0; k < zeros.count; ++k) {
          const auto kk = static_cast<std::size_t>(k);
          const double d = zeros.d[kk];
          if (d < kRimOnEdge) continue;
          const double ch = std::cosh(d);
          const double sh = std::sinh(d);
          for (const double x : {folded[kk], -folded[kk], kPi - folded[kk]}) {  // at most 1 + 2 x 3
            sing.z[static_cast<std::size_t>(sing.count++)] =
                weierstrass_image({std::cos(x), std::sin(x), ch, sh}, cm, sm);
          }
        }
        build_panels(T, sing, false, panels, true);
        for_each_node_pair(panels, [&](Lanes cphi, Lanes sphi, Lanes wgt) {
          for (int l = 0; l < 2 && wgt[l] != 0.0; ++l) {
            integrand.add(cm * cphi[l] - sm * sphi[l], sm * cphi[l] + cm * sphi[l], wgt[l], sums);
          }
        });
      }
    }
  }
  Result r;
  r.g1 = -(4.0 / kPi) * c1 * sums.s1;
  r.g2 = -(4.0 / kPi) * c2 * sums.s2;
  if (use_hat) {
    r.h = (1.0 / (3.0 * kPi)) * sums.sh + (4.0 / (3.0 * kPi * cn)) * (c1 * c1 * sums.h1 + c2 * c2 * sums.h2);
  } else {
    r.h = (1.0 / (3.0 * kPi)) * sums.sh + (2.0 / 3.0) * (c1 * r.g1 + c2 * r.g2);
  }
  return r;
}

// Uniform pressure, ICR inside: the ICR reduction with the chord factor sqrt(D)
// (docs/pressure-models.md §3), in u = F(tau, e): tau = am(u, e), C = cn u, S = sn u, L = dn u,
// dtau / L = du, so
//   G' = -(2/pi) ∫_0^2K sqrt(D) (e.c~) v du,   H = (2/pi) ∫_0^2K sqrt(D) [X + D L^2/3] du,
// polynomials in sn, cn, dn times sqrt(D): the thin patch's near-singularity of 1/L is gone. The
// periodic trapezoid rule in u converges like exp(-pi N a / K), a the distance of the nearest
// singularity from the real axis: the poles of sn, cn, dn at K', the branch points of sqrt(D),
// taken at acos(rho) (their distance where L is least stretched; the rule is calibrated below).
// sn, cn, dn at the nodes u = 2K j/N come from theta series whose angles z = pi j/N are
// tabulated.

// The route is taken for rho = |c~| below this and mu from kSlenderAxisRatio (smaller mu would
// need more theta terms). Nearer the rim N grows like 1/acos(rho); at 0.97 it is still cheaper
// than the graded rim integrals (measured: the benchmark set's ICRs with 0.9 < rho < 1 took
// ~1.7 us by the rim alone, ~0.9 us with this route up to 0.97).
constexpr double kInsideMaxRho = 0.97;
// Trapezoid nodes per period 2K: N >= kInsideExponent K / (pi a), the next size in kInsideNodes.
// Calibrated on 200,000 random cases (mu log-uniform in [0.01, 1], psi anywhere, both spins;
// s log-uniform in [1e-4, 1e4], |c~| uniform in [0, 1], and within 1e-6..0.3 of the rim inside
// and out) against the rim integrals run with kRimTrapezoidExponent = 48: largest difference
// 6.6e-13 (30 gave 4.6e-12, 22 gave 1e-8; the worst cases are small rho, mu ~ 0.02, in M).
// Checked again with a = inside_branch_distance (for acos rho) on 150,000 inputs (the same
// distributions, mu in [0.01, 0.011] for one in seven) against the rim at exponent 44 and this
// route at 48: 6.7e-13 (30 gave 4.6e-12, 28 gave 3.2e-11: small rho, mu ~ 0.1-0.3, in M).
constexpr double kInsideExponent = 32.0;
// Tabulated angles z_j = pi j / kThetaBase, j <= kThetaBase / 2: N must divide kThetaBase, and
// N/4 must be an integer (the nodes in [K/2, K] come from those in [0, K/2]).
constexpr int kThetaBase = 480;
constexpr std::array<int, 15> kInsideNodes = {8, 12, 16, 20, 24, 32, 40, 48, 60, 80, 96, 120, 160, 240, 480};
// Terms of each theta series: the first neglected is qn^72 (t1, t2) or qn^81 (theta_3, theta_4),
// below 1e-25 for mu >= 0.01 (nome qn <= 0.44).
constexpr int kThetaTerms = 8;
// Terms with qn^(n(n+1)) below this are dropped (theta_3,4's qn^((n+1)^2) are smaller still): 6
// terms at mu = 0.1, 4 at 0.5, 3 from mu ~ 0.75, 8 only below mu ~ 0.03. Outputs changed by at
// most 3e-16 (150,000 random inputs, against all 8 terms).
constexpr double kThetaCut = 1e-18;

struct ThetaTable {
  struct Row {
    std::array<double, kThetaTerms> c_odd, s_odd, c_even;  // cos, sin((2n+1) z), cos(2(n+1) z)
  };
  std::array<Row, kThetaBase / 2 + 1> row{};
  ThetaTable() {
    for (int j = 0; j <= kThetaBase / 2; ++j) {
      Row& r = row[static_cast<std::size_t>(j)];
      for (int n = 0; n < kThetaTerms; ++n) {
        const long double z = std::numbers::pi_v<long double> * j / kThetaBase;
        r.c_odd[static_cast<std::size_t>(n)] = static_cast<double>(std::cos((2 * n + 1) * z));
        r.s_odd[static_cast<std::size_t>(n)] = static_cast<double>(std::sin((2 * n + 1) * z));
        r.c_even[static_cast<std::size_t>(n)] = static_cast<double>(std::cos((2 * n + 2) * z));
      }
    }
  }
};

// A lower bound on the distance in u of the branch points of sqrt(D) from the real axis. With
// c~ = rho (cos theta, sin theta), e x c~ = +-1 at tau = theta +- pi/2 + i acosh(1/rho). Above
// tau0 = 0 (where L is largest) the distance is (Jacobi's imaginary transformation)
// Im F(i acosh(1/rho), e) = F(acos rho, mu); Jensen's inequality for the convex 1/sqrt(1 - x)
// bounds it below by phi / sqrt(1 - mu^2 <sin^2>), <sin^2> = 1/2 - sin(2 phi)/(4 phi) the mean of
// sin^2 over [0, phi], phi = acos rho. Equal to acos rho for thin patches, up to sqrt 2 times it
// for the circle; never above K' = F(pi/2, mu), so the poles of sn, cn, dn need no check. (That
// tau0 = 0 gives the least distance is not proven: the rule's exponent is calibrated with it.)
double inside_branch_distance(double mu, double rho) {
  const double phi = std::acos(rho);
  if (!(phi > 0.0)) return phi;
  const double mean_sin2 = 0.5 - 0.5 * rho * std::sqrt((1.0 - rho) * (1.0 + rho)) / phi;
  return phi / std::sqrt(1.0 - mu * mu * mean_sin2);
}

Result uniform_inside(double mu, double p, double q) {
  static const ThetaTable table;
  // The nome qn = exp(-pi K'/K) of the modulus e (complementary modulus mu), from its series in
  // eps = (1 - sqrt k')/(2 (1 + sqrt k')) (Abramowitz & Stegun 17.3.21): for mu >= 0.5 directly
  // (eps <= 0.086: the terms kept reach eps^17), below through the nome qc of the complementary
  // modulus (eps <= 0.018), ln qn ln qc = pi^2.
  const double e2 = (1.0 - mu) * (1.0 + mu);
  double qn = 0.0;
  if (mu >= 0.5) {
    const double sk = std::sqrt(mu);
    const double eps = (1.0 - sk) / (2.0 * (1.0 + sk));
    const double e4 = (eps * eps) * (eps * eps);
    qn = eps * (1.0 + 2.0 * e4 * (1.0 + 7.5 * e4 * (1.0 + 10.0 * e4 * (1.0 + 11.38 * e4))));
  } else {
    const double e = std::sqrt(e2);
    const double sk = std::sqrt(e);
    const double eps = (mu * mu / ((1.0 + e) * (1.0 + sk))) / (2.0 * (1.0 + sk));  // 1 - sqrt e without cancellation
    const double e4 = (eps * eps) * (eps * eps);
    const double qc = eps * (1.0 + 2.0 * e4 * (1.0 + 7.5 * e4 * (1.0 + 10.0 * e4)));
    qn = std::exp(kPi * kPi / std::log(qc));
  }
  // Theta series (DLMF 20.2.1-4) with theta_1, theta_2 divided by 2 qn^(1/4):
  //   t1 = sum (-1)^n qn^(n(n+1)) sin((2n+1) z),  t2 = sum qn^(n(n+1)) cos((2n+1) z),
  //   theta_3,4 = 1 + 2 sum_(n>=1) (+-1)^n qn^(n^2) cos(2n z);
  // sn = (theta_3(0)/t2(0)) t1/theta_4, cn = (theta_4(0)/t2(0)) t2/theta_4,
  // dn = (theta_4(0)/theta_3(0)) theta_3/theta_4 (DLMF 22.2.4-6), K = (pi/2) theta_3(0)^2 (20.9.2).
  // Only the terms with qn^(n(n+1)) >= kThetaCut are kept: the rest are below round-off relative
  // to the series at the nodes (z <= pi/4, where t2 ~ cos z and theta_4 >= 1 - 2 qn > 0.1).
  std::array<double, kThetaTerms> co{}, so{}, c3{}, c4{};
  std::size_t terms = 0;
  {
    double o = 1.0;    // qn^(n(n+1))
    double oq = qn * qn;
    double v = qn;     // qn^((n+1)^2)
    double vq = qn * qn * qn;
    for (int n = 0; n < kThetaTerms && o >= kThetaCut; ++n) {
      const auto k = static_cast<std::size_t>(n);
      co[k] = o;
      so[k] = (n % 2 == 0) ? o : -o;
      c3[k] = 2.0 * v;
      c4[k] = (n % 2 == 0) ? -2.0 * v : 2.0 * v;
      o *= oq;
      oq *= qn * qn;
      v *= vq;
      vq *= qn * qn;
      ++terms;
    }
  }
  double t2_0 = 0.0;
  double th3_0 = 1.0;
  double th4_0 = 1.0;
  for (std::size_t k = terms; k-- > 0;) {  // smallest first
    t2_0 += co[k];
    th3_0 += c3[k];
    th4_0 += c4[k];
  }
  const double K = 0.5 * kPi * th3_0 * th3_0;
  // Nodes: the nearest singularity at a from the real axis, the branch points of sqrt(D) at
  // F(acos rho, mu) or more, bounded below by inside_branch_distance; the poles of sn, cn, dn at
  // K' = F(pi/2, mu) are never nearer.
  const double rho = std::sqrt(p * p + q * q);
  const double a = inside_branch_distance(mu, rho);
  const double wanted = kInsideExponent * K / (kPi * a);
  int N = kInsideNodes.back();
  for (const int n : kInsideNodes) {
    if (n >= wanted) {
      N = n;
      break;
    }
  }
  const int stride = kThetaBase / N;
  const int half = N / 2;
  const double fs = th3_0 / t2_0;
  const double fc = th4_0 / t2_0;
  const double fd = th4_0 / th3_0;
  // e = (C, S) at u = 2K j/N and (-C, S) at 2K - u (sn(2K - u) = sn u, cn(2K - u) = -cn u): the
  // pairs for j in [0, N/2] cover the period; at j = 0 and N/2 the two are one node (the integrand
  // is even in e), weighted 1/2 each.
  // sn, cn, dn for u in [0, K/2] by the series, in [K/2, K] by u -> K - u (DLMF 22.4.3:
  // sn(K - u) = cn/dn, cn(K - u) = mu sn/dn, dn(K - u) = mu/dn).
  std::array<double, kThetaBase / 2 + 2> Cs, Ss, L2s;  // one more: a zero node pads the last pair
  const double mu2 = mu * mu;
  // u = 0 and its reflection u = K exactly: sn, cn, dn = 0, 1, 1 and 1, 0, mu.
  Ss[0] = 0.0;
  Cs[0] = 1.0;
  L2s[0] = 1.0;
  Ss[static_cast<std::size_t>(half)] = 1.0;
  Cs[static_cast<std::size_t>(half)] = 0.0;
  L2s[static_cast<std::size_t>(half)] = mu2;
  const double ifd = th3_0 / th4_0;
  for (int j = 1; j <= N / 4; ++j) {
    const ThetaTable::Row& z = table.row[static_cast<std::size_t>(j * stride)];
    double t1 = 0.0;
    double t2 = 0.0;
    double t3 = 1.0;
    double t4 = 1.0;
    for (std::size_t k = 0; k < terms; ++k) {
      t1 += so[k] * z.s_odd[k];
      t2 += co[k] * z.c_odd[k];
      t3 += c3[k] * z.c_even[k];
      t4 += c4[k] * z.c_even[k];
    }
    const double inv = 1.0 / (t3 * t4);  // one division for 1/theta_4 and 1/dn
    const double i4 = t3 * inv;
    const auto jj = static_cast<std::size_t>(j);
    Ss[jj] = fs * t1 * i4;
    Cs[jj] = fc * t2 * i4;
    const double L = fd * t3 * i4;
    L2s[jj] = L * L;
    if (4 * j == N) break;  // u = K/2 is its own reflection
    const auto jr = static_cast<std::size_t>(half - j);
    const double iL = ifd * t4 * t4 * inv;
    Ss[jr] = Cs[jj] * iL;
    Cs[jr] = mu * Ss[jj] * iL;
    L2s[jr] = mu2 * iL * iL;
  }
  // Two nodes at a time (j, j + 1 in the lanes); a node (C, S, L^2) = 0 past the last one adds
  // exactly 0 (D = 1, e.c~ = 0, L^2 = 0).
  {
    const auto pad = static_cast<std::size_t>(half + 1);
    Cs[pad] = 0.0;
    Ss[pad] = 0.0;
    L2s[pad] = 0.0;
  }
  Lanes g1v = {0.0, 0.0};
  Lanes g2v = {0.0, 0.0};
  Lanes hv = {0.0, 0.0};
  for (int j = 0; j <= half; j += 2) {
    const auto jj = static_cast<std::size_t>(j);
    const Lanes C = {Cs[jj], Cs[jj + 1]};
    const Lanes S = {Ss[jj], Ss[jj + 1]};
    const Lanes L2 = {L2s[jj], L2s[jj + 1]};
    const Lanes w = {(j == 0 || j == half) ? 0.5 : 1.0, (j + 1 == half) ? 0.5 : 1.0};
    const Lanes A = C * p;
    const Lanes B = S * q;
    const Lanes X = C * q;
    const Lanes Y = S * p;
    const Lanes ex_p = X - Y;  // e x c~ at (C, S)
    const Lanes ex_m = X + Y;  // minus e x c~ at (-C, S)
    const Lanes D_p = 1.0 - ex_p * ex_p;
    const Lanes D_m = 1.0 - ex_m * ex_m;
    const Lanes r_p = w * lanes_sqrt(D_p);
    const Lanes r_m = w * lanes_sqrt(D_m);
    const Lanes ec_p = r_p * (A + B);  // sqrt(D) e.c~
    const Lanes ec_m = r_m * (B - A);
    g1v += C * (ec_p - ec_m);
    g2v += S * (ec_p + ec_m);
    hv += e2 * S * C * (ex_p * ec_p + ex_m * ec_m) + (1.0 / 3.0) * L2 * (r_p * D_p + r_m * D_m);
  }
  const double g1 = g1v[0] + g1v[1];
  const double g2 = g2v[0] + g2v[1];
  const double h = hv[0] + hv[1];
  const double k = (2.0 / kPi) * (2.0 * K / N);
  return {-k * g1, -k * mu * g2, k * h};
}

// The uniform window's integrand (below) at two nodes: sin chi and cos^2 chi in the lanes, each
// weighted by wgt, added into g1, g2 (per cos^2 chi v/L) and h. The ICR's scaled direction c^ =
// (p, q)/rho, u0 = -c^, n = J c^; qm = mu^2 q.
struct UniformWindowIntegrand {
  double rho, irho, u0x, u0y, nx, ny, mu2, p, qm, s;
  void add(Lanes schi, Lanes c2, Lanes wgt, Lanes& g1, Lanes& g2, Lanes& h) const {
    const Lanes sphi = schi * irho;
    const Lanes root = lanes_sqrt((rho - schi) * (rho + schi));  // rho cos phi
    const Lanes cphi = root * irho;
    const auto [C, S, L, num, den] = window_direction(cphi, sphi, u0x, u0y, nx, ny, mu2, p, qm, s, mu2 * schi * schi);
    const Lanes ld = L * den;
    const Lanes inv3 = 1.0 / (ld * root);  // one division per node for 1/(L den) and 1/root
    const Lanes inv = inv3 * root;
    const Lanes a = wgt * c2 * inv * den;  // cos^2 chi / L, weighted
    g1 += a * C;
    g2 += a * S;
    const Lanes one_plus = num * inv * L;
    h += wgt * c2 * one_plus * (s + L * (root + (1.0 / 3.0) * c2 * ld * inv3));
  }
};

// Uniform pressure, ICR outside: the window of the ICR reduction (as window_integral, with the
// chord factor sqrt(D), prefactor 2/pi and chord moment 1/3; docs/pressure-models.md §3) in the
// variable chi of rho sin phi = sin chi, chi in [-pi/2, pi/2]: sqrt(D) = cos chi and
// dphi = cos chi dchi / (rho cos phi), rho cos phi = sqrt(rho^2 - sin^2 chi), so
//   G' = (2/pi) ∫ cos^2 chi v/L dchi,
//   H  = (2/pi) ∫ cos^2 chi (1 + d.c^) [ s + L (rho cos phi + cos^2 chi/(3 rho cos phi)) ] dchi.
// The integrand depends on chi through sin chi and cos^2 chi only, so it is the half of a smooth
// 2 pi-periodic function (even about chi = +-pi/2): the periodic trapezoid rule applies, and
// converges like exp(-N d), d the distance from the real axis of the nearest singularity: the
// branch points of rho cos phi at sin chi = +-rho (d = acosh rho) and those of L at
// sin chi = rho sin phi*, phi* = x + i atanh(mu) (as in singularities()). Nodes
// chi_j = -pi/2 + 2 pi j/N, j = 1 .. N/2 - 1 (the ends contribute 0, the other half mirrors
// these), weight 2 pi/N; sin and cos by rotation. Sets done = false (nothing computed) where the
// rule would need more than kWindowMaxNodes nodes (the ICR within ~0.03 of the rim, or L's branch
// point that near the real axis): the rim integrals take those.
//
// Nodes: n = 2h, the least h >= kWindowMinHalf with (2h - 2 kWindowGrowth) d >= kWindowExponent,
// i.e. the rim's exponent with 2 kWindowGrowth nodes more for the integrand's growth in the strip
// (cos^2 chi and the factors L, rho cos phi grow like exp(|Im chi|)). Calibrated on 60,000 random
// inputs (mu log-uniform in [0.01, 1], psi anywhere, both spins; a third each with s log-uniform in
// [1e-4, 1e4], the ICR within 1e-6..0.3 of the rim inside and out, rho log-uniform in [1, 100])
// against the rim integrals: largest difference 3.7e-13 with kWindowGrowth = 2 (the rim's own
// level), 1.2e-11 with 1, 4.8e-8 with 0 (at rho ~ 100 to 1500, where d is large and n small).
constexpr double kWindowExponent = kRimTrapezoidExponent;
constexpr int kWindowGrowth = 2;
constexpr int kWindowMinHalf = 4;  // n >= 8, i.e. 3 evaluations
constexpr int kWindowMaxNodes = 2 * RimSteps::kMaxHalf;
Result uniform_window(double mu, double p, double q, double rho, double s, bool& done) {
  const auto [u0x, u0y, nx, ny] = icr_frame(p, q, rho);
  // cosh d of the nearest singularity: rho for rho cos phi; for L, with
  // w = rho sin phi* = rho (sin x + i mu cos x)/e, cosh |Im asin w| = (|w + 1| + |w - 1|)/2.
  double cosh_d = rho;
  const double e2 = (1.0 - mu) * (1.0 + mu);
  if (e2 > 0.0) {
    double sx = -u0x;
    double cxx = u0y;
    if (cxx < 0.0) {
      sx = -sx;
      cxx = -cxx;
    }
    const double e = std::sqrt(e2);
    const double wr = rho * sx / e;
    const double wi = rho * mu * cxx / e;
    cosh_d = std::min(cosh_d, 0.5 * (std::sqrt((wr + 1.0) * (wr + 1.0) + wi * wi) +
                                     std::sqrt((wr - 1.0) * (wr - 1.0) + wi * wi)));
  }
  // (2h - 2g) d >= kWindowExponent, i.e. 2 d >= kWindowExponent/(h - g), compared through
  // cosh(2 d) = 2 cosh^2 d - 1 with the table cosh(kRimTrapezoidExponent/h) of rim_steps().
  static_assert(kWindowExponent == kRimTrapezoidExponent && kWindowMinHalf > kWindowGrowth);
  const RimSteps& steps = rim_steps();
  const double cosh_2d = 2.0 * cosh_d * cosh_d - 1.0;
  int half = kWindowMinHalf;
  while (half <= RimSteps::kMaxHalf && cosh_2d < steps.cosh_2d[static_cast<std::size_t>(half - kWindowGrowth)]) ++half;
  if (half > kWindowMaxNodes / 2) {
    done = false;
    return {};
  }
  const int n = 2 * half;
  done = true;
  const RimStep& step = rim_steps().step[static_cast<std::size_t>(half)];
  const double cd = step.c;
  const double sd = step.s;
  const double mu2 = mu * mu;
  const UniformWindowIntegrand f{rho, 1.0 / rho, u0x, u0y, nx, ny, mu2, p, mu2 * q, s};
  // Two nodes at a time, j and j + 1 in the two lanes: (cos, sin) of j 2pi/n, rotated by
  // 2 (2pi/n) per step; chi = -pi/2 + j 2 pi/n: sin chi = -cos, cos chi = sin. Past the last node
  // (an odd count) the second lane repeats the first at weight 0 (a finite integrand: it adds 0).
  const double c2d = cd * cd - sd * sd;
  const double s2d = 2.0 * sd * cd;
  Lanes cj = {cd, c2d};
  Lanes sj = {sd, s2d};
  Lanes g1 = {0.0, 0.0};
  Lanes g2 = {0.0, 0.0};
  Lanes h = {0.0, 0.0};
  for (int j = 1; j < half; j += 2) {
    Lanes schi = -cj;
    Lanes c2 = sj * sj;
    Lanes wgt = {1.0, 1.0};
    if (j + 1 == half) {
      schi[1] = schi[0];
      c2[1] = c2[0];
      wgt[1] = 0.0;
    }
    const Lanes c_next = cj * c2d - sj * s2d;
    sj = sj * c2d + cj * s2d;
    cj = c_next;
    f.add(schi, c2, wgt, g1, g2, h);
  }
  const double k = (2.0 / kPi) * (2.0 * kPi / n);
  return {k * (g1[0] + g1[1]), k * mu * (g2[0] + g2[1]), k * (h[0] + h[1])};
}

// Uniform pressure, ICR outside, where the trapezoid of uniform_window would need too many nodes
// (L's branch points near the real chi axis: slender patches, directions near the minor axis):
// the same integrand over chi in [-pi/2, pi/2], by composite Gauss-Legendre panels (build_panels)
// in t = tan(chi/2) in [-1, 1], graded towards the nearest singularity. In t: the poles of the
// substitution at t = +-i (with the margin of the Hertz window), the branch points of
// rho cos phi = sqrt(rho^2 - sin^2 chi) at sin chi = +-rho, t = (+-1 + i sqrt(rho^2 - 1))/rho, and
// those of L at sin chi = +-w, w = rho sin phi* (as in uniform_window), t = +-w/(1 + sqrt(1 - w^2))
// and their reciprocals (chi and pi - chi).
Result uniform_window_graded(double mu, double p, double q, double rho, double s) {
  using Complex = std::complex<double>;
  const auto [u0x, u0y, nx, ny] = icr_frame(p, q, rho);
  Singularities sing;
  sing.z[0] = {0.0, kWeierstrassPoleMargin};
  sing.z[1] = {1.0 / rho, std::sqrt((rho - 1.0) * (rho + 1.0)) / rho};
  sing.z[2] = {-sing.z[1].re, sing.z[1].im};
  sing.count = 3;
  const double e2 = (1.0 - mu) * (1.0 + mu);
  if (e2 > 0.0) {
    const double e = std::sqrt(e2);
    const Complex w(rho * (-u0x) / e, rho * mu * u0y / e);
    const Complex t = w / (1.0 + std::sqrt(1.0 - w * w));
    const Complex ti = 1.0 / t;
    sing.z[3] = {t.real(), t.imag()};
    sing.z[4] = {-t.real(), t.imag()};
    sing.z[5] = {ti.real(), ti.imag()};
    sing.z[6] = {-ti.real(), ti.imag()};
    sing.count = 7;
  }
  Panels panels;
  build_panels(1.0, sing, false, panels, true);
  const double mu2 = mu * mu;
  const UniformWindowIntegrand f{rho, 1.0 / rho, u0x, u0y, nx, ny, mu2, p, mu2 * q, s};
  Lanes g1 = {0.0, 0.0};
  Lanes g2 = {0.0, 0.0};
  Lanes h = {0.0, 0.0};
  for_each_node_pair(panels, [&](Lanes cchi, Lanes schi, Lanes wgt) { f.add(schi, cchi * cchi, wgt, g1, g2, h); });
  const double k = 2.0 / kPi;
  return {k * (g1[0] + g1[1]), k * mu * (g2[0] + g2[1]), k * (h[0] + h[1])};
}

// Hertz and punch: the ICR reduction (docs/exact-law.md §1; the punch's chord factor in
// docs/pressure-models.md), the ICR inside in closed form, outside by window or whole - gap.
template <bool kPunch>
Result icr_reduction(double mu, double e2, double p, double q, double rho2, double s) {
  Result r;
  bool use_window = rho2 > (mu < kSlenderAxisRatio ? kMaxGapRho2Slender : kMaxGapRho2);
  if (rho2 > 1.0 && !use_window) {
    const double rho = std::sqrt(rho2);
    const double e = std::sqrt(e2);
    const double sigma_gap =
        difficulty_sigma(gap_half_width(rho), singularities(-q / rho, p / rho, mu, e));
    const double sigma_window =
        difficulty_sigma(window_half_width(rho), singularities(-p / rho, -q / rho, mu, e));
    use_window = sigma_window > sigma_gap;
  }
  if (use_window) {
    r = window_integral<kPunch>(mu, e2, p, q, std::sqrt(rho2), s);
  } else {
    const Moments m = moments(mu, e2);
    r = kPunch ? whole_period_punch(m, mu, e2, p, q) : whole_period(m, mu, e2, p, q);
    if (rho2 > 1.0) {
      const Result gap = gap_integral<kPunch>(mu, e2, p, q, std::sqrt(rho2));
      r.g1 -= gap.g1;
      r.g2 -= gap.g2;
      r.h -= gap.h;
    }
  }
  return r;
}

}  // namespace

std::vector<LawParameter> ExactLaw::parameters() {
  return {LawParameter::choice("pressure", pressure_names(), "hertz",
                               "the normal pressure over the patch (docs/pressure-models.md): hertz "
                               "(elastic bodies), uniform (flat face, Contensou), punch (rigid flat punch)")};
}

LawPromises ExactLaw::promises() const {
  LawPromises p;
  p.F1_in_Omega = Parity::even;
  p.F2_in_Omega = Parity::even;
  p.M_in_Omega = Parity::odd;
  p.pi_periodic_in_psi = true;
  p.psi_mirror = true;
  p.dissipative = true;
  p.bounded = true;
  p.whole_domain = true;
  p.exact_pure_spin = true;
  p.pure_spin_factor = pressure_pure_spin_factor(pressure_);
  p.min_axis_ratio = kExactMinAxisRatio;
  p.tolerance = pressure_ == Pressure::hertz ? kExactLawAccuracy : kExactLawPressureAccuracy;
  return p;
}

FrictionForces ExactLaw::do_evaluate(const ContactInput& in) const {
  const double mu = in.b / in.a;
  if (mu < kExactMinAxisRatio) {
    throw std::invalid_argument("friction input b = " + support::shortest(in.b) +
                                " is invalid for exact: the axis ratio b/a = " + support::shortest(mu) + " is below " +
                                support::significant(kExactMinAxisRatio, 3) +
                                ", the smallest its quadrature is built for (a patch that slender is a line)");
  }
  const double kN = in.k * in.N;
  if (kN == 0.0) return {};
  if (in.Omega == 0.0) {
    if (in.U == 0.0) return {};  // indeterminate at U = Omega = 0: documented as zero
    return {kN, 0.0, 0.0};       // pure sliding
  }
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  const double s = slip_ratio(in.U, in.a, in.Omega);  // may be +inf: fast-slip branch
  // A circle is symmetric under rotation: psi = 0 makes F2 = 0 exact.
  const PatchAngle::CosSin axis = (mu == 1.0) ? PatchAngle::CosSin{1.0, 0.0} : in.psi.cos_sin();
  const double cpsi = axis.c;
  const double spsi = axis.s;
  const double e2 = (1.0 - mu) * (1.0 + mu);

  if (s > kFastSlipRatio) {
    // Fast-slip expansion (docs/model.md, docs/pressure-models.md): with m2 the pressure's
    // second moment per axis (1/5 Hertz), F1 = kN (1 - m2 d3/(2 s^2)), F2 = kN m2 d4/(2 s^2),
    // M = kNa m2 d3/s.
    const double d3 = e2 * cpsi * cpsi + mu * mu;
    const double d4 = 2.0 * e2 * spsi * cpsi;
    const double is = 1.0 / s;
    if (pressure_ == Pressure::hertz) {  // kept as it was, bit for bit
      return {kN * (1.0 - 0.1 * d3 * is * is), kN * 0.1 * d4 * is * is, sign * kN * in.a * 0.2 * d3 * is};
    }
    const double m2 = pressure_second_moment(pressure_);
    return {kN * (1.0 - 0.5 * m2 * d3 * is * is), kN * 0.5 * m2 * d4 * is * is, sign * kN * in.a * m2 * d3 * is};
  }

  const double p = s * spsi;
  const double q = s * cpsi / mu;
  const double rho2 = p * p + q * q;
  Result r;
  if (pressure_ == Pressure::uniform) {
    if (mu >= kSlenderAxisRatio && rho2 < kInsideMaxRho * kInsideMaxRho) {
      r = uniform_inside(mu, p, q);
    } else {
      bool done = false;
      // rho itself above 1: rho^2 up to one ulp above 1 has sqrt 1, the ICR on the rim, where the
      // window's branch points reach its ends (NaN); the rim integrals take it.
      const double rho = std::sqrt(rho2);
      const bool window = mu >= kSlenderAxisRatio && rho > 1.0;
      if (window) r = uniform_window(mu, p, q, rho, s, done);
      if (!done) {
        if (window) {
          r = uniform_window_graded(mu, p, q, rho, s);
        } else if (mu < kRimFoldedMaxAxisRatio) {
          r = uniform_rim_folded(mu, p, s * cpsi);
        } else {
          r = uniform_rim(mu, p, mu * q);
        }
      }
    }
  } else if (pressure_ == Pressure::punch) {
    r = icr_reduction<true>(mu, e2, p, q, rho2, s);
  } else {
    r = icr_reduction<false>(mu, e2, p, q, rho2, s);
  }
  // An ICR on an axis of the ellipse (psi = 0 or pi/2, or any circle): the patch's mirror
  // symmetry about that axis makes the other component of G' vanish; the quadrature would leave
  // round-off there, so it is set exactly.
  if (p == 0.0) r.g1 = 0.0;
  if (q == 0.0) r.g2 = 0.0;
  const double gx = cpsi * r.g1 - spsi * r.g2;
  const double gy = spsi * r.g1 + cpsi * r.g2;
  return {-kN * gy, kN * gx, sign * kN * in.a * r.h};
}

}  // namespace frictionlab::friction
