#include "dynamics/shapes/polynomial.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_poly.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <stdexcept>

#include "friction/gsl_error_policy.h"

namespace frictionlab::dynamics {

Polynomial::Polynomial(std::vector<double> ascending) : c_(std::move(ascending)) {
  while (!c_.empty() && c_.back() == 0.0) c_.pop_back();
}

double Polynomial::operator()(double x) const {
  double p = 0.0;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) p = p * x + *it;
  return p;
}

PolynomialJet Polynomial::jet(double x) const {
  // Horner for p, p', p''/2 together.
  double p = 0.0, d1 = 0.0, d2 = 0.0;
  for (auto it = c_.rbegin(); it != c_.rend(); ++it) {
    d2 = d2 * x + d1;
    d1 = d1 * x + p;
    p = p * x + *it;
  }
  return {p, d1, 2.0 * d2};
}

Polynomial Polynomial::derivative() const {
  if (c_.size() <= 1) return Polynomial{};
  std::vector<double> d(c_.size() - 1);
  for (std::size_t i = 1; i < c_.size(); ++i) d[i - 1] = static_cast<double>(i) * c_[i];
  return Polynomial(std::move(d));
}

Polynomial Polynomial::antiderivative() const {
  std::vector<double> a(c_.size() + 1, 0.0);
  for (std::size_t i = 0; i < c_.size(); ++i) a[i + 1] = c_[i] / static_cast<double>(i + 1);
  return Polynomial(std::move(a));
}

Polynomial operator*(const Polynomial& p, const Polynomial& q) {
  if (p.c_.empty() || q.c_.empty()) return Polynomial{};
  std::vector<double> r(p.c_.size() + q.c_.size() - 1, 0.0);
  for (std::size_t i = 0; i < p.c_.size(); ++i)
    for (std::size_t j = 0; j < q.c_.size(); ++j) r[i + j] += p.c_[i] * q.c_[j];
  return Polynomial(std::move(r));
}

Polynomial operator+(const Polynomial& p, const Polynomial& q) {
  std::vector<double> r(std::max(p.c_.size(), q.c_.size()), 0.0);
  for (std::size_t i = 0; i < p.c_.size(); ++i) r[i] += p.c_[i];
  for (std::size_t i = 0; i < q.c_.size(); ++i) r[i] += q.c_[i];
  return Polynomial(std::move(r));
}

Polynomial operator*(double s, const Polynomial& p) {
  std::vector<double> r = p.c_;
  for (double& c : r) c *= s;
  return Polynomial(std::move(r));
}

std::vector<double> real_roots(const Polynomial& p, double imag_tol) {
  const int n = p.degree();
  if (n < 1) throw std::invalid_argument("real_roots: the polynomial must have degree >= 1");
  std::vector<double> roots;
  if (n == 1) {
    roots.push_back(-p.coefficients()[0] / p.coefficients()[1]);
    return roots;
  }
  std::vector<double> z(2 * static_cast<std::size_t>(n));
  gsl_poly_complex_workspace* w = gsl_poly_complex_workspace_alloc(static_cast<std::size_t>(n) + 1);
  use_gsl_status_codes();
  const int status = gsl_poly_complex_solve(p.coefficients().data(), static_cast<std::size_t>(n) + 1, w,
                                            z.data());
  gsl_poly_complex_workspace_free(w);
  if (status != GSL_SUCCESS) throw std::runtime_error("real_roots: GSL root finder did not converge");
  const Polynomial dp = p.derivative();
  for (int i = 0; i < n; ++i) {
    double re = z[2 * static_cast<std::size_t>(i)];
    const double im = z[2 * static_cast<std::size_t>(i) + 1];
    if (std::abs(im) > imag_tol * std::max(1.0, std::abs(re))) continue;
    // Polish: a few Newton steps, kept only while they reduce |p|.
    for (int it = 0; it < 8; ++it) {
      const double d = dp(re);
      if (d == 0.0) break;
      const double next = re - p(re) / d;
      if (!(std::abs(p(next)) < std::abs(p(re)))) break;
      re = next;
    }
    roots.push_back(re);
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

}  // namespace frictionlab::dynamics
