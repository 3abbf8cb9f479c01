#!/usr/bin/python3
"""Fits the coefficients of the `fit` friction law (friction/standalone/fit_law.h, docs/fit.md), a
closed-form coupled sliding/spinning dry-friction law on an elliptic patch, against frictionlab's
`exact` law.

The law is the gradient of the dissipation function D = P^(1/8), P a homogeneous quartic in
X = ux^2, Y = uy^2, W = (a Omega)^2 (patch axes, mu = b/a in [0.05, 1]):

    P = S^4 + 4 W S^2 m2 (X + mu^2 Y) + W^2 (c0 X^2 + c1 X Y + c2 Y^2) + W^3 (c3 X + c4 Y) + M0^8 W^4,

S = X + Y, M0 = c_p E(e), m2 the pressure's second moment per axis (1/5 hertz, 1/4 uniform, 1/3
punch). The W^0, W^1 and W^4 terms are fixed by the fast-slip and pure-spin limits; the five free
shape functions are, with z = sqrt(mu) and t = 1 - z,

    c0 = A^2 + t B0^2, c1 = 2 A^2 + t B1^2, c2 = A^2 + t B2^2, c3 = C^2 + t B3^2, c4 = C^2 + t B4^2,

A, C, B0..B4 cubic polynomials in z: 28 numbers q per pressure (hertz, uniform, punch), c_m >= 0
by construction, and P isotropic (a function of S and W only) at mu = 1, as the exact law is for
a circle.

Training sets: per mu, the directions psi = 0, pi/2, nps uniform ones in (0, pi) and nps more
bunched around pi/2 (psi = atan2(sin phi, mu cos phi), phi uniform: there the rim point moves
fastest with psi on thin patches); along each of them s log-spaced in [1e-3, 1e3], s just inside
and outside the rim s_rim (1 -+ d) with d log-spaced in [1e-4, 0.5], and s_rim times [0.05, 3].
Omega > 0 only: the other sign and psi in (pi, 2 pi) follow by symmetry, exactly for both laws.

Method, for each pressure (deterministic: no random numbers):
(1) per-mu fits of the five c_m on 8 mu log-spaced from 1 to 0.05 (nps = 24), each started from
    the previous one (continuation), by Lawson-reweighted least squares;
(2) cubic least-squares fits in z: of sqrt(A^2), A^2 = min(c0, c1/2, c2), of sqrt(C^2),
    C^2 = min(c3, c4), and of the square roots of the rest over t: the start of
(3) a joint Lawson-reweighted minimax refit of all 28 q (4 rounds, 14 mu, nps = 16), keeping
    the round with the smallest maximum error, then
(4) a true minimax polish by sequential linear programming (trust region, HiGHS) on a denser set
    (30 mu, nps = 24, 156,000 points), which lowers the maximum error by 2-5 %.
The result is then checked against the exact law on 120,000 seeded random points (seed 2025):
mu log-uniform in [0.05, 1], psi uniform in [0, 2 pi), random sign of Omega, and s one third
log-uniform in [1e-4, 1e4], one third s_rim (1 - d), one third s_rim (1 + d), d log-uniform in
[1e-4, 0.3]. The errors found are the floor of the form itself (docs/fit.md §4): per-mu minimax
fits of the five c_m at mu = 0.05 alone reach 0.0396 (hertz), 0.0444 (uniform) and 0.0606 (punch),
the same minimum from 5 different starts, and a quartic in z changes nothing.

    FRICTIONLAB_PYTHON=build/python /usr/bin/python3 friction/tools/fit_dissipation.py [hertz|uniform|punch|all]

(FRICTIONLAB_PYTHON defaults to build/python of the repository) prints the progress and, per
pressure, the check's maximum absolute error of F1, F2 (kN) and M (kNa), the worst point and
the rms to stderr, and the coefficients as the C++ initializer of kQ[3][7][4] (order hertz,
uniform, punch; one pressure only if one is asked for) to stdout: 161 s, 146 s and 118 s of CPU
time for hertz, uniform and punch (2026-11-29, 2-core AMD EPYC KVM guest). Debian 12's
python3-numpy (1.24.2) and python3-scipy (1.10.1) reproduce them to the last digit.
"""
import os
import sys
import time

import numpy as np
from scipy.optimize import least_squares, linprog
from scipy.special import ellipe

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PYDIR = os.environ.get("FRICTIONLAB_PYTHON", os.path.join(ROOT, "build", "python"))
sys.path.insert(0, PYDIR)
try:
    import frictionlab
except ImportError as exc:
    sys.exit(f"fit_dissipation.py: cannot import frictionlab from {PYDIR} ({exc}); set FRICTIONLAB_PYTHON")

# pressure: (exact law name, c_p, m2)
PRESSURES = {"hertz": ("exact", 3 / 8, 1 / 5),
             "uniform": ("exact:pressure=uniform", 4 / (3 * np.pi), 1 / 4),
             "punch": ("exact:pressure=punch", 1 / 2, 1 / 3)}
DEG = 3          # degree of the q polynomials in z = sqrt(mu)
MU_MIN = 0.05


def log(*args):
    print(*args, file=sys.stderr, flush=True)


def exact(pres, s, sg, mu, psi):
    """exact law, dimensionless (a = kN = 1, Omega = sg = +-1, U = s): F1, F2, M as a (3, n) array"""
    return np.array(frictionlab.Law(PRESSURES[pres][0])(s, sg, 1.0, mu, psi, 1.0, 1.0))


def s_rim(mu, psi):
    """slip ratio at which the instantaneous centre of rotation lies on the rim"""
    return 1 / np.sqrt(np.sin(psi) ** 2 + np.cos(psi) ** 2 / mu ** 2)


ROWS = 7  # the polynomials A, C, B0..B4 of shape()


def shape(q, mu):
    """the shape functions c_m(mu), m = 0..4, from q (ROWS, DEG + 1): with z = sqrt(mu), t = 1 - z and
    the polynomials r = (A, C, B0..B4) in z, c0 = A^2 + t B0^2, c1 = 2 A^2 + t B1^2, c2 = A^2 + t B2^2,
    c3 = C^2 + t B3^2, c4 = C^2 + t B4^2: >= 0, and isotropic at mu = 1 -> (5, len(mu))"""
    z = np.sqrt(mu)
    t = 1 - z
    r = np.polynomial.polynomial.polyval(z, q.T) ** 2
    return np.array([r[0] + t * r[2], 2 * r[0] + t * r[3], r[0] + t * r[4], r[1] + t * r[5], r[1] + t * r[6]])


def law(pres, c, s, sg, mu, psi):
    """the fitted law, dimensionless like exact(); c (5, n) the shape functions at mu"""
    _, cp, m2 = PRESSURES[pres]
    cs, sn = np.cos(psi), np.sin(psi)
    inv = 1 / (s + 1)                                  # degree-0 result: scale out |x|
    ux, uy, w = s * cs * inv, -s * sn * inv, sg * inv
    X, Y, W = ux * ux, uy * uy, w * w
    S = X + Y
    J = m2 * (X + mu * mu * Y)
    M8 = (cp * ellipe(1 - mu * mu)) ** 8
    A2 = c[0] * X * X + c[1] * X * Y + c[2] * Y * Y
    A3 = c[3] * X + c[4] * Y
    P = S ** 4 + 4 * W * S * S * J + W ** 2 * A2 + W ** 3 * A3 + M8 * W ** 4
    PX = 4 * S ** 3 + 4 * W * (2 * S * J + S * S * m2) + W ** 2 * (2 * c[0] * X + c[1] * Y) + W ** 3 * c[3]
    PY = (4 * S ** 3 + 4 * W * (2 * S * J + S * S * m2 * mu * mu) + W ** 2 * (c[1] * X + 2 * c[2] * Y)
          + W ** 3 * c[4])
    PW = 4 * S * S * J + 2 * W * A2 + 3 * W ** 2 * A3 + 4 * M8 * W ** 3
    f = P ** 0.125 / (4 * P)
    Gx, Gy = f * ux * PX, f * uy * PY
    return np.array([Gx * cs - Gy * sn, Gx * sn + Gy * cs, f * w * PW])


def train_set(mus, nps, ns):
    """see the module docstring; returns s, sg, mu, psi"""
    parts = []
    d = np.logspace(-4, np.log10(0.5), 12)
    phi = (np.arange(nps) + 0.5) / nps * np.pi
    for mu in mus:
        for p in np.concatenate([[0, np.pi / 2], phi, np.arctan2(np.sin(phi), mu * np.cos(phi))]):
            sr = s_rim(mu, p)
            s = np.concatenate([np.logspace(-3, 3, ns), sr * (1 - d), sr * (1 + d),
                                sr * np.linspace(0.05, 3, 30)])
            parts.append(np.array([s, np.ones_like(s), np.full_like(s, mu), np.full_like(s, p)]))
    return tuple(np.concatenate(parts, axis=1))


def check_set(n=120000, seed=2025):
    """see the module docstring; returns s, sg, mu, psi"""
    r = np.random.default_rng(seed)
    mu = np.exp(r.uniform(np.log(MU_MIN), 0, n))
    psi = r.uniform(0, 2 * np.pi, n)
    sg = np.where(r.random(n) < 0.5, -1.0, 1.0)
    k = n // 3
    s = np.exp(r.uniform(np.log(1e-4), np.log(1e4), n))
    d = np.exp(r.uniform(np.log(1e-4), np.log(0.3), n))
    sr = s_rim(mu, psi)
    s[k:2 * k] = sr[k:2 * k] * (1 - d[k:2 * k])
    s[2 * k:] = sr[2 * k:] * (1 + d[2 * k:])
    return s, sg, mu, psi


def lawson(residual, x, rounds, nfev):
    """Lawson-reweighted least squares towards the minimax solution of residual(x); returns the
    x of the round with the smallest maximum |residual| (the start included) and that maximum"""
    w = np.ones(residual(x).size)
    best = (np.abs(residual(x)).max(), x)
    for _ in range(rounds):
        x = least_squares(lambda v: residual(v) * w, x, max_nfev=nfev, x_scale="jac").x
        e = np.abs(residual(x))
        best = min(best, (e.max(), x), key=lambda t: t[0])
        w = w * np.sqrt(e / e.max() + 1e-3)
        w /= w.max()
    return best


def minimax(residual, x, iters, delta=0.05, h=1e-7, tol=1e-5):
    """sequential linear programming for min over x of max |residual(x)|: each step minimises the
    maximum of the linearised residuals (forward-difference Jacobian, rows above 0.3 of the current
    maximum) in a box trust region, until the maximum has dropped by less than tol in 3 steps;
    returns the best x and its maximum"""
    r = residual(x)
    history = [np.abs(r).max()]
    for it in range(iters):
        log(f"  minimax step {it}: max {np.abs(r).max():.5f}, trust region {delta:.2g}")
        J = np.array([(residual(x + h * e) - r) / h for e in np.eye(x.size)]).T
        m = np.abs(r).max()
        a = np.abs(r) > 0.3 * m
        while delta > 1e-9:
            A = np.hstack([J[a], -np.ones((a.sum(), 1))])
            lp = linprog(np.r_[np.zeros(x.size), 1.0], A_ub=np.vstack([A, A * [*-np.ones(x.size), 1]]),
                         b_ub=np.r_[-r[a], r[a]], bounds=[(-delta, delta)] * x.size + [(0, None)],
                         method="highs")
            if lp.status != 0:                          # numerically failed LP: shrink the region
                delta /= 4
                continue
            rn = residual(x + lp.x[:-1])
            rho = (m - np.abs(rn).max()) / max(m - lp.x[-1], 1e-300)
            if rho > 0:
                x, r = x + lp.x[:-1], rn
                delta *= 2 if rho > 0.75 else 1
                break
            delta /= 4
        history.append(np.abs(r).max())
        if delta <= 1e-9 or len(history) > 3 and history[-4] - history[-1] < tol:
            break
    return np.abs(r).max(), x


def fit(pres):
    """returns q (ROWS, DEG + 1)"""
    t0 = time.time()
    mus = np.exp(np.linspace(0, np.log(MU_MIN), 8))
    roots, q = [], np.full(5, 0.3)
    for mu in mus:                                     # (1) per-mu fits, continuation in mu
        s, sg, muv, psi = train_set([mu], nps=24, ns=60)
        E = exact(pres, s, sg, muv, psi)
        e, q = lawson(lambda q: (law(pres, (q * q)[:, None], s, sg, muv, psi) - E).ravel(), q, 4, 300)
        roots.append(np.abs(q))
        q = np.sqrt(q * q + 1e-4)                      # off zero, where the gradient in q vanishes
        log(f"{pres}: per-mu fit mu={mu:.4f} max err {e:.4f}")
    # (2) polynomial start in z: the isotropic parts A^2 = min(c0, c1/2, c2), C^2 = min(c3, c4), the
    # rest over t (the circle, t = 0, has none); (3) joint Lawson refit, (4) minimax polish on a
    # denser set
    C = np.array(roots) ** 2                           # (len(mus), 5): the per-mu shape values
    z, t = np.sqrt(mus), 1 - np.sqrt(mus)
    A2 = np.minimum(np.minimum(C[:, 0], C[:, 1] / 2), C[:, 2])
    C2 = np.minimum(C[:, 3], C[:, 4])
    iso = np.array([A2, 2 * A2, A2, C2, C2]).T
    Q = np.zeros((ROWS, DEG + 1))
    Q[0] = np.polynomial.polynomial.polyfit(z, np.sqrt(A2), DEG)
    Q[1] = np.polynomial.polynomial.polyfit(z, np.sqrt(C2), DEG)
    inside = t > 1e-9
    for m in range(5):
        Q[2 + m] = np.polynomial.polynomial.polyfit(z[inside], np.sqrt((C[inside, m] - iso[inside, m]) / t[inside] + 1e-6),
                                                    DEG)
    for nmu, nps, joint in [(14, 16, lawson), (30, 24, minimax)]:
        s, sg, mu, psi = train_set(np.exp(np.linspace(0, np.log(MU_MIN), nmu)), nps, ns=50)
        E = exact(pres, s, sg, mu, psi)
        e, Q = joint(lambda v: (law(pres, shape(v.reshape(ROWS, DEG + 1), mu), s, sg, mu, psi) - E).ravel(),
                     Q.ravel(), *(4, 100) if joint is lawson else (30,))
        Q = Q.reshape(ROWS, DEG + 1)
        log(f"{pres}: joint {joint.__name__} fit on {s.size} points: max err {e:.4f} "
            f"({time.time() - t0:.0f} s)")
    return Q


def check(pres, q):
    s, sg, mu, psi = check_set()
    err = np.abs(law(pres, shape(q, mu), s, sg, mu, psi) - exact(pres, s, sg, mu, psi))
    k, i = np.unravel_index(err.argmax(), err.shape)
    log(f"{pres}: check on {s.size} points: max abs err F1 {err[0].max():.4g} F2 {err[1].max():.4g} "
        f"M {err[2].max():.4g}; rms {np.sqrt((err ** 2).mean()):.3g}")
    log(f"{pres}:   worst {['F1', 'F2', 'M'][k]} {err[k, i]:.4g} at s={s[i]:.6g} mu={mu[i]:.5f} "
        f"psi={psi[i]:.4f} sign(Omega)={sg[i]:+.0f} (s/s_rim={s[i] / s_rim(mu[i], psi[i]):.4f})")


def main():
    which = sys.argv[1] if len(sys.argv) > 1 else "all"
    if which not in ["all", *PRESSURES]:
        sys.exit("usage: fit_dissipation.py [hertz|uniform|punch|all]")
    rows = []
    for pres in PRESSURES if which == "all" else [which]:
        q = fit(pres)
        check(pres, q)
        rows.append("{" + ", ".join("{" + ", ".join("%.17g" % x for x in r) + "}" for r in q) + "}")
    print("{" + ",\n ".join(rows) + "}" if which == "all" else rows[0])


if __name__ == "__main__":
    main()
