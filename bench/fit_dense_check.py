#!/usr/bin/python3
"""How far `fit` is from `exact` on a much denser set than its test's (docs/fit.md §4): N seeded
random points per pressure, drawn as the check set of tests/friction/dense_check_set.h (b/a
log-uniform in [0.05, 1], psi uniform in [0, 2 pi), the spin's sign random; s a third log-uniform
in [1e-4, 1e4], a third just inside the rim, a third just outside, at relative distances
log-uniform in [1e-6, 0.3]) but from numpy's generator with another seed, so not the test's
points. Prints, per pressure, the largest |fit - exact| of F1, F2 (per kN = k·N, the friction
coefficient times the normal force) and M (per kNa = k·N·a) with the worst point; then climbs from
the 8 worst points of each output to the nearest local maximum of the error (Nelder-Mead in
ln s, ln(b/a), psi; scipy) and prints the largest found, against the bound the header states
(frictionlab_fit::kMaxError, read from friction/standalone/fit_law.h).

    PYTHONPATH=build/python /usr/bin/python3 bench/fit_dense_check.py [--points 2000000] [--seed 7]

Exit status 1 if an error exceeds the stated bound.
"""

import argparse
import os
import re
import sys

import numpy as np
from scipy.optimize import minimize

try:
    import frictionlab
except ImportError as exc:
    sys.exit(f"fit_dense_check.py: error: cannot import frictionlab ({exc}); set PYTHONPATH=build/python")

PRESSURES = ["hertz", "uniform", "punch"]
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def stated_bounds():
    text = open(os.path.join(ROOT, "friction", "standalone", "fit_law.h")).read()
    values = re.search(r"kMaxError\[3\] = \{([^}]*)\}", text).group(1)
    return dict(zip(PRESSURES, (float(v) for v in values.split(","))))


def check_set(n, seed):
    rng = np.random.default_rng(seed)
    mu = 0.05 ** rng.random(n)
    psi = 2 * np.pi * rng.random(n)
    omega = np.where(rng.random(n) < 0.5, 1.0, -1.0)
    d = 10.0 ** (-6.0 + (6.0 + np.log10(0.3)) * rng.random(n))
    rim = 1 / np.sqrt(np.sin(psi) ** 2 + (np.cos(psi) / mu) ** 2)
    s = 10.0 ** (-4.0 + 8.0 * rng.random(n))
    kind = np.arange(n) % 3
    s = np.where(kind == 1, rim * (1 - d), np.where(kind == 2, rim * (1 + d), s))
    return s, omega, mu, psi, rim


def local_maximum(pressure, err, s, omega, mu, psi):
    """the largest |fit - exact| found by climbing from the 8 worst points of each output"""
    exact, fit = frictionlab.Law(f"exact:pressure={pressure}"), frictionlab.Law(f"fit:pressure={pressure}")

    def minus_error(x, k, sign):
        ratio = min(1.0, max(0.05, np.exp(x[1])))
        return -abs(fit(np.exp(x[0]), sign, 1.0, ratio, x[2], 1.0, 1.0)[k] -
                    exact(np.exp(x[0]), sign, 1.0, ratio, x[2], 1.0, 1.0)[k])

    best, where = 0.0, ""
    for k, name in enumerate(["F1/kN", "F2/kN", "M/kNa"]):
        for i in np.argsort(err[k])[-8:]:
            r = minimize(minus_error, [np.log(s[i]), np.log(mu[i]), psi[i]], args=(k, omega[i]), method="Nelder-Mead",
                         options=dict(xatol=1e-7, fatol=1e-10, maxiter=400))
            if -r.fun > best:
                best = -r.fun
                where = (f"{name} at s = {np.exp(r.x[0]):.5g}, b/a = {min(1.0, max(0.05, np.exp(r.x[1]))):.5g}, "
                         f"psi = {r.x[2]:.5g}")
    return max(best, float(err.max())), where


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=2_000_000)
    parser.add_argument("--seed", type=int, default=7)
    args = parser.parse_args()
    if args.points < 3:
        sys.exit(f"fit_dense_check.py: error: --points = {args.points} is invalid: it must be at least 3")
    bounds = stated_bounds()
    s, omega, mu, psi, rim = check_set(args.points, args.seed)
    failed = False
    print(f"{args.points} points per pressure (seed {args.seed}), b/a in [0.05, 1]: max |fit - exact|")
    for pressure in PRESSURES:
        exact = np.array(frictionlab.Law(f"exact:pressure={pressure}")(s, omega, 1.0, mu, psi, 1.0, 1.0))
        fit = np.array(frictionlab.Law(f"fit:pressure={pressure}")(s, omega, 1.0, mu, psi, 1.0, 1.0))
        err = np.abs(fit - exact)
        worst = [int(np.argmax(e)) for e in err]
        parts = []
        for name, e, i in zip(["F1/kN", "F2/kN", "M/kNa"], err, worst):
            parts.append(f"{name} {e[i]:.4g} (s = {s[i]:.4g}, b/a = {mu[i]:.4g}, psi = {psi[i]:.4g}, "
                         f"s/s_rim = {s[i] / rim[i]:.4g})")
        largest, where = local_maximum(pressure, err, s, omega, mu, psi)
        parts.append(f"local maximum {largest:.4g} ({where})")
        verdict = "within" if largest <= bounds[pressure] else "ABOVE"
        failed |= largest > bounds[pressure]
        print(f"  {pressure}: {'; '.join(parts)}; {verdict} the stated {bounds[pressure]}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
