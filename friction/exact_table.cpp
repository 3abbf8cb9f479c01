#include "friction/exact_table.h"

// The table design of docs/exact-table.md: the build (node values from ExactLaw, then the spline
// coefficients) and the evaluation share the coordinate maps below, so that a node is evaluated at
// the very ICR it was built from.

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "friction/elliptic_e_fit.h"
#include "friction/exact_law.h"
#include "friction/law.h"
#include "friction/support/number_format.h"
#include "friction/uniform_bspline.h"

namespace frictionlab::friction {
namespace {

constexpr int kNx[2] = {ExactTable::kInsideRadialNodes, ExactTable::kOutsideRadialNodes};
constexpr int kNz = ExactTable::kAngularNodes;
constexpr int kNt = ExactTable::kAxisRatioNodes;
// Coefficients per axis: n + 2 (cubic), n + 4 (quintic).
constexpr int kCz = kNz + 2;
constexpr int kCt = kNt + 4;
constexpr std::size_t kOutputs = 3;  // u, v, m, interleaved innermost
constexpr std::size_t kZStride = kOutputs;
constexpr std::size_t kXStride = kCz * kZStride;
constexpr std::size_t t_stride_of(int block) { return static_cast<std::size_t>(kNx[block] + 2) * kXStride; }

// The t axis: t = (mu^(1/4) - 1) / (0.01^(1/4) - 1).
double quarter_root_min() { return std::sqrt(std::sqrt(kExactTableMinAxisRatio)); }

// Outside radial map: xi = sqrt(sigma / (sigma + s0)), s0 = 2 + ln(1/mu).
constexpr double kOutsideMapOffset = 2.0;
// Nodes beyond this sigma (s > e^150 mu, inf at xi = 1) take it: far beyond any s the table is
// asked for (the law answers s > 1e8 by the fast-slip expansion).
constexpr double kMaxNodeSigma = 150.0;
// Rows where fx or fy is below this (the axes zeta = 0, 1 and the centre rho = 0): u = Gx/fx (or
// v) is taken as u0 + a2 c^2 through the values at c = d and 2d (even in c; Richardson), error
// O(d^4) ~ 1e-11 times the fourth derivative.
constexpr double kRichardsonStep = 2e-3;

// ---------------------------------------------------------------------------------------------
// Build

// The patch-frame force and the moment of ExactLaw at the ICR (Xt, Yt), a = N = k = 1, Omega = 1.
struct PatchSample {
  double gx, gy, M;
};

PatchSample patch_sample(const ExactLaw& law, double Xt, double Yt, double mu, long& calls) {
  const double s = std::hypot(Xt, Yt);
  // (cos psi, sin psi) = (Yt, Xt)/s; the pure-spin point s = 0 has no direction (any will do).
  const double c = s > 0.0 ? Yt / s : 1.0;
  const double sn = s > 0.0 ? Xt / s : 0.0;
  ContactInput in;
  in.U = s;
  in.Omega = 1.0;
  in.a = 1.0;
  in.b = mu;
  in.psi = PatchAngle::from_direction(c, sn);
  in.N = 1.0;
  in.k = 1.0;
  const FrictionForces f = law.evaluate(in);
  ++calls;
  if (!std::isfinite(f.F1) || !std::isfinite(f.F2) || !std::isfinite(f.M)) {
    throw std::logic_error("exact-table: exact gave a non-finite value at s = " + support::shortest(s) +
                           ", b/a = " + support::shortest(mu) + ": the table cannot be built");
  }
  // (px, py) = F1 e1 + F2 e2 in the patch axes; the table's G = (py, -px) is the pressure-weighted
  // mean of (r - c)/|r - c| over the patch, c the ICR (docs/exact-table.md "Coordinates").
  const double px = f.F1 * c + f.F2 * sn;
  const double py = -f.F1 * sn + f.F2 * c;
  return {py, -px, f.M};
}

struct NodeValues {
  double u, v, M;
};

// u = Gx/cx, v = Gy/cy and M at the ICR (sx cx, sy cy): fx = cx, fy = cy.
NodeValues node_values(const ExactLaw& law, double cx, double cy, double sx, double sy, double mu, long& calls) {
  constexpr double d = kRichardsonStep;
  const PatchSample g = patch_sample(law, sx * cx, sy * cy, mu, calls);
  NodeValues out{cx >= d ? g.gx / cx : 0.0, cy >= d ? g.gy / cy : 0.0, g.M};
  if (cx < d) {
    const double u1 = patch_sample(law, sx * d, sy * cy, mu, calls).gx / d;
    const double u2 = patch_sample(law, sx * 2.0 * d, sy * cy, mu, calls).gx / (2.0 * d);
    const double a2 = (u2 - u1) / (3.0 * d * d);
    out.u = u1 + a2 * (cx * cx - d * d);
  }
  if (cy < d) {
    const double v1 = patch_sample(law, sx * cx, sy * d, mu, calls).gy / d;
    const double v2 = patch_sample(law, sx * cx, sy * 2.0 * d, mu, calls).gy / (2.0 * d);
    const double a2 = (v2 - v1) / (3.0 * d * d);
    out.v = v1 + a2 * (cy * cy - d * d);
  }
  return out;
}

double node(int i, int n) { return static_cast<double>(i) / (n - 1); }

// mu at the t node j: the inverse of t(mu).
double axis_ratio_at_node(int j) {
  const double q = 1.0 + node(j, kNt) * (quarter_root_min() - 1.0);
  return (q * q) * (q * q);
}

// The node values [t][xi][zeta][u, v, m] of one block (0 inside, 1 outside), into `values`.
void block_values(const ExactLaw& law, double pure_spin_factor, int block, long& calls, std::vector<double>& values) {
  const int nx = kNx[block];
  values.resize(static_cast<std::size_t>(kNt) * nx * kNz * kOutputs);
  double* out = values.data();
  for (int j = 0; j < kNt; ++j) {
    const double mu = axis_ratio_at_node(j);
    const double M0 = pure_spin_factor * elliptic_e_fit(mu * mu, std::log(mu));
    const double f2 = (1.0 - mu) * (1.0 + mu);
    const double s0 = kOutsideMapOffset - std::log(mu);
    for (int i = 0; i < nx; ++i) {
      const double xi = node(i, nx);
      for (int k = 0; k < kNz; ++k, out += kOutputs) {
        const double zeta = node(k, kNz);
        const double across = std::sqrt((1.0 - zeta) * (1.0 + zeta));
        NodeValues nv;
        if (block == 0) {
          // Inside: rho = 1 - (1 - xi)^2, (fx, fy) = rho (sqrt(1 - zeta^2), zeta) = (Xt, Yt/mu).
          const double rho = 1.0 - (1.0 - xi) * (1.0 - xi);
          nv = node_values(law, rho * across, rho * zeta, 1.0, mu, mu, calls);
          if (i == 0) nv.M = M0;  // the centre is pure spin: m = 1 exactly
        } else if (i == nx - 1) {
          nv = {-1.0, -1.0, 0.0};  // s = inf: F1 = kN, F2 = M = 0
        } else {
          // Outside: the confocal ellipse with B = mu e^sigma, (fx, fy) = (sqrt(1 - zeta^2), zeta)
          // = (Xt/A, Yt/B).
          const double x2 = xi * xi;
          const double B = mu * std::exp(std::min(s0 * x2 / (1.0 - x2), kMaxNodeSigma));
          const double A = std::sqrt(B * B + f2);
          nv = node_values(law, across, zeta, A, B, mu, calls);
        }
        out[0] = nv.u;
        out[1] = nv.v;
        out[2] = nv.M / M0;
      }
    }
  }
}

// The coefficients of one block: its node values, then interpolated along one axis at a time (xi,
// zeta, t); [t][xi][zeta][3] throughout. `work` is scratch, reused from block to block: fresh pages
// cost more than the solves (each is faulted in on first touch).
std::vector<double> block_coefficients(const ExactLaw& law, double pure_spin_factor, int block, long& calls,
                                       std::vector<double>& work) {
  const int nx = kNx[block];
  const UniformSplineInterpolation along_xi(3, nx, SplineEnd::zero_slope, SplineEnd::zero_slope);
  const UniformSplineInterpolation along_zeta(3, kNz, SplineEnd::zero_slope, SplineEnd::not_a_knot);
  const UniformSplineInterpolation along_t(5, kNt, SplineEnd::not_a_knot, SplineEnd::not_a_knot);
  std::vector<double> coefficients;
  coefficients.reserve(static_cast<std::size_t>(kCt) * (nx + 2) * kCz * kOutputs);
  block_values(law, pure_spin_factor, block, calls, work);
  along_xi.solve(work, kNt, kNz * kOutputs, coefficients);
  along_zeta.solve(coefficients, static_cast<std::size_t>(kNt) * (nx + 2), kOutputs, work);
  along_t.solve(work, 1, static_cast<std::size_t>(nx + 2) * kCz * kOutputs, coefficients);
  return coefficients;
}

// ---------------------------------------------------------------------------------------------
// Evaluation

// sum_{a,b,c} wt[a] wx[b] wz[c] C[t + a][x + b][z + c][0..2]: 6 x 4 rows of 4 x 3 contiguous
// coefficients (u, v, m of four zeta nodes), weighted and summed as six 2-lane vectors (the
// GCC/Clang vector extension: SSE2 on x86-64, NEON on arm64; each lane rounds as the scalar sum
// would), then contracted with the zeta weights.
using Lanes = double __attribute__((vector_size(16)));

ExactTableValue tensor_sum(const double* c, std::size_t t_stride, const double wt[6], const double wx[4],
                           const double wz[4]) {
  Lanes acc[6] = {};
  for (int a = 0; a < 6; ++a) {
    const double* plane = c + a * t_stride;
    for (int b = 0; b < 4; ++b) {
      const double w = wt[a] * wx[b];
      const Lanes weight = {w, w};
      const double* row = plane + b * kXStride;
      for (int q = 0; q < 6; ++q) {
        Lanes x;
        std::memcpy(&x, row + 2 * q, sizeof x);  // unaligned
        acc[q] += weight * x;
      }
    }
  }
  // acc lanes: (u0 v0) (m0 u1) (v1 m1) (u2 v2) (m2 u3) (v3 m3), the digit the zeta node.
  ExactTableValue r;
  r.gx = wz[0] * acc[0][0] + wz[1] * acc[1][1] + wz[2] * acc[3][0] + wz[3] * acc[4][1];
  r.gy = wz[0] * acc[0][1] + wz[1] * acc[2][0] + wz[2] * acc[3][1] + wz[3] * acc[5][0];
  r.m = wz[0] * acc[1][0] + wz[1] * acc[2][1] + wz[2] * acc[4][0] + wz[3] * acc[5][1];
  return r;
}

#if defined(__x86_64__) || defined(__i386__)
// The sums of two cells at once, each as three 4-lane vectors (u0 v0 m0 u1) (v1 m1 u2 v2)
// (m2 u3 v3 m3), for processors with AVX, chosen at run time (ExactTable::has_wide_sum). Each lane
// does the very operations of tensor_sum's lane for that output, in the same order (AVX has no
// fused multiply-add, and the library is built with -ffp-contract=off), so the values are the same
// bit for bit. Why two: a sum is a chain of 24 dependent adds per accumulator, so one cell's three
// accumulators leave the adder waiting on latency (as do tensor_sum's six, which SSE2's throughput
// bounds anyway); two independent cells keep six chains in flight.
using WideLanes = double __attribute__((vector_size(32)));

__attribute__((target("avx"))) void tensor_sum_wide_pair(const ExactTableCell* const cells[2],
                                                          const double wt[2][6], const double wx[2][4],
                                                          const double wz[2][4], ExactTableValue out[2]) {
  WideLanes acc[2][3] = {};
  for (int a = 0; a < 6; ++a) {
    for (int b = 0; b < 4; ++b) {
      for (int k = 0; k < 2; ++k) {
        const double w = wt[k][a] * wx[k][b];
        const WideLanes weight = {w, w, w, w};
        const double* row = cells[k]->corner + a * cells[k]->t_stride + b * kXStride;
        for (int q = 0; q < 3; ++q) {
          WideLanes x;
          std::memcpy(&x, row + 4 * q, sizeof x);  // unaligned
          acc[k][q] += weight * x;
        }
      }
    }
  }
  for (int k = 0; k < 2; ++k) {
    const WideLanes* g = acc[k];
    const double* z = wz[k];
    out[k].gx = (z[0] * g[0][0] + z[1] * g[0][3] + z[2] * g[1][2] + z[3] * g[2][1]) * cells[k]->fx;
    out[k].gy = (z[0] * g[0][1] + z[1] * g[1][0] + z[2] * g[1][3] + z[3] * g[2][2]) * cells[k]->fy;
    out[k].m = z[0] * g[0][2] + z[1] * g[1][1] + z[2] * g[2][0] + z[3] * g[2][3];
  }
}
#endif

// Steps 5-7 of docs/exact-table.md (ExactTable::locate), inlined into ExactTable::at too, so that
// at() stays one function, as it was before the batch needed the steps apart: the compiler then
// overlaps the weights and the first loads with the coordinates' chain of square roots (with calls
// between the steps the per-contact path measured 5 to 15 % slower).
[[gnu::always_inline]] inline ExactTableCell locate_cell(const double* inside, const double* outside, double t_scale,
                                                          double Xt, double Yt, double mu, double ln_mu) {
  // docs/exact-table.md "Evaluation, in order", steps 5-7.
  const UniformCell ct = uniform_cell((std::sqrt(std::sqrt(mu)) - 1.0) * t_scale, 1.0, kNt - 2);
  const double Ys = Yt / mu;
  const double r2 = Xt * Xt + Ys * Ys;
  int block = 0;
  double xi = 0.0;
  double zeta = 0.0;
  double fx = 0.0;
  double fy = 0.0;
  if (r2 <= 1.0) {
    const double rho = std::sqrt(r2);
    xi = 1.0 - std::sqrt(1.0 - rho);
    zeta = rho > 0.0 ? std::min(1.0, std::abs(Ys) / rho) : 0.0;
    fx = Xt;
    fy = Ys;
  } else {
    block = 1;
    // The ellipse confocal with the patch through the ICR: B^2 the smaller root of
    // B^2 (B^2 + f2) - (X^2 + Y^2 - f2) B^2 - f2 Y^2 = 0, taken without cancellation.
    const double X2 = Xt * Xt;
    const double Y2 = Yt * Yt;
    const double f2 = (1.0 - mu) * (1.0 + mu);
    const double Sm = X2 + Y2 - f2;
    const double D = std::sqrt(Sm * Sm + 4.0 * f2 * Y2);
    const double B2 = Sm >= 0.0 ? 0.5 * (Sm + D) : 2.0 * f2 * Y2 / (D - Sm);
    const double inv_B = 1.0 / std::sqrt(B2);
    const double sigma = std::max(0.0, 0.5 * std::log(B2) - ln_mu);  // ln(B/mu)
    xi = std::sqrt(sigma / (sigma + (kOutsideMapOffset - ln_mu)));
    zeta = std::min(1.0, std::abs(Yt) * inv_B);
    fx = Xt / std::sqrt(B2 + f2);
    fy = Yt * inv_B;
  }
  const int nx = kNx[block];
  const UniformCell cx = uniform_cell(xi, nx - 1.0, nx - 2);
  const UniformCell cz = uniform_cell(zeta, kNz - 1.0, kNz - 2);
  const std::size_t t_stride = t_stride_of(block);
  const double* c = (block == 0 ? inside : outside) + ct.index * t_stride +
                    static_cast<std::size_t>(cx.index) * kXStride + static_cast<std::size_t>(cz.index) * kZStride;
  return {c, t_stride, ct.tau, cx.tau, cz.tau, fx, fy};
}

// Step 8 of docs/exact-table.md (ExactTable::contract), inlined into ExactTable::at too.
[[gnu::always_inline]] inline ExactTableValue contract_cell(const ExactTableCell& cell, const double wt[6],
                                                            const double wx[4], const double wz[4]) {
  ExactTableValue r = tensor_sum(cell.corner, cell.t_stride, wt, wx, wz);
  r.gx *= cell.fx;
  r.gy *= cell.fy;
  return r;
}

}  // namespace

ExactTable::ExactTable(Pressure pressure)
    : pressure_(pressure),
      pure_spin_factor_(pressure_pure_spin_factor(pressure)),
      t_scale_((kNt - 1) / (quarter_root_min() - 1.0)) {
  const ExactLaw law(pressure);
  std::vector<double> work;
  work.reserve(static_cast<std::size_t>(kNt) * (kNx[1] + 2) * kCz * kOutputs);  // the largest stage
  inside_ = block_coefficients(law, pure_spin_factor_, 0, exact_evaluations_, work);
  outside_ = block_coefficients(law, pure_spin_factor_, 1, exact_evaluations_, work);
}

const ExactTable& ExactTable::of(Pressure pressure) {
  switch (pressure) {
    case Pressure::uniform: {
      static const ExactTable table(Pressure::uniform);
      return table;
    }
    case Pressure::punch: {
      static const ExactTable table(Pressure::punch);
      return table;
    }
    case Pressure::hertz: break;
  }
  static const ExactTable table(Pressure::hertz);
  return table;
}

double ExactTable::pure_spin_moment(double mu, double ln_mu) const {
  return pure_spin_factor_ * elliptic_e_fit(mu * mu, ln_mu);
}

ExactTableValue ExactTable::at(double Xt, double Yt, double mu, double ln_mu) const {
  const ExactTableCell cell = locate_cell(inside_.data(), outside_.data(), t_scale_, Xt, Yt, mu, ln_mu);
  double wt[6];
  double wx[4];
  double wz[4];
  exact_table_weights(cell, wt, wx, wz);
  return contract_cell(cell, wt, wx, wz);
}

ExactTableCell ExactTable::locate(double Xt, double Yt, double mu, double ln_mu) const {
  return locate_cell(inside_.data(), outside_.data(), t_scale_, Xt, Yt, mu, ln_mu);
}

ExactTableValue ExactTable::contract(const ExactTableCell& cell, const double wt[6], const double wx[4],
                                     const double wz[4]) {
  return contract_cell(cell, wt, wx, wz);
}

bool ExactTable::has_wide_sum() {
#if defined(__x86_64__) || defined(__i386__)
  static const bool avx = __builtin_cpu_supports("avx");
  return avx;
#else
  return false;
#endif
}

void ExactTable::contract_pair_wide(const ExactTableCell& first, const ExactTableCell& second,
                                    ExactTableValue& first_value, ExactTableValue& second_value) {
  const ExactTableCell* const cells[2] = {&first, &second};
  double wt[2][6];
  double wx[2][4];
  double wz[2][4];
  for (int k = 0; k < 2; ++k) {
    exact_table_weights(*cells[k], wt[k], wx[k], wz[k]);
  }
#if defined(__x86_64__) || defined(__i386__)
  ExactTableValue values[2];
  tensor_sum_wide_pair(cells, wt, wx, wz, values);
  first_value = values[0];
  second_value = values[1];
#else
  first_value = contract(first, wt[0], wx[0], wz[0]);
  second_value = contract(second, wt[1], wx[1], wz[1]);
#endif
}

}  // namespace frictionlab::friction
