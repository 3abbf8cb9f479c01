#!/usr/bin/python3
"""The complete elliptic integral E(e), e^2 = 1 - mu^2, for mu in [0.01, 1], as

    E = P(m1) - ln(m1) Q(m1),   m1 = mu^2,   P of degree 8, Q of degree 8 with Q(0) = 0,

for the pure-spin moment M0 = c_p k N a E(e) of `exact-table` (the table design of
docs/exact-table.md) and of `fit` (docs/fit.md). ln(m1) = 2 ln(mu) is the logarithm the table's coordinates
take anyway, so M0 costs no extra transcendental function.

Least-squares fit of the monomial coefficients of P and Q (degrees 6, 8, 10, 12 tried; 8 kept)
against scipy.special.ellipe on 4,000 Chebyshev points of m1 in [0, 1] and 2,000 log-spaced
points in [1e-8, 1], checked on 200,001 log-spaced mu in [0.01, 1]:

    /usr/bin/python3 friction/tools/fit_elliptic_e.py

prints the largest relative error of each degree (degree 8: 1.26e-14) to stderr and the degree-8
coefficients, as written in friction/standalone/fit_law.h (elliptic_e_fit, which
friction/elliptic_e_fit.h calls), to stdout. Debian 12's python3-numpy (1.24.2) and
python3-scipy (1.10.1) reproduce them to the last digit (2026-11-29, 2-core AMD EPYC KVM guest).
"""
import sys

import numpy as np
from scipy.special import ellipe

KEPT = 8
for d in [6, 8, 10, 12]:
    x = np.concatenate([np.cos(np.linspace(0, np.pi, 4000)) * 0.5 + 0.5, 10 ** np.linspace(-8, 0, 2000)])
    x = np.clip(x, 1e-12, 1)
    E = ellipe(1 - x)
    Bm = np.hstack([x[:, None] ** np.arange(d + 1), -np.log(x)[:, None] * x[:, None] ** np.arange(1, d + 1)])
    coef, *_ = np.linalg.lstsq(Bm, E, rcond=None)
    mu = 10 ** np.linspace(-2, 0, 200001); m1 = mu * mu
    P = np.polyval(coef[:d + 1][::-1], m1); Q = m1 * np.polyval(coef[d + 1:][::-1], m1)
    err = np.abs(P - np.log(m1) * Q - ellipe(1 - m1)) / ellipe(1 - m1)
    print(f"degree {d}: max rel err on mu in [0.01,1]: {err.max():.2e}", file=sys.stderr)
    if d == KEPT:
        kept = coef

print("// P: m1^0..m1^8")
print(",\n".join("%.17e" % c for c in kept[:KEPT + 1]))
print("// Q: m1^1..m1^8")
print(",\n".join("%.17e" % c for c in kept[KEPT + 1:]))
