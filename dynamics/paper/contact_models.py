#!/usr/bin/env python3
"""Side-by-side comparison of the paper's runs under the two contact models (docs/contact-models.md §6).

Reads two jobs of `frictionlab paper`, one per contact model, e.g.

    build/frictionlab paper --out results/contact-section --laws exact,pade-reconstructed
    build/frictionlab paper --out results/contact-hertz --laws exact,pade-reconstructed \
        --set contact.patch=hertz --no-baseline
    python3 dynamics/paper/contact_models.py results/contact-section results/contact-hertz \
        --out results/contact-models

and writes, into --out: `table.md` (end time, reason, time to vertical, final gamma3 per run, and
the effect of the contact model beside the effect of the law and the chaos floor), one gnuplot
script and figure per egg (`gamma3-<egg>.gp`, `.png`: the 1-s mean of gamma3 against time for
each case, both models, both laws).

`--egg-table` prints, independently of the C++ code, the two models' patch shape and Hertz's
stiffness along the egg (lambda matched at the lower pole).

Divergence time: the first time the 1-s means of gamma3 of two runs differ by more than 0.05,
compared on the reference run's samples of gamma3.csv (every 0.1 s; the other run linearly
interpolated) up to the end of the shorter run (the definition of docs/experiments.md §2).
"""
import argparse
import bisect
import csv
import math
import os
import subprocess
import sys

DIVERGENCE = 0.05


def read_behaviour(job):
    with open(os.path.join(job, "behaviour.csv"), newline="") as f:
        return {(r["egg"], r["case"], r["label"]): r for r in csv.DictReader(f)}


def read_gamma3(job, egg, case, label):
    path = os.path.join(job, "runs", f"{egg}-{case}", label, "gamma3.csv")
    t, g, m = [], [], []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            t.append(float(r["t"]))
            g.append(float(r["gamma3"]))
            m.append(float(r["gamma3_mean_1s"]))
    return t, g, m


def interpolate(ts, ys, t):
    i = bisect.bisect_left(ts, t)
    if i <= 0:
        return ys[0]
    if i >= len(ts):
        return ys[-1]
    w = (t - ts[i - 1]) / (ts[i] - ts[i - 1])
    return ys[i - 1] + w * (ys[i] - ys[i - 1])


def divergence(ref, other):
    t_end = min(ref[0][-1], other[0][-1])
    for t, y in zip(ref[0], ref[2]):
        if t > t_end:
            break
        if abs(y - interpolate(other[0], other[2], t)) > DIVERGENCE:
            return t
    return None


def fmt(x, digits=4):
    if x is None or x == "":
        return "–"
    try:
        v = float(x)
    except ValueError:
        return str(x)
    return f"{v:.{digits}g}"


# --- The two models on the egg, independently of the C++ code: K and E by the arithmetic-geometric
# mean, the contact point by bisection. chi^2 = P(z) = 2 (z + 0.1)(z - 1.2)(z - 0.252) (docs/model.md).
def egg_radii(g3):
    """(R_meridian, R_parallel) where the upward vertical has third component g3 (analytic derivatives)."""
    r = [-0.1, 1.2, 0.252]
    e1 = sum(r); e2 = r[0] * r[1] + r[0] * r[2] + r[1] * r[2]; e3 = r[0] * r[1] * r[2]
    P = lambda z: 2 * (z ** 3 - e1 * z ** 2 + e2 * z - e3)
    P1 = lambda z: 2 * (3 * z ** 2 - 2 * e1 * z + e2)
    P2 = lambda z: 2 * (6 * z - 2 * e1)
    g = lambda z: P1(z) / math.sqrt(4 * P(z) + P1(z) ** 2)
    lo, hi = -0.1, 0.252
    if g3 >= 1.0:
        z = lo
    elif g3 <= -1.0:
        z = hi
    else:
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if g(mid) > g3:
                lo = mid
            else:
                hi = mid
        z = 0.5 * (lo + hi)
    s = math.sqrt(4 * P(z) + P1(z) ** 2)
    G = 2 * P(z) * P2(z) - P1(z) ** 2
    return s ** 3 / (2 * abs(G)), s / 2


def agm_KE(k):
    a, b, c, total, n = 1.0, math.sqrt(1 - k * k), k, 0.5 * k * k, 0
    while abs(c) > 1e-16 * a and n < 60:
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        n += 1
        total += 2 ** (n - 1) * c * c
    K = math.pi / (2 * a)
    return K, K * (1 - total)


def hertz(R_major, R_minor):
    """(mu, a^2/delta, S) of Hertz's ellipse by bisection on Johnson's B/A = ((a/b)^2 E - K)/(K - E)."""
    rho = R_major / R_minor
    if rho - 1 < 1e-9:
        return 1.0, R_major, 4.0 / 3.0 * math.sqrt(R_major)
    lo, hi = 1e-6, 1.0 - 1e-12
    for _ in range(200):
        mu = 0.5 * (lo + hi)
        K, E = agm_KE(math.sqrt(1 - mu * mu))
        if (E / mu ** 2 - K) / (K - E) > rho:
            lo = mu
        else:
            hi = mu
    mu = 0.5 * (lo + hi)
    K, E = agm_KE(math.sqrt(1 - mu * mu))
    e2 = 1 - mu * mu
    a2 = 2 * R_major * ((K - E) / e2) / K
    return mu, a2, 2 * math.pi / 3 * math.sqrt(a2) / K


def egg_table():
    """Hertz vs section on the egg, lambda matched at the lower pole (gamma3 = 1)."""
    S_ref = hertz(*sorted(egg_radii(1.0), reverse=True))[2]
    lines = ["| gamma3 | R_meridian (m) | R_parallel (m) | lambda_hertz/lambda | b/a section | b/a hertz | a_hertz/a_section at equal delta |",
             "|---|---|---|---|---|---|---|"]
    for g3 in (1.0, 0.97, 0.5, 0.0, -0.5, -0.97, -1.0):
        Rm, Rp = egg_radii(g3)
        Rmaj, Rmin = max(Rm, Rp), min(Rm, Rp)
        mu, a2, S = hertz(Rmaj, Rmin)
        lines.append(f"| {g3:g} | {Rm:.4f} | {Rp:.4f} | {S / S_ref:.4f} | {math.sqrt(Rmin / Rmaj):.4f} | {mu:.4f} | "
                     f"{math.sqrt(a2 / (2 * Rmaj)):.4f} |")
    return "\n".join(lines)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("section_job", nargs="?")
    p.add_argument("hertz_job", nargs="?")
    p.add_argument("--out")
    p.add_argument("--egg-table", action="store_true", help="print the two models' patch and stiffness on the egg and exit")
    p.add_argument("--laws", default="exact,pade-reconstructed")
    p.add_argument("--baseline", default="exact-tol1e-10", help="label of the section job's baseline run ('' for none)")
    a = p.parse_args()
    if a.egg_table:
        print(egg_table())
        return
    if not (a.section_job and a.hertz_job and a.out):
        p.error("give SECTION_JOB HERTZ_JOB --out DIR (or --egg-table)")
    laws = a.laws.split(",")
    os.makedirs(a.out, exist_ok=True)
    jobs = {"section": a.section_job, "hertz": a.hertz_job}
    beh = {m: read_behaviour(j) for m, j in jobs.items()}
    eggs = sorted({k[0] for k in beh["section"]}, key=lambda e: (e != "egg-printed", e))
    cases = sorted({k[1] for k in beh["section"]})

    rows = ["| egg | case | patch | law | reason | end (s) | to vertical (s) | final γ3 | lift-offs | W slide / spin (J) |",
            "|---|---|---|---|---|---|---|---|---|---|"]
    effects = ["| egg | case | Δ end: contact / law / floor (s) | Δ to vertical: contact / law (s) | "
               "final γ3: S-exact, H-exact, S-pade, H-pade | γ3 parts (s): contact / law / floor / contact under pade |",
               "|---|---|---|---|---|---|"]
    for egg in eggs:
        for case in cases:
            for model in ("section", "hertz"):
                for law in laws:
                    r = beh[model].get((egg, case, law))
                    if r is None:
                        continue
                    rows.append(f"| {egg} | {case} | {model} | {law} | {r['reason']} | {fmt(r['t_final_s'], 5)} | "
                                f"{fmt(r['t_vertical_s'])} | {fmt(r['gamma3_final_mean'], 3)} | {r['liftoffs']} | "
                                f"{fmt(r['work_sliding_J'], 4)} / {fmt(r['work_spinning_J'], 4)} |")
            S = beh["section"].get((egg, case, laws[0]))
            H = beh["hertz"].get((egg, case, laws[0]))
            SP = beh["section"].get((egg, case, laws[1]))
            HP = beh["hertz"].get((egg, case, laws[1]))
            B = beh["section"].get((egg, case, a.baseline)) if a.baseline else None

            def d(x, y, key):
                if x is None or y is None or x[key] == "" or y[key] == "":
                    return "–"
                return f"{float(y[key]) - float(x[key]):+.3g}"

            g = {}
            for name, model, label in (("S", "section", laws[0]), ("H", "hertz", laws[0]), ("SP", "section", laws[1]),
                                       ("HP", "hertz", laws[1]), ("B", "section", a.baseline)):
                try:
                    g[name] = read_gamma3(jobs[model], egg, case, label) if label else None
                except FileNotFoundError:
                    g[name] = None

            def div(x, y):
                if g.get(x) is None or g.get(y) is None:
                    return "–"
                t = divergence(g[x], g[y])
                return "never" if t is None else f"{t:.1f}"

            effects.append(
                f"| {egg} | {case} | {d(S, H, 't_final_s')} / {d(S, SP, 't_final_s')} / {d(S, B, 't_final_s')} | "
                f"{d(S, H, 't_vertical_s')} / {d(S, SP, 't_vertical_s')} | "
                f"{fmt(S and S['gamma3_final_mean'], 3)}, {fmt(H and H['gamma3_final_mean'], 3)}, "
                f"{fmt(SP and SP['gamma3_final_mean'], 3)}, {fmt(HP and HP['gamma3_final_mean'], 3)} | "
                f"{div('S', 'H')} / {div('S', 'SP')} / {div('S', 'B')} / {div('SP', 'HP')} |")
    with open(os.path.join(a.out, "table.md"), "w") as f:
        f.write("\n".join(rows) + "\n\n" + "\n".join(effects) + "\n")

    styles = {("section", laws[0]): 'lc rgb "black" dt 1 lw 1.5',
              ("hertz", laws[0]): 'lc rgb "#d62728" dt 1 lw 1.5',
              ("section", laws[1]): 'lc rgb "#1f77b4" dt 2 lw 1.5',
              ("hertz", laws[1]): 'lc rgb "#ff7f0e" dt 2 lw 1.5'}
    for egg in eggs:
        gp = [f'set terminal pngcairo size 1200,1000 font ",10"', f'set output "gamma3-{egg}.png"',
              f'set multiplot layout {len(cases)},1 title "{egg}: 1-s mean of gamma3, section vs hertz contact, two laws"',
              'set xlabel "t (s)"', 'set ylabel "gamma3 (1-s mean)"', 'set yrange [-1.05:1.05]', 'set key outside right',
              'set datafile separator ","']
        for case in cases:
            plots = []
            for model in ("section", "hertz"):
                for law in laws:
                    path = os.path.relpath(os.path.join(jobs[model], "runs", f"{egg}-{case}", law, "gamma3.csv"), a.out)
                    if os.path.exists(os.path.join(a.out, path)):
                        plots.append(f'"{path}" every ::1 using 1:3 with lines {styles[(model, law)]} title "{model}, {law}"')
            gp.append(f'set title "case {case}"')
            gp.append("plot " + ", \\\n     ".join(plots))
        gp.append("unset multiplot")
        script = os.path.join(a.out, f"gamma3-{egg}.gp")
        with open(script, "w") as f:
            f.write("\n".join(gp) + "\n")
        subprocess.run(["gnuplot", os.path.basename(script)], cwd=a.out, check=True)
    print(f"wrote {a.out}/table.md and {len(eggs)} figures", file=sys.stderr)


if __name__ == "__main__":
    main()
