#!/usr/bin/env python3
"""The steady-circle tables of docs/convex-bodies.md §13: the disk of
data/scenarios/disk-rolling-circle.toml (started on the rigid steady circle) run for 0.3 s while the
plane stiffens (contact.lambda), while the ellipsoidal law's spin radius Rb shrinks, and while k
falls; one markdown row per run: the patch's major semi-axis a at the start, the largest deviation
of the lean beta(t) = asin(gamma3) from its start, the mean precession rate over the run (the
turning of the axis's horizontal projection, from the pose quaternion) against the rigid one, and
each deviation's ratio to the previous row's. The rigid precession rate is the start's
instantaneous one, (omega.gamma - omega3 gamma3)/(1 - gamma3^2), which for a start
omega = Omega gamma + s e3 is Omega itself: the closed form of steady_circle.h
(DynRollingDisk.ShippedScenarioStartsOnTheClosedFormCircle checks the start).

    python3 bench/disk_circle_table.py [--exe build/frictionlab] [--t-end 0.3]

The test DynRollingDisk (tests/dynamics/body/rolling_disk_test.cpp) checks the same convergence
against steady_circle.h directly, at a tighter integrator tolerance.
"""

import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

SCENARIO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "scenarios", "disk-rolling-circle.toml")


def run(exe, out, name, sets, law=None):
    folder = os.path.join(out, name)
    cmd = [exe, "simulate", SCENARIO, "--out", folder]
    if law:
        cmd += ["--law", law]
    for s in sets:
        cmd += ["--set", s]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode not in (0, 3):
        sys.exit(f"disk_circle_table: {' '.join(cmd)} failed ({done.returncode}): {done.stderr.strip()}")
    with open(os.path.join(folder, "trajectory.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def measures(rows):
    first = rows[0]
    beta0 = math.asin(first["gamma3"])
    g = [first["gamma1"], first["gamma2"], first["gamma3"]]
    w = [first["omega1"], first["omega2"], first["omega3"]]
    rigid = (sum(a * b for a, b in zip(w, g)) - w[2] * g[2]) / (1.0 - g[2] ** 2)
    turned, last = 0.0, None
    for r in rows:
        # the axis e3 in world axes, R(q) e3
        qw, qx, qy, qz = r["qw"], r["qx"], r["qy"], r["qz"]
        angle = math.atan2(2 * (qy * qz - qw * qx), 2 * (qx * qz + qw * qy))
        if last is not None:
            step = angle - last
            turned += step - 2 * math.pi * round(step / (2 * math.pi))
        last = angle
    span = rows[-1]["t"] - rows[0]["t"]
    tilt = max(abs(math.asin(r["gamma3"]) - beta0) for r in rows)
    return {"a": first["a"], "tilt": tilt, "precession": turned / span, "rigid": rigid, "t": rows[-1]["t"]}


def table(title, variants, exe, out, t_end):
    print(f"**{title}**")
    print()
    print("| run | a at the start (m) | max abs(beta - beta0) (rad) | ratio | mean precession (1/s) | "
          "(Omega - mean)/Omega | ratio |")
    print("| --- | --- | --- | --- | --- | --- | --- |")
    prev = None
    for name, sets, law in variants:
        m = measures(run(exe, out, name, sets + [f"run.t_end={t_end:g}"], law))
        rel = (m["rigid"] - m["precession"]) / m["rigid"]
        r1 = f"{prev['tilt'] / m['tilt']:.3g}" if prev else ""
        r2 = f"{prev['rel'] / rel:.3g}" if prev else ""
        ended = "" if abs(m["t"] - t_end) < 1e-9 else f" (ended at {m['t']:g} s)"
        print(f"| {name}{ended} | {m['a']:.3g} | {m['tilt']:.3g} | {r1} | {m['precession']:.6g} | {rel:.3g} | {r2} |")
        prev = dict(m, rel=rel)
    print()
    print(f"Rigid steady circle: Omega = {prev['rigid']:.6g} 1/s.")
    print()


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exe", default="build/frictionlab")
    p.add_argument("--t-end", type=float, default=0.3)
    a = p.parse_args()
    print(f"`{' '.join(sys.argv)}`")
    print()
    with tempfile.TemporaryDirectory() as out:
        table("exact law, k = 0.3: the plane stiffens",
              [(f"lambda = {l}", [f"contact.lambda={l}"], None) for l in ("1e7", "1e8", "1e9", "1e10", "1e11")],
              a.exe, out, a.t_end)
        table("ellipsoidal law, k = 0.3, lambda = 1e8: the spin radius Rb shrinks",
              [(f"Rb = {rb} m", ["contact.lambda=1e8"], f"ellipsoidal:Rb={rb}") for rb in ("1e-4", "1e-5", "1e-6")],
              a.exe, out, a.t_end)
        table("exact law, lambda = 1e9: k falls",
              [(f"k = {k}", ["contact.lambda=1e9", f"contact.k={k}"], None) for k in ("0.3", "0.2", "0.1", "0.09", "0.085")],
              a.exe, out, a.t_end)


if __name__ == "__main__":
    main()
