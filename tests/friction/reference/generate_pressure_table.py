#!/usr/bin/python3
"""The exact law for the uniform and flat-punch pressures at 30+ digits, slender patches first.

Writes tests/friction/reference/pressure_table.csv (read by
tests/friction/exact_law_pressure_table_test.cpp): F1/(kN), F2/(kN), M/(kNa) at dimensionless
contacts a = N = k = 1 (m, N, -), b = mu, U = s, Omega = sign, for `exact:pressure=uniform` and
`exact:pressure=punch`, at every point listed in `points()`.

    /usr/bin/python3 tests/friction/reference/generate_pressure_table.py --jobs 2 > tests/friction/reference/pressure_table.csv

Debian 12's python3 and python3-mpmath reproduce the committed file byte for byte (no clock, no
randomness; `--jobs N` changes only the time). `--self-check` compares the method with closed
forms (the uniform circle, the pure-spin moments, the slit limit) and exits.

Method: that of generate_exact_table.py (its `exact_law_polar`, imported, with `pressure=`): the
definition of the law in polar coordinates about the instantaneous centre of rotation, the
integral along each line through it elementary for these pressures and taken in closed form, the
integral over the lines' directions by tanh-sinh quadrature in mpmath at 50 digits, split and
graded as for the Hertz table. It shares no quadrature with `exact` (rim integrals, a
Jacobi-amplitude trapezoid rule or graded Gauss-Legendre panels; for every uniform patch below
b/a = 0.01, rim integrals, which share not even the reduction) nor with `exact-reference` (GSL,
b/a >= 0.01 only). With the chord integrals by tanh-sinh instead (as the Hertz table does), the
first 39 points agreed with these to 1.6e-30 (2026-11-27; mpmath 1.3.0).

Points (`points()`): the two fuzzed inputs of docs/pressure-models.md §3 (uniform, b/a ~ 1e-12, where `exact` once
gave F1 = 1.00008 and F1 < 0); then, for each pressure, each mu in its list and each psi in 0, 0.4,
1.2, pi/2 - 5e-9, pi/2 (as doubles), 2.5, two ICR positions by turns from: inside (rho = 0.5),
1e-9 inside and outside the rim, rho = 1.02, rho = sqrt 2, rho = 4, rho = 1e3, s = 1e4 and
s = 1e-8, with rho = s sqrt(sin^2 psi + cos^2 psi / mu^2) the ICR's distance in the unit-disc
frame; the spin sign alternates.
"""

import argparse
import os
import sys

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_exact_table as base  # noqa: E402  (the 2-D method, its rule and helpers)

PRESSURES = {
    # pressure: the axis ratios of its points
    "uniform": [1e-2, 1e-3, 1e-4, 1e-6, 1e-9, 1e-12],
    "punch": [1e-3, 1e-6, 1e-12],
}
PSIS = [0.0, 0.4, 1.2, 1.5707963217948966, 1.5707963267948966, 2.5]
KINDS = [("inside", 0.5), ("rim-", 1 - 1e-9), ("rim+", 1 + 1e-9), ("near", 1.02), ("sqrt2", 2 ** 0.5),
         ("window", 4.0), ("far", 1e3), ("fast", None), ("slow", None)]
FIXED_S = {"fast": 1e4, "slow": 1e-8}


def points():
    """(pressure, case, s, mu, psi, sign) as Python floats: the doubles the C++ test passes."""
    out = [
        ("uniform", "issue", 255094.52174620156, 1.0025254830532505e-12, -2.4426969214284204, 1),
        ("uniform", "issue", 3.9575557720477157e-08, 1.0753224871646648e-12, 3.0505797375823827, 1),
    ]
    sign = 1
    for pressure, mus in PRESSURES.items():
        for i, mu in enumerate(mus):
            for j, psi in enumerate(PSIS):
                for k in (2 * j + i, 2 * j + 1 + i):
                    kind, rho = KINDS[k % len(KINDS)]
                    s = FIXED_S[kind] if rho is None else base.s_at(rho, mu, psi)
                    out.append((pressure, kind, s, mu, psi, sign))
                    sign = -sign
    return out


def init():
    if base.RULE is None:
        mp.dps = base.DIGITS
        base.RULE = base.TanhSinh()


def evaluate(point):
    init()
    pressure, case, s, mu, psi, sign = point
    F1, F2, M = base.exact_law_polar(s, mu, psi, sign, pressure)
    return ",".join([pressure, case, repr(s), repr(mu), repr(psi), str(sign),
                     base.fmt(F1), base.fmt(F2), base.fmt(M)])


def slit_limit(pressure, s, psi):
    """F1, F2, M (Omega > 0) of the slit b/a -> 0 (docs/pressure-models.md §6): the load on the
    major axis with the line density lambda(xi) = ∫ p dy, and G_e = ∫ lambda w/|w| dxi,
    H = ∫ lambda xi w_x/|w| dxi, w = (xi - c1, -c2), by mpmath's quad split at xi = c1."""
    s, psi = mpf(s), mpf(psi)
    c1, c2 = s * mp.sin(psi), s * mp.cos(psi)
    density = {"hertz": lambda x: mpf(3) / 4 * (1 - x * x),
               "uniform": lambda x: 2 / mp.pi * mp.sqrt(1 - x * x),
               "punch": lambda x: mpf(1) / 2}[pressure]
    ends = [mpf(-1)] + ([c1] if -1 < c1 < 1 else []) + [mpf(1)]

    def integral(f):
        return mp.quad(lambda x: density(x) * f(x), ends)

    r = lambda x: mp.sqrt((x - c1) ** 2 + c2 ** 2)  # noqa: E731
    gx = integral(lambda x: (x - c1) / r(x))
    gy = integral(lambda x: -c2 / r(x))
    H = integral(lambda x: x * (x - c1) / r(x))
    return base.slip_frame((gx, gy, H), psi, 1)


def self_check():
    init()
    worst = mpf(0)

    def report(what, got, want):
        nonlocal worst
        error = abs(got - want)
        worst = max(worst, error)
        print("%s: error %s" % (what, mp.nstr(error, 3)), flush=True)

    # The uniform circle (docs/pressure-models.md §2, Contensou-Erismann); mpmath's ellipk and
    # ellipe take the parameter m = k^2.
    for u in [mpf("0.5"), 1 + mpf("1e-9"), mpf(2)]:
        F1, F2, M = base.exact_law_polar(u, 1.0, 0.3, 1, "uniform")
        if u <= 1:
            K, E = mp.ellipk(u * u), mp.ellipe(u * u)
            f1 = 4 / (3 * mp.pi * u) * ((1 + u * u) * E - (1 - u * u) * K)
            m = 4 / (9 * mp.pi) * ((4 - 2 * u * u) * E - (1 - u * u) * K)
        else:
            K, E = mp.ellipk(1 / (u * u)), mp.ellipe(1 / (u * u))
            f1 = 4 / (3 * mp.pi) * ((1 + u * u) * E - (u * u - 1) * K)
            m = 4 * u / (9 * mp.pi) * ((4 - 2 * u * u) * E + (2 * u * u - 5 + 3 / (u * u)) * K)
        report("uniform circle u = %s F1" % mp.nstr(u, 12), F1, f1)
        report("uniform circle u = %s F2" % mp.nstr(u, 12), F2, 0)
        report("uniform circle u = %s M" % mp.nstr(u, 12), M, m)
    # Pure spin: M = c E(e), c = 4/(3 pi) uniform, 1/2 punch.
    mu = mpf(0.1)  # the double nearest 0.1, as the law sees it
    for pressure, c in (("uniform", 4 / (3 * mp.pi)), ("punch", mpf(1) / 2)):
        F1, F2, M = base.exact_law_polar(0.0, 0.1, 0.7, -1, pressure)
        report("%s pure spin mu = 0.1 M" % pressure, M, -c * mp.ellipe(1 - mu * mu))
        report("%s pure spin mu = 0.1 |F|" % pressure, abs(F1) + abs(F2), 0)
    # The slit limit at mu = 1e-12, the ICR off the slit (its corrections are O(mu^2/|c2|)).
    for pressure in ("uniform", "punch"):
        for s, psi in ((0.3, 0.4), (2.0, 1.2), (0.7, 2.5)):
            got = base.exact_law_polar(s, 1e-12, psi, 1, pressure)
            want = slit_limit(pressure, s, psi)
            for name, g, w in zip(("F1", "F2", "M"), got, want):
                report("%s slit s = %s psi = %s %s" % (pressure, s, psi, name), g, w)
    print("largest error: %s" % mp.nstr(worst, 3))
    return 0 if worst < mpf(10) ** -20 else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--jobs", type=int, default=1, help="worker processes (the output is the same)")
    parser.add_argument("--self-check", action="store_true", help="compare with closed forms and exit")
    args = parser.parse_args()
    if args.self_check:
        return self_check()
    print("# The exact friction law for the uniform and flat-punch pressures at 30+ digits: F1/(kN),")
    print("# F2/(kN), M/(kNa) at a = N = k = 1, b = mu, U = s, Omega = sign. Generated by")
    print("# tests/friction/reference/generate_pressure_table.py (mpmath %s, %d digits, 2-D tanh-sinh" %
          (mpmath.__version__, base.DIGITS))
    print("# quadrature in polar coordinates about the ICR; see the script). Do not edit: rerun the")
    print("# script, which reproduces this file byte for byte.")
    print("pressure,case,s,mu,psi,sign,F1,F2,M")
    sys.stdout.flush()
    todo = points()
    if args.jobs > 1:
        import multiprocessing
        with multiprocessing.Pool(args.jobs) as pool:
            for line in pool.imap(evaluate, todo):
                print(line, flush=True)
    else:
        for point in todo:
            print(evaluate(point), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
