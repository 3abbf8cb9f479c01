#pragma once
// Uniform B-splines with their knots at the nodes, cubic and quintic, as the table design of
// docs/exact-table.md uses them on each axis of a tensor-product table: n nodes x_i = i/(n - 1) on
// [0, 1], n + 2 (cubic) or n + 4 (quintic) coefficients, stored shifted so that coefficient j is
// c_{j-1} (cubic) or c_{j-2} (quintic).
//
//   * Evaluation (hot path, inline): the cell of x in O(1), no search, and the degree + 1 basis
//     weights of that cell by Horner; the spline is sum_j w_j c_{index + j}.
//   * Interpolation (once, at table build): node values and end conditions -> coefficients, one
//     small linear system per axis, factored once and applied to every line of the table.
//
// Rows of the interpolation systems (docs/exact-table.md "Node layout and scheme"):
//   cubic    (c_{i-1} + 4 c_i + c_{i+1}) / 6 = f_i;
//   quintic  (c_{i-2} + 26 c_{i-1} + 66 c_i + 26 c_{i+1} + c_{i+2}) / 120 = f_i;
// end conditions, one per end (cubic) or two per end (quintic):
//   zero slope   f' = 0 at the end node (cubic: c_{-1} = c_1, c_{n-2} = c_n);
//   not-a-knot   the highest derivative continuous at the second (and, quintic, third) node from
//                the end: the 4th difference (cubic) or 6th difference (quintic) of the
//                coefficients about that node is zero.

#include <cstddef>
#include <vector>

namespace frictionlab::friction {

/// Where x lies on a uniform axis: coefficients index .. index + degree carry it, tau in [0, 1]
/// is its place in the cell.
struct UniformCell {
  int index;
  double tau;
};

/// The cell of x in [0, 1] on an axis of n nodes, with scale = n - 1 and last = n - 2: index =
/// min(floor(x (n - 1)), n - 2) (x = 1 is the end of the last cell, not a cell of its own).
[[nodiscard]] inline UniformCell uniform_cell(double x, double scale, int last) {
  const double u = x * scale;
  int i = static_cast<int>(u);  // x >= 0: truncation is floor
  if (i > last) i = last;
  return {i, u - i};
}

/// The 4 cubic B-spline weights of a cell at tau in [0, 1].
inline void cubic_weights(double tau, double w[4]) {
  const double t = tau;
  const double r = 1.0 - t;
  constexpr double k = 1.0 / 6.0;
  w[0] = k * r * r * r;
  w[1] = k * (4.0 + t * t * (3.0 * t - 6.0));
  w[2] = k * (1.0 + t * (3.0 + t * (3.0 - 3.0 * t)));
  w[3] = k * t * t * t;
}

/// The 6 quintic B-spline weights of a cell at tau in [0, 1]: the cardinal B-spline
/// N5(tau + 5 - j), j = 0..5, by Horner.
inline void quintic_weights(double tau, double w[6]) {
  const double t = tau;
  const double r = 1.0 - t;
  const double t2 = t * t;
  const double r2 = r * r;
  constexpr double k = 1.0 / 120.0;
  w[0] = k * r2 * r2 * r;
  w[1] = k * (26.0 + t * (-50.0 + t * (20.0 + t * (20.0 + t * (-20.0 + t * 5.0)))));
  w[2] = k * (66.0 + t2 * (-60.0 + t2 * (30.0 - 10.0 * t)));
  w[3] = k * (26.0 + t * (50.0 + t * (20.0 + t * (-20.0 + t * (-20.0 + t * 10.0)))));
  w[4] = k * (1.0 + t * (5.0 + t * (10.0 + t * (10.0 + t * (5.0 - 5.0 * t)))));
  w[5] = k * t2 * t2 * t;
}

/// An end condition of an interpolating spline.
enum class SplineEnd { zero_slope, not_a_knot };

/// The interpolation system of a uniform B-spline on `nodes` nodes: degree 3 with either end
/// condition at each end, or degree 5 with not-a-knot at both (the only quintic the table uses;
/// anything else is std::invalid_argument). Factored once (LU with partial pivoting; the matrix is
/// banded and small), then applied to any number of lines.
class UniformSplineInterpolation {
 public:
  UniformSplineInterpolation(int degree, int nodes, SplineEnd left, SplineEnd right);

  [[nodiscard]] int nodes() const { return n_; }
  [[nodiscard]] int coefficients() const { return m_; }

  /// `values` is an array [outer][nodes][inner] (row-major) of node values along this axis;
  /// `coefficients` becomes the array [outer][coefficients()][inner] of the splines through them
  /// (resized: a vector with the capacity already is reused, not reallocated).
  void solve(const std::vector<double>& values, std::size_t outer, std::size_t inner,
             std::vector<double>& coefficients) const;

 private:
  int n_;
  int m_;
  int conditions_left_;         // equations before the interpolation rows
  std::vector<double> lu_;      // m x m: L below the diagonal (unit diagonal), U on and above
  std::vector<int> row_;        // row_[r]: the equation in row r after pivoting
  std::vector<int> first_l_;    // first nonzero column of L in each row
  std::vector<int> last_u_;     // last nonzero column of U in each row
};

}  // namespace frictionlab::friction
