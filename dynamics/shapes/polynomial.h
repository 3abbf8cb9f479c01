#pragma once
// A real polynomial in one variable, coefficients in ascending powers: p(x) = c0 + c1 x + c2 x^2 ...
// Used for the body profile chi(xi3)^2 (dynamics/shapes/profile.h) and the expressions built from it.

#include <cstddef>
#include <vector>

namespace frictionlab::dynamics {

/// p, p' and p'' at one point.
struct PolynomialJet {
  double value = 0.0;
  double d1 = 0.0;
  double d2 = 0.0;
};

class Polynomial {
 public:
  Polynomial() = default;
  /// Ascending coefficients; trailing zeros are dropped (the zero polynomial has no coefficients).
  explicit Polynomial(std::vector<double> ascending);

  [[nodiscard]] const std::vector<double>& coefficients() const { return c_; }
  /// Degree; -1 for the zero polynomial.
  [[nodiscard]] int degree() const { return static_cast<int>(c_.size()) - 1; }

  /// p(x) by Horner's rule. No allocation.
  [[nodiscard]] double operator()(double x) const;
  /// p(x), p'(x), p''(x) in one Horner pass. No allocation.
  [[nodiscard]] PolynomialJet jet(double x) const;

  [[nodiscard]] Polynomial derivative() const;
  /// The antiderivative vanishing at 0.
  [[nodiscard]] Polynomial antiderivative() const;

  friend Polynomial operator*(const Polynomial& p, const Polynomial& q);
  friend Polynomial operator+(const Polynomial& p, const Polynomial& q);
  friend Polynomial operator*(double s, const Polynomial& p);

 private:
  std::vector<double> c_;
};

/// The real roots of p, ascending, each polished by Newton's method. Complex roots whose imaginary
/// part is below `imag_tol` (relative to max(1, |root|)) count as real. Uses GSL's companion-matrix
/// solver; p must have degree >= 1.
[[nodiscard]] std::vector<double> real_roots(const Polynomial& p, double imag_tol = 1e-7);

}  // namespace frictionlab::dynamics
