#pragma once
// The complete elliptic integral of the second kind E(e), e^2 = 1 - mu^2, for axis ratios mu in
// [0.01, 1], as a fit that shares the logarithm of mu with the coordinates of `exact-table`
// (the table design of docs/exact-table.md, step 4):
//
//   E = P(m1) - ln(m1) Q(m1),   m1 = mu^2,   ln(m1) = 2 ln(mu),
//
// P of degree 8, Q of degree 8 with Q(0) = 0 (the form of E's expansion about e = 1, whose
// logarithmic term is (m1/4) ln(16/m1) + ...). Coefficients: the least-squares fit of
// friction/tools/fit_elliptic_e.py (regenerate with `/usr/bin/python3
// friction/tools/fit_elliptic_e.py`). Largest relative error on mu in [0.01, 1]: 1.26e-14
// (that script, 200,001 points against scipy.special.ellipe). Outside [0.01, 1] it is not E.

namespace frictionlab::friction {

/// E(sqrt(1 - mu^2)) for mu in [0.01, 1], from m1 = mu^2 and ln_mu = ln(mu): 17 multiply-adds.
[[nodiscard]] inline double elliptic_e_fit(double m1, double ln_mu) {
  // friction/tools/fit_elliptic_e.py, degree 8. P: m1^0..m1^8.
  constexpr double p0 = 1.00000000000000777e+00, p1 = 4.43147181230792719e-01, p2 = 5.68057124381813883e-02,
                   p3 = 2.18795455451062382e-02, p4 = 1.25520758471495131e-02, p5 = 1.31434886966174114e-02,
                   p6 = 1.53560065109186183e-02, p7 = 7.22247542904486117e-03, p8 = 6.89841097086238420e-04;
  // Q: m1^1..m1^8.
  constexpr double q1 = 2.49999999922726146e-01, q2 = 9.37499101465794765e-02, q3 = 5.85819356802619109e-02,
                   q4 = 4.23649618275207390e-02, q5 = 3.02039742932201268e-02, q6 = 1.53627745531750171e-02,
                   q7 = 3.41316878843145322e-03, q8 = 1.59278550086593140e-04;
  const double x = m1;
  const double P = p0 + x * (p1 + x * (p2 + x * (p3 + x * (p4 + x * (p5 + x * (p6 + x * (p7 + x * p8)))))));
  const double Q = x * (q1 + x * (q2 + x * (q3 + x * (q4 + x * (q5 + x * (q6 + x * (q7 + x * q8)))))));
  return P - 2.0 * ln_mu * Q;
}

}  // namespace frictionlab::friction
