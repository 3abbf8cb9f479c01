#include "friction/uniform_bspline.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace frictionlab::friction {
namespace {

// The rows of the system in equation order: the left end conditions, the interpolation rows of
// nodes 0..n-1, the right end conditions (so that the matrix is banded). Columns are the shifted
// coefficients 0..m-1.
std::vector<double> system_matrix(int degree, int n, SplineEnd left, SplineEnd right) {
  const int m = n + degree - 1;
  std::vector<double> a(static_cast<std::size_t>(m) * m, 0.0);
  const auto at = [&](int r, int c) -> double& { return a[static_cast<std::size_t>(r) * m + c]; };
  int r = 0;
  if (degree == 3) {
    // f'(0) = 0: c_1 - c_{-1} = 0; not-a-knot: 4th difference about node 1.
    if (left == SplineEnd::zero_slope) {
      at(r, 0) = -1.0;
      at(r, 2) = 1.0;
    } else {
      const double d4[] = {-1.0, 4.0, -6.0, 4.0, -1.0};
      for (int j = 0; j < 5; ++j) at(r, j) = d4[j];
    }
    ++r;
    for (int i = 0; i < n; ++i, ++r) {
      at(r, i) = 1.0 / 6.0;
      at(r, i + 1) = 4.0 / 6.0;
      at(r, i + 2) = 1.0 / 6.0;
    }
    if (right == SplineEnd::zero_slope) {
      at(r, n - 1) = -1.0;
      at(r, n + 1) = 1.0;
    } else {
      const double d4[] = {-1.0, 4.0, -6.0, 4.0, -1.0};
      for (int j = 0; j < 5; ++j) at(r, n - 3 + j) = d4[j];
    }
    ++r;
  } else {
    // Not-a-knot: the 6th difference about nodes 1, 2 and n - 3, n - 2.
    const double d6[] = {1.0, -6.0, 15.0, -20.0, 15.0, -6.0, 1.0};
    for (const int first : {0, 1}) {
      for (int j = 0; j < 7; ++j) at(r, first + j) = d6[j];
      ++r;
    }
    const double row[] = {1.0, 26.0, 66.0, 26.0, 1.0};
    for (int i = 0; i < n; ++i, ++r) {
      for (int j = 0; j < 5; ++j) at(r, i + j) = row[j] / 120.0;
    }
    for (const int first : {n - 4, n - 3}) {
      for (int j = 0; j < 7; ++j) at(r, first + j) = d6[j];
      ++r;
    }
  }
  assert(r == m);
  return a;
}

}  // namespace

UniformSplineInterpolation::UniformSplineInterpolation(int degree, int nodes, SplineEnd left, SplineEnd right)
    : n_(nodes), m_(nodes + degree - 1), conditions_left_((degree - 1) / 2) {
  if (degree != 3 && degree != 5) {
    throw std::invalid_argument("uniform spline degree = " + std::to_string(degree) + ": use 3 or 5");
  }
  if (degree == 5 && (left != SplineEnd::not_a_knot || right != SplineEnd::not_a_knot)) {
    throw std::invalid_argument("a quintic uniform spline takes not-a-knot ends only");
  }
  if (nodes < degree + 3) {
    throw std::invalid_argument("uniform spline nodes = " + std::to_string(nodes) + ": its end conditions need at least " +
                                std::to_string(degree + 3));
  }
  const int m = m_;
  lu_ = system_matrix(degree, nodes, left, right);
  const auto a = [&](int r, int c) -> double& { return lu_[static_cast<std::size_t>(r) * m + c]; };
  row_.resize(m);
  for (int r = 0; r < m; ++r) row_[r] = r;
  // Gaussian elimination with partial pivoting (P A = L U). The system is well conditioned (the
  // interpolation rows are diagonally dominant); the pivoting is for the end-condition rows.
  for (int k = 0; k < m; ++k) {
    int p = k;
    for (int r = k + 1; r < m; ++r) {
      if (std::abs(a(r, k)) > std::abs(a(p, k))) p = r;
    }
    if (a(p, k) == 0.0) throw std::logic_error("uniform spline interpolation system is singular");
    if (p != k) {
      for (int c = 0; c < m; ++c) std::swap(a(p, c), a(k, c));
      std::swap(row_[p], row_[k]);
    }
    for (int r = k + 1; r < m; ++r) {
      if (a(r, k) == 0.0) continue;
      const double l = a(r, k) / a(k, k);
      a(r, k) = l;
      for (int c = k + 1; c < m; ++c) a(r, c) -= l * a(k, c);
    }
  }
  // The factors stay banded: record each row's extent, so that applying them costs O(m band).
  first_l_.resize(m);
  last_u_.resize(m);
  for (int r = 0; r < m; ++r) {
    int f = r;
    for (int c = 0; c < r; ++c) {
      if (a(r, c) != 0.0) {
        f = c;
        break;
      }
    }
    first_l_[r] = f;
    int l = r;
    for (int c = m - 1; c > r; --c) {
      if (a(r, c) != 0.0) {
        l = c;
        break;
      }
    }
    last_u_[r] = l;
  }
}

void UniformSplineInterpolation::solve(const std::vector<double>& values, std::size_t outer, std::size_t inner,
                                       std::vector<double>& coefficients) const {
  const std::size_t n = static_cast<std::size_t>(n_);
  const std::size_t m = static_cast<std::size_t>(m_);
  if (values.size() != outer * n * inner) {
    throw std::invalid_argument("uniform spline interpolation: " + std::to_string(values.size()) +
                                " values for " + std::to_string(outer) + " x " + std::to_string(n) + " x " +
                                std::to_string(inner));
  }
  if (&coefficients == &values) throw std::invalid_argument("uniform spline interpolation cannot solve in place");
  coefficients.resize(outer * m * inner);
  double* const out = coefficients.data();
  // One block of `inner` lines at a time, each row of the system a row of `inner` values.
  for (std::size_t o = 0; o < outer; ++o) {
    double* w = out + o * m * inner;
    const double* v = values.data() + o * n * inner;
    for (std::size_t r = 0; r < m; ++r) {
      // Equation row_[r]: an end condition (right-hand side 0) or the interpolation row of a node.
      const int node = row_[r] - conditions_left_;
      double* wr = w + r * inner;
      if (node >= 0 && node < n_) {
        std::copy(v + static_cast<std::size_t>(node) * inner, v + static_cast<std::size_t>(node + 1) * inner, wr);
      } else {
        std::fill(wr, wr + inner, 0.0);
      }
    }
    for (std::size_t r = 1; r < m; ++r) {  // L y = P b
      double* wr = w + r * inner;
      for (std::size_t c = static_cast<std::size_t>(first_l_[r]); c < r; ++c) {
        const double l = lu_[r * m + c];
        if (l == 0.0) continue;
        const double* wc = w + c * inner;
        for (std::size_t q = 0; q < inner; ++q) wr[q] -= l * wc[q];
      }
    }
    for (std::size_t r = m; r-- > 0;) {  // U x = y
      double* wr = w + r * inner;
      for (std::size_t c = r + 1; c <= static_cast<std::size_t>(last_u_[r]); ++c) {
        const double u = lu_[r * m + c];
        if (u == 0.0) continue;
        const double* wc = w + c * inner;
        for (std::size_t q = 0; q < inner; ++q) wr[q] -= u * wc[q];
      }
      const double d = 1.0 / lu_[r * m + r];
      for (std::size_t q = 0; q < inner; ++q) wr[q] *= d;
    }
  }
}

}  // namespace frictionlab::friction
