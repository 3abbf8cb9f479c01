#pragma once
// The table of `exact-table` (friction/exact_table_law.h) for one pressure model: tensor-product
// B-spline coefficients of the exact law's forces and moment, built from ExactLaw in this process,
// and their evaluation at one instantaneous centre of rotation (ICR). The design (coordinates,
// node layout, spline scheme, end conditions, storage) is the table design of
// docs/exact-table.md; the section names below are that document's.
//
// Dimensionless (a = N = k = 1, Omega > 0): the ICR in the patch axes (x along the major axis) is
// (Xt, Yt) = s (sin psi, cos psi), s = U/(a|Omega|); the axis ratio is mu = b/a in [0.01, 1]. The
// table stores three functions u, v, m, even in Xt and in Yt, smooth on each of two blocks:
//
//   G = (Gx, Gy) = (fx u, fy v)   the patch-frame force per kN: F1 = -(Gx sin psi + Gy cos psi),
//                                 F2 = Gx cos psi - Gy sin psi;
//   m = M / M0                    the moment as a fraction of the pure-spin moment
//                                 M0 = c_p E(e) (c_p = pressure_pure_spin_factor, e^2 = 1 - mu^2).
//
// Blocks and coordinates ("Coordinates"), each mapped to [0, 1]^3 = (xi, zeta, t):
//   * inside, r2 = Xt^2 + (Yt/mu)^2 <= 1: rho = sqrt(r2), xi = 1 - sqrt(1 - rho),
//     zeta = |Yt/mu|/rho, fx = Xt, fy = Yt/mu;
//   * outside: B, A the semi-axes of the ellipse confocal with the patch through the ICR (foci
//     +-sqrt(1 - mu^2)), sigma = ln(B/mu) (0 on the rim), xi = sqrt(sigma/(sigma + s0)),
//     s0 = 2 + ln(1/mu) (xi = 1 is s = inf), zeta = |Yt|/B, fx = Xt/A, fy = Yt/B;
//   * both: t = (mu^(1/4) - 1)/(0.01^(1/4) - 1).
// Splines ("Node layout and scheme"): uniform nodes, knots at the nodes; cubic in xi (48 nodes
// inside, 192 outside) and zeta (32), quintic in t (25). End conditions: zero slope at both xi
// ends (the centre, the rim from either side, and s = inf) and at zeta = 0, not-a-knot at
// zeta = 1 and at both t ends. The two blocks take the same data on the rim, so they agree there
// to rounding.
// Storage ("Storage"): [t][xi][zeta][u, v, m] doubles, 29 x 50 x 34 x 3 inside and
// 29 x 194 x 34 x 3 outside, 5,774,016 bytes per pressure.

#include <cstddef>
#include <vector>

#include "friction/pressure.h"
#include "friction/uniform_bspline.h"

namespace frictionlab::friction {

/// The smallest axis ratio b/a the table covers (its t axis ends there).
inline constexpr double kExactTableMinAxisRatio = 0.01;

/// The table at one ICR: the patch-frame force per kN and the moment per pure-spin moment.
struct ExactTableValue {
  double gx;  ///< G along the major axis, per kN
  double gy;  ///< G along the minor axis, per kN
  double m;   ///< M / M0, M0 = pure_spin_moment()
};

/// Where ExactTable::at reads the table for one ICR (steps 5-7 of docs/exact-table.md): the cell's
/// first coefficient row, its place in the cell on each axis, and the factors (fx, fy) of G. The
/// split lets a batch locate many ICRs before it sums any (friction/exact_table_batch.h).
struct ExactTableCell {
  const double* corner;   ///< coefficient [t][xi][zeta][0] of the cell's first node on each axis
  std::size_t t_stride;   ///< doubles between t planes of the cell's block
  double tau_t, tau_x, tau_z;  ///< place in the cell, in [0, 1], along t, xi, zeta
  double fx, fy;          ///< Gx = fx u, Gy = fy v
};

/// The B-spline weights of a cell's place: quintic along t, cubic along xi and zeta
/// (friction/uniform_bspline.h), as ExactTable::contract takes them.
inline void exact_table_weights(const ExactTableCell& cell, double wt[6], double wx[4], double wz[4]) {
  quintic_weights(cell.tau_t, wt);
  cubic_weights(cell.tau_x, wx);
  cubic_weights(cell.tau_z, wz);
}

/// The B-spline table of the exact law for one pressure model. Immutable once built; safe to read
/// concurrently.
class ExactTable {
 public:
  // The node layout of docs/exact-table.md.
  static constexpr int kInsideRadialNodes = 48;
  static constexpr int kOutsideRadialNodes = 192;  ///< the last at s = inf
  static constexpr int kAngularNodes = 32;
  static constexpr int kAxisRatioNodes = 25;

  /// Builds the table of `pressure` from ExactLaw (friction/exact_law.h): one evaluation of it per
  /// node, a few more on the rows where fx or fy vanishes (about 0.22 M in all), then one banded
  /// solve per axis. About 0.1 to 0.3 s (friction/exact_table_law.h gives the measured times).
  explicit ExactTable(Pressure pressure);

  /// The table of `pressure`, built at the first call for that pressure and then shared for the
  /// life of the process; thread-safe (a function-local static per pressure).
  [[nodiscard]] static const ExactTable& of(Pressure pressure);

  [[nodiscard]] Pressure pressure() const { return pressure_; }

  /// M0 / (kNa) = c_p E(e), e^2 = 1 - mu^2, for mu in [0.01, 1], ln_mu = ln(mu): the pure-spin
  /// moment (friction/elliptic_e_fit.h, relative error below 1.3e-14).
  [[nodiscard]] double pure_spin_moment(double mu, double ln_mu) const;

  /// (Gx, Gy, m) at the ICR (Xt, Yt) (patch axes, units of a; finite, |Xt|, |Yt| <= 1e8) for
  /// mu in [0.01, 1], ln_mu = ln(mu). No allocation. It is contract(locate(...), weights of the
  /// cell's taus by quintic_weights and cubic_weights, friction/uniform_bspline.h).
  [[nodiscard]] ExactTableValue at(double Xt, double Yt, double mu, double ln_mu) const;

  /// Steps 5-7 of at(): the cell of the ICR (Xt, Yt) at axis ratio mu, ln_mu = ln(mu).
  [[nodiscard]] ExactTableCell locate(double Xt, double Yt, double mu, double ln_mu) const;
  /// Step 8 of at(): the tensor sum of the cell's 6 x 4 x 4 coefficients with the quintic weights
  /// `wt` (t) and the cubic weights `wx` (xi), `wz` (zeta) of its taus, times (fx, fy).
  [[nodiscard]] static ExactTableValue contract(const ExactTableCell& cell, const double wt[6], const double wx[4],
                                                const double wz[4]);
  /// True if the processor has AVX, for contract_pair_wide() (checked once).
  [[nodiscard]] static bool has_wide_sum();
  /// contract() of two cells with the weights of their taus, the same values bit for bit, both
  /// sums at once in 4-lane AVX vectors; only where has_wide_sum() (two contract()s elsewhere than
  /// on x86). The batch uses it (friction/exact_table_batch.h); a single contact keeps contract(),
  /// SSE2 on any x86-64.
  static void contract_pair_wide(const ExactTableCell& first, const ExactTableCell& second,
                                 ExactTableValue& first_value, ExactTableValue& second_value);

  /// Bytes of coefficients (5,774,016).
  [[nodiscard]] std::size_t bytes() const { return (inside_.size() + outside_.size()) * sizeof(double); }
  /// How many times the build evaluated ExactLaw.
  [[nodiscard]] long exact_evaluations() const { return exact_evaluations_; }

 private:
  Pressure pressure_;
  double pure_spin_factor_;
  double t_scale_;  // (n - 1)/(0.01^(1/4) - 1): t (n - 1) = (mu^(1/4) - 1) t_scale_
  long exact_evaluations_ = 0;
  std::vector<double> inside_;   // [t][xi][zeta][3]
  std::vector<double> outside_;  // [t][xi][zeta][3]
};

}  // namespace frictionlab::friction
