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
// The coefficients live in the standalone header of `fit` (friction/standalone/fit_law.h), which
// must need nothing else.

#include "friction/standalone/fit_law.h"

namespace frictionlab::friction {

/// E(sqrt(1 - mu^2)) for mu in [0.01, 1], from m1 = mu^2 and ln_mu = ln(mu): 17 multiply-adds.
[[nodiscard]] inline double elliptic_e_fit(double m1, double ln_mu) { return frictionlab_fit::elliptic_e_fit(m1, ln_mu); }

}  // namespace frictionlab::friction
