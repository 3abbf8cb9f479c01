#!/usr/bin/python3
"""The exact friction law over an elliptic Hertz patch at 30+ digits, for the tests of `exact`.

Writes tests/friction/reference/exact_table.csv (read by tests/friction/exact_law_table_test.cpp):
F1/(kN), F2/(kN), M/(kNa) at dimensionless contacts a = N = k = 1 (m, N, -), b = mu, U = s,
Omega = sign (so s = U/(a|Omega|)), at every point listed in `points()`.

    /usr/bin/python3 tests/friction/reference/generate_exact_table.py > tests/friction/reference/exact_table.csv

Debian 12's python3 and python3-mpmath (1.2.1, pure-Python backend) reproduce the committed file
byte for byte (no clock, no randomness; `--jobs N` changes only the time). It takes about 35
minutes with `--jobs 2` on the development machine (2-core AMD EPYC KVM guest), about 70 on one
core: the slender patches with the ICR near them cost up to a minute a point. `--self-check`
compares the method with closed forms and exits; `--cross-check` recomputes the first
CROSS_CHECK_POINTS points (mu = 1 .. 1e-6) by a second 2-D quadrature (about 70 minutes on one
core) and prints the largest difference.

Method: independent of both laws. friction/exact_law.cpp reduces the radial integrals in closed
form, in a frame where the patch is the unit disc, and integrates over line directions by
Gauss-Legendre after a Weierstrass substitution; friction/exact_reference_law.cpp integrates in
polar coordinates about the patch centre with GSL. Here the definition of the law
(docs/model.md),

    F1 = k ∫∫ p v_x/|v| dA,  F2 = k ∫∫ p v_y/|v| dA,  M = k ∫∫ p (x v_y - y v_x)/|v| dA,
    v = (U - Omega y, Omega x) in the slip frame, p = 3N/(2 pi a b) sqrt(1 - xi^2/a^2 - eta^2/b^2),

is integrated in two dimensions by tanh-sinh quadrature in mpmath at 50 digits, split at the
instantaneous centre of rotation (ICR) c: with w = rho - c, v = Omega J w, J(x, y) = (-y, x), so
v/|v| = sign(Omega) J w/|w|, and the integrals G = ∫∫ p w/|w| dA, H = ∫∫ p rho.w/|w| dA give
F1 = -sign G_y, F2 = sign G_x, M = sign H. `exact_law_polar` (the table) uses polar coordinates
about c, where w/|w| is constant along each ray and the inner integrand is the pressure's square
root times r or r^2; `exact_law_cartesian` (the cross-check) uses Cartesian coordinates of the
unit-disc frame split at c. Each 1-D rule refines its step 2^-level until two successive levels
agree to 1e-28 (relative, for values above 1), at 50 digits; nodes closer to an end than 1e-47
(relative) are dropped (their weights are below 1e-46).

Accuracy: the values are good to better than 1e-30 (per kN, kNa). Evidence, 2026-11-22:
  * `--cross-check`: the two methods agree on the first 68 points (mu = 1 .. 1e-6) to 1.2e-34;
  * the slit point (mu = 1e-9, psi 5e-9 from pi/2, s = 0.5) rerun by the Cartesian method at 60
    digits with tolerance 1e-36 agrees with the table to 2e-37;
  * `--self-check`: the circle closed forms (docs/model.md) at u = 0.5, 1 + 1e-9 and 2, and the
    pure-spin moment (3/8) E(e) at mu = 0.1, agree to 3e-48.

Points (`points()`): the 12 inputs of the former inline spot values of exact_law_test.cpp and the
input of the slit case that once gave NaN; then, for each mu in 1, 0.5, 0.1, 0.01, 1e-3, 1e-6,
1e-9, 1e-12 and each psi in 0, 0.4, 1.2, pi/2 - 5e-9, pi/2 (as doubles), 2.5 (mu = 1: 0, 0.9),
two ICR positions by turns from: inside (rho = 0.5), 1e-9 inside and outside the rim, rho = sqrt 2
(where the law switches method), rho = 4, rho = 1e3, and s = 1e4, with rho = s sqrt(sin^2 psi +
cos^2 psi / mu^2) the ICR's distance in the unit-disc frame; the spin sign alternates.
"""

import argparse
import sys

import mpmath
from mpmath import mp, mpf

DIGITS = 50             # working precision, decimal digits
TOLERANCE = mpf(10) ** -28  # two successive tanh-sinh levels must agree to this
MAX_LEVEL = 12
OUTPUT_DIGITS = 34      # significant digits written
CROSS_CHECK_POINTS = 68  # the points --cross-check recomputes by the Cartesian method


def converged(current, previous):
    """Two successive levels agree to TOLERANCE, relative to the values' size where it exceeds 1."""
    scale = max([mpf(1)] + [abs(x) for x in current])
    return max(abs(c - p) for c, p in zip(current, previous)) < TOLERANCE * scale


class TanhSinh:
    """The tanh-sinh rule on [-1, 1], nested by level (step 2^-level), nodes as distances to the ends."""

    def __init__(self):
        eps = mpf(10) ** (-(DIGITS - 3))
        t = mpf(1)
        while 2 * mp.exp(-mp.pi * mp.sinh(t)) >= eps:  # 1 - tanh((pi/2) sinh t) ~ 2 exp(-pi sinh t)
            t += mpf(1) / 16
        t_max = t
        self.levels = []
        for level in range(MAX_LEVEL + 1):
            h = mpf(2) ** -level
            first, step = (0, 1) if level == 0 else (1, 2)
            nodes = []
            k = first
            while k * h <= t_max:
                tk = k * h
                u = mp.pi / 2 * mp.sinh(tk)
                e = mp.exp(-2 * u)
                end_distance = 2 * e / (1 + e)  # 1 - tanh(u), without cancellation
                weight = mp.pi / 2 * mp.cosh(tk) / mp.cosh(u) ** 2
                nodes.append((end_distance, weight, k == 0))
                k += step
            self.levels.append(nodes)

    def integrate(self, f, a, b, ncomp):
        """The integral over [a, b] of the ncomp-vector function f."""
        half = (b - a) / 2
        acc = [mpf(0)] * ncomp
        previous = None
        for level, nodes in enumerate(self.levels):
            for end_distance, weight, centre in nodes:
                for x in ([b - half * end_distance] if centre else
                          [b - half * end_distance, a + half * end_distance]):
                    value = f(x)
                    for i in range(ncomp):
                        acc[i] += weight * value[i]
            current = [half * mpf(2) ** -level * x for x in acc]
            if previous is not None and level >= 3 and converged(current, previous):
                return current
            previous = current
        raise RuntimeError("tanh-sinh did not converge on [%s, %s]" % (mp.nstr(a, 10), mp.nstr(b, 10)))

    def integrate_with_ends(self, f, a, b, ncomp):
        """As integrate(), f(x, e) also given e = the distance from x to the nearer end, per (b - a)/2."""
        half = (b - a) / 2
        acc = [mpf(0)] * ncomp
        previous = None
        for level, nodes in enumerate(self.levels):
            for end_distance, weight, centre in nodes:
                for x in ([b - half * end_distance] if centre else
                          [b - half * end_distance, a + half * end_distance]):
                    value = f(x, end_distance)
                    for i in range(ncomp):
                        acc[i] += weight * value[i]
            current = [half * mpf(2) ** -level * x for x in acc]
            if previous is not None and level >= 3 and converged(current, previous):
                return current
            previous = current
        raise RuntimeError("tanh-sinh did not converge on [%s, %s]" % (mp.nstr(a, 10), mp.nstr(b, 10)))


RULE = None


def slip_frame(F_ellipse, psi, sign):
    """(F1, F2, M) from G_e = ∫∫ p w/|w| dA (ellipse frame) and H = ∫∫ p rho.w/|w| dA, per N.

    v/|v| = sign J w/|w| and G = R(psi) G_e give F1 = -sign G_y, F2 = sign G_x, M = sign H."""
    gx, gy, H = F_ellipse
    cpsi, spsi = mp.cos(psi), mp.sin(psi)
    return (-sign * (spsi * gx + cpsi * gy), sign * (cpsi * gx - spsi * gy), sign * H)


def exact_law_polar(s, mu, psi, sign, pressure="hertz"):
    """The table's method: polar coordinates about the ICR, both integrals by tanh-sinh.

    rho = c + r d(theta) in the ellipse frame (x along the major axis, a = 1, b = mu), with
    d = (cos theta, sin theta), theta in a period pi, r signed along the whole chord; dA = |r| dr
    dtheta and w/|w| = sign(r) d, so G_e = ∫ d ∫ p r dr dtheta and H = ∫ ∫ p (c.d + r) r dr dtheta.
    The inner integrand is p = (3/(2 pi mu)) sqrt(A (r+ - r)(r - r-)) times r or r^2: evaluated from
    the nodes' distances to the chord's ends, it has its square-root ends exactly. The outer one is
    integrated over the directions that meet the patch (all, for an ICR inside), split at the
    major axis and geometrically (ratio 4) from mu/4 away from it, where A = cos^2 + sin^2/mu^2
    varies on every scale from mu to 1; and geometrically from the window's ends (ICR outside) or
    about the directions where the chord is shortest (ICR inside), for an ICR near the rim.

    `pressure` (generate_pressure_table.py): "hertz" as above; "uniform", p = 1/(pi mu), and
    "punch", p = (1/(2 pi mu)) / sqrt(A (r+ - r)(r - r-)) (docs/pressure-models.md §1), whose chord
    integrals are elementary and taken in closed form (the punch's in the angle of
    r = (r+ + r-)/2 - ((r+ - r-)/2) cos(angle)); only the integral over directions is numerical."""
    s, mu, psi = mpf(s), mpf(mu), mpf(psi)
    cx, cy = sign * s * mp.sin(psi), sign * s * mp.cos(psi)  # the ICR, ellipse frame
    mu2 = mu * mu
    c0 = cx * cx + cy * cy / mu2 - 1  # < 0: the ICR is inside
    p0 = 3 / (2 * mp.pi * mu)

    def direction(theta):
        dx, dy = mp.cos(theta), mp.sin(theta)
        A = dx * dx + dy * dy / mu2
        B = cx * dx + cy * dy / mu2
        cross = dx * cy - dy * cx
        D = A - cross * cross / mu2  # = B^2 - A c0 (Lagrange's identity), > 0 on a chord
        if D <= 0:
            return (0, 0, 0)
        q = -(B + mp.sqrt(D)) if B >= 0 else -(B - mp.sqrt(D))
        r1, r2 = sorted((q / A, c0 / q))
        half = (r2 - r1) / 2
        scale = p0 * mp.sqrt(A) * half

        def chord(r, end):  # end: the node's distance to the nearer chord end, per half
            hertz = scale * mp.sqrt(end * (2 - end))
            return (hertz * r, hertz * r * r)

        if pressure == "hertz":
            I1, I2 = RULE.integrate_with_ends(chord, r1, r2, 2)
        elif pressure == "uniform":  # p = 1/(pi mu)
            I1 = (r2 * r2 - r1 * r1) / (2 * mp.pi * mu)
            I2 = (r2 ** 3 - r1 ** 3) / (3 * mp.pi * mu)
        else:  # punch: r = mid - half cos(angle), p dr = dangle / (2 pi mu sqrt(A))
            mid = (r1 + r2) / 2
            I1 = mid / (2 * mu * mp.sqrt(A))
            I2 = (mid * mid + half * half / 2) / (2 * mu * mp.sqrt(A))
        return (dx * I1, dy * I1, (cx * dx + cy * dy) * I1 + I2)

    rho = mp.sqrt(cx * cx + cy * cy / mu2)
    phi = mp.atan2(cy / mu, cx)  # the ICR's direction in the unit-disc frame (x, y/mu)

    def ellipse_angle(tau):  # the direction (cos tau, sin tau) of the disc frame, as theta
        return mp.atan2(mu * mp.sin(tau), mp.cos(tau))

    def graded(first, limit):  # first, 4 first, 16 first, ... below limit (none if first = 0)
        out = []
        x = first if first > 0 else limit
        while x < limit:
            out.append(x)
            x *= 4
        return out

    breaks = set()
    if c0 < 0:
        lo, hi = mpf(0), mp.pi
        # D is smallest, 1 - rho^2 = -c0, on the lines perpendicular to the ICR's direction (in the
        # disc frame), with zeros at +-i sqrt(-c0)/rho off them: graded breaks about them.
        perpendicular = phi + mp.pi / 2
        for tau in [perpendicular] + [perpendicular + sgn * x for x in graded(mp.sqrt(-c0), mp.pi / 2)
                                      for sgn in (-1, 1)]:
            breaks.add(ellipse_angle(tau) % mp.pi)
    else:  # the window: the lines through the ICR tangent to the patch bound it
        half_window = mp.asin(1 / rho)
        lo = ellipse_angle(phi - half_window)
        hi = ellipse_angle(phi + half_window)
        while hi <= lo:
            hi += mp.pi
        # Across the gap of directions that miss the patch the window's ends are each other's
        # singularities: graded breaks at multiples of the gap from both ends.
        gap = mp.pi - (hi - lo)
        for x in graded(gap, (hi - lo) / 2):
            breaks.update((lo + x, hi - x))
    breaks.update((lo, hi))
    # The major axis (theta = k pi): A = cos^2 + sin^2/mu^2 has its zeros at +-i atanh(mu) from it,
    # and the integrand varies on every scale from mu to 1: graded breaks mu/4, mu, 4 mu, ...
    k = mp.floor(lo / mp.pi)
    while k * mp.pi < hi + mp.pi:
        axis = k * mp.pi
        for x in [axis] + [axis + sgn * x for x in graded(mu / 4, mp.pi / 2) for sgn in (-1, 1)]:
            breaks.add(x)
        k += 1
    # Fold the breaks into [lo, hi] (the integrand has period pi in theta).
    folded = set()
    for x in breaks:
        x = lo + (x - lo) % mp.pi
        if lo <= x <= hi:
            folded.add(x)
    breaks = folded | {lo, hi}
    breaks = sorted(breaks)
    G = [mpf(0)] * 3
    for a, b in zip(breaks, breaks[1:]):
        part = RULE.integrate(direction, a, b, 3)
        for i in range(3):
            G[i] += part[i]
    return slip_frame(G, psi, sign)


def exact_law_cartesian(s, mu, psi, sign):
    """The cross-check: Cartesian coordinates X = x/a, Y = y/b of the ellipse frame (the patch is
    the unit disc), the inner integral over X split at the ICR's Xc, the outer over Y split at Yc
    and at +-sqrt(1 - Xc^2). Good to 30+ digits too, but slow for slender patches with the ICR
    near them (the direction of w turns within mu |Y - Yc| of X = Xc): `--cross-check` runs it on
    the first CROSS_CHECK_POINTS points."""
    s, mu, psi = mpf(s), mpf(mu), mpf(psi)
    cpsi, spsi = mp.cos(psi), mp.sin(psi)
    xc = sign * s * spsi
    yc = sign * s * cpsi / mu

    def row(y):
        # Over the chord at Y = y, with w = (X - Xc, mu (Y - Yc)) in the ellipse frame (|w| is the
        # same in every frame) and rho = (X, mu Y): ∫ p w/|w| and ∫ p rho.w/|w|, every integrand
        # bounded by the pressure (on the ICR's own row too, where w_Y = 0).
        h2 = 1 - y * y
        h = mp.sqrt(h2) if h2 > 0 else mpf(0)
        wy = mu * (y - yc)
        wy2 = wy * wy

        def chord(x):
            hertz2 = h2 - x * x
            hertz = mp.sqrt(hertz2) if hertz2 > 0 else mpf(0)
            wx = x - xc
            n2 = wx * wx + wy2
            if n2 == 0:
                return (0, 0, 0)
            t = hertz / mp.sqrt(n2)
            return (t * wx, t * wy, t * (x * wx + mu * y * wy))

        ends = [-h] + ([xc] if -h < xc < h else []) + [h]
        total = [mpf(0)] * 3
        for lo, hi in zip(ends, ends[1:]):
            part = RULE.integrate(chord, lo, hi, 3)
            for i in range(3):
                total[i] += part[i]
        return total

    breaks = {mpf(-1), mpf(1)}
    if -1 < yc < 1:
        breaks.add(yc)
    if -1 < xc < 1:
        edge = mp.sqrt(1 - xc * xc)
        breaks.update((edge, -edge))
    breaks = sorted(breaks)
    G = [mpf(0)] * 3
    for lo, hi in zip(breaks, breaks[1:]):
        part = RULE.integrate(row, lo, hi, 3)
        for i in range(3):
            G[i] += part[i]
    c = 3 / (2 * mp.pi)  # p dA = (3/(2 pi)) sqrt(1 - X^2 - Y^2) dX dY per N
    return slip_frame([c * g for g in G], psi, sign)



def s_at(rho, mu, psi):
    """The double s that puts the ICR at distance rho from the centre of the unit-disc frame."""
    with mp.workdps(40):
        return float(mpf(rho) / mp.sqrt(mp.sin(psi) ** 2 + (mp.cos(psi) / mpf(mu)) ** 2))


def points():
    """(case, s, mu, psi, sign) as Python floats: the doubles the C++ test passes to the law."""
    out = []
    # The former inline spot values of exact_law_test.cpp: ICR on the rim of mu = 0.5 and 1e-8 off
    # it, slender patches, rho = sqrt 2 (the gap/window switch), fast slip.
    spots = [
        (0.5, 0.5, 0.0, 1), (0.500000005, 0.5, 0.0, 1), (0.499999995, 0.5, 0.0, -1),
        (0.7, 0.01, 1.2, 1), (0.3, 0.01, 1.5697963267948967, -1), (0.005, 0.01, 0.001, 1),
        (3.0, 0.05, 0.4, 1), (50.0, 0.2, 2.5, -1), (1.0, 0.7, 1.0, 1),
        (0.7071067811865476, 0.5, 0.0, 1), (0.02, 0.01, 0.7, 1), (10000.0, 0.3, 0.3, 1),
    ]
    out += [("spot",) + p for p in spots]
    out.append(("slit", 0.5, 1e-9, 1.5707963217948966, 1))  # once -nan,-nan,inf
    kinds = [("inside", 0.5), ("rim-", 1 - 1e-9), ("rim+", 1 + 1e-9), ("sqrt2", 2 ** 0.5),
             ("window", 4.0), ("far", 1e3), ("fast", None)]
    sign = 1
    for i, mu in enumerate([1.0, 0.5, 0.1, 0.01, 1e-3, 1e-6, 1e-9, 1e-12]):
        psis = [0.0, 0.9] if mu == 1.0 else [0.0, 0.4, 1.2, 1.5707963217948966, 1.5707963267948966, 2.5]
        for j, psi in enumerate(psis):
            for kind, rho in (kinds[(2 * j + i) % 7], kinds[(2 * j + 1 + i) % 7]):
                s = 1e4 if rho is None else s_at(rho, mu, psi)
                out.append((kind, s, mu, psi, sign))
                sign = -sign
    return out


def fmt(x):
    return mp.nstr(x, OUTPUT_DIGITS, min_fixed=1, max_fixed=0, strip_zeros=False)


def evaluate(point):
    global RULE
    if RULE is None:
        mp.dps = DIGITS
        RULE = TanhSinh()
    case, s, mu, psi, sign = point
    F1, F2, M = exact_law_polar(s, mu, psi, sign)
    return ",".join([case, repr(s), repr(mu), repr(psi), str(sign), fmt(F1), fmt(F2), fmt(M)])


def self_check():
    global RULE
    mp.dps = DIGITS
    RULE = TanhSinh()
    worst = mpf(0)
    for u in [mpf("0.5"), 1 + mpf("1e-9"), mpf(2)]:
        F1, F2, M = exact_law_polar(u, 1.0, 0.3, 1)
        if u <= 1:
            f1 = 3 * mp.pi / 32 * u * (4 - u * u)
            m = 3 * mp.pi / 128 * (8 - 8 * u * u + 3 * u ** 4)
        else:
            f1 = 3 / (16 * u) * ((4 * u * u - u ** 4) * mp.asin(1 / u) + (u * u + 2) * mp.sqrt(u * u - 1))
            m = mpf(3) / 64 * ((8 - 8 * u * u + 3 * u ** 4) * mp.asin(1 / u) + (6 - 3 * u * u) * mp.sqrt(u * u - 1))
        for name, got, want in (("F1", F1, f1), ("F2", F2, 0), ("M", M, m)):
            print("circle u = %s: %s error %s" % (mp.nstr(u, 12), name, mp.nstr(abs(got - want), 3)))
            worst = max(worst, abs(got - want))
    mu = mpf(0.1)  # the double nearest 0.1, as the law sees it
    F1, F2, M = exact_law_polar(0.0, 0.1, 0.7, -1)
    m = -mpf(3) / 8 * mp.ellipe(1 - mu * mu)  # mpmath's ellipe takes the parameter e^2
    print("pure spin mu = 0.1: M error %s, |F| %s" % (mp.nstr(abs(M - m), 3), mp.nstr(abs(F1) + abs(F2), 3)))
    worst = max(worst, abs(M - m), abs(F1), abs(F2))
    print("largest error: %s" % mp.nstr(worst, 3))
    return 0 if worst < mpf(10) ** -30 else 1


def cross_check():
    global RULE
    mp.dps = DIGITS
    RULE = TanhSinh()
    worst = mpf(0)
    for case, s, mu, psi, sign in points()[:CROSS_CHECK_POINTS]:
        a = exact_law_polar(s, mu, psi, sign)
        b = exact_law_cartesian(s, mu, psi, sign)
        diff = max(abs(x - y) for x, y in zip(a, b))
        worst = max(worst, diff)
        print("%s s = %r mu = %r psi = %r: %s" % (case, s, mu, psi, mp.nstr(diff, 3)), flush=True)
    print("largest difference: %s" % mp.nstr(worst, 3))
    return 0 if worst < mpf(10) ** -30 else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--jobs", type=int, default=1, help="worker processes (the output is the same)")
    parser.add_argument("--self-check", action="store_true", help="compare with closed forms and exit")
    parser.add_argument("--cross-check", action="store_true",
                        help="compare the two 2-D methods on the first points and exit")
    args = parser.parse_args()
    if args.self_check:
        return self_check()
    if args.cross_check:
        return cross_check()
    print("# The exact friction law over an elliptic Hertz patch at 30+ digits: F1/(kN), F2/(kN), M/(kNa)")
    print("# at a = N = k = 1, b = mu, U = s, Omega = sign. Generated by")
    print("# tests/friction/reference/generate_exact_table.py (mpmath %s, %d digits, 2-D tanh-sinh" % (mpmath.__version__, DIGITS))
    print("# quadrature in polar coordinates about the ICR; see the script). Do not edit: rerun the")
    print("# script, which reproduces this file byte for byte.")
    print("case,s,mu,psi,sign,F1,F2,M")
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
