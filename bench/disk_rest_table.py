#!/usr/bin/env python3
"""The approach-to-rest table of docs/convex-bodies.md §13: Euler's disk
(data/scenarios/disk-spin-to-rest.toml) run once with every friction law that `frictionlab laws`
lists, and one markdown row per law from the run's summary.json: how the run ended (reason, time),
the tilt of the axis from the vertical at the end (the disk's plane against the table), the kinetic
energy left, the share of the dissipated work done against spinning, the least N/(m g), and the
wall time of the run.

    python3 bench/disk_rest_table.py [--exe build/frictionlab] [--out DIR] [--laws exact,ellipsoidal]
                                     [--t-end-for exact-reference=1] [--set KEY=VALUE ...]

exact-reference (nested adaptive 2-D quadrature, the slow cross-check of `exact`: ~20 ms a
right-hand side here, the whole run would take ~1.7 h) is bounded by default to its first 0.05 s
(`--t-end-for exact-reference=0.05`; the table says "bounded"), and its end state is compared with
`exact` run over the same span.
Every run writes its folder under --out (default: a temporary folder, removed afterwards).
"""

import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import tomllib

SCENARIO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "scenarios", "disk-spin-to-rest.toml")
# Laws too slow for the whole run on a workstation: t_end (s) unless --t-end-for says otherwise.
DEFAULT_BOUNDS = {"exact-reference": 0.05}  # ~22 s of CPU; the whole run would take ~1.7 h


def law_names(exe):
    """The registered laws: the unindented lines of `frictionlab laws` after its heading."""
    text = subprocess.run([exe, "laws"], check=True, capture_output=True, text=True).stdout
    lines = text.splitlines()[1:]
    return [line.split()[0] for line in lines if line and not line[0].isspace()]


def run(exe, law, out, sets, t_end, tag=""):
    folder = os.path.join(out, law + tag)
    cmd = [exe, "simulate", SCENARIO, "--law", law, "--out", folder, "--set", "run.output_dt=0.01"]
    for s in sets:
        cmd += ["--set", s]
    if t_end is not None:
        cmd += ["--set", f"run.t_end={t_end:g}"]
    # Exit status 3: the run stopped early (an outcome here, recorded like any other).
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode not in (0, 3):
        sys.exit(f"disk_rest_table: {' '.join(cmd)} failed ({done.returncode}): {done.stderr.strip()}")
    with open(os.path.join(folder, "summary.json")) as f:
        return folder, json.load(f)


def kinetic(summary, state):
    m = summary["body"]["mass"]
    J = summary["body"]["inertia"]
    v, w = state["v"], state["omega"]
    Jw = [sum(J[i][j] * w[j] for j in range(3)) for i in range(3)]
    return 0.5 * m * sum(x * x for x in v) + 0.5 * sum(a * b for a, b in zip(w, Jw))


def start_state(folder):
    """The start as the scenario written beside the run says (summary.json has only the end)."""
    with open(os.path.join(folder, "scenario.toml"), "rb") as f:
        initial = tomllib.load(f)["initial"]
    return {"omega": initial["omega"], "v": initial["v"]}


def no_negative_zero(text):
    """A number that rounds to zero is written without a sign ("-0.00" would read as a negative)."""
    return text[1:] if text.startswith("-") and not any(c in "123456789" for c in text.split("e")[0]) else text


def row(law, s, k_start, bounded):
    fs = s["final_state"]
    g, w = fs["gamma"], fs["omega"]
    tilt = math.degrees(math.acos(min(1.0, abs(g[2]) / math.sqrt(sum(x * x for x in g)))))
    w_total = s["work_sliding"] + s["work_spinning"]
    spin_share = s["work_spinning"] / w_total if w_total > 0 else float("nan")
    reason = s["termination"]["reason"]
    if bounded and reason == "t_end":
        reason += " (bounded)"
    omega_n = sum(a * b for a, b in zip(w, g))
    return (f"| `{law}` | {reason} | {s['final_time']:.4g} | {tilt:.3g} | {kinetic(s, fs) / k_start:.3g} | "
            f"{no_negative_zero(f'{omega_n:.3g}')} | {w_total:.3g} | {no_negative_zero(f'{spin_share:.2f}')} | "
            f"{s['min_N_over_mg']:.3f} | {s['wall_time_s']:.2g} |")


def compare(x, y):
    def diff(key):
        d = math.sqrt(sum((a - b) ** 2 for a, b in zip(x[key], y[key])))
        return d / math.sqrt(sum(b * b for b in y[key]))
    return (f"|gamma - gamma_exact| = {diff('gamma'):.2g}, |omega - omega_exact|/|omega_exact| = {diff('omega'):.2g}, "
            f"|v - v_exact|/|v_exact| = {diff('v'):.2g}")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--exe", default="build/frictionlab")
    p.add_argument("--out", default=None, help="keep the runs' folders here")
    p.add_argument("--laws", default=None, help="comma-separated; default: every law of `frictionlab laws`")
    p.add_argument("--t-end-for", action="append", default=[], metavar="LAW=SECONDS",
                   help="bound one law's run (default exact-reference=0.05)")
    p.add_argument("--set", action="append", default=[], help="an override of every run, as `simulate --set`")
    a = p.parse_args()
    bounds = dict(DEFAULT_BOUNDS)
    for item in a.t_end_for:
        law, _, value = item.partition("=")
        bounds[law] = float(value)
    laws = a.laws.split(",") if a.laws else law_names(a.exe)
    with tempfile.TemporaryDirectory() as tmp:
        out = a.out or tmp
        print(f"Euler's disk (disk-spin-to-rest) per law: `{' '.join(sys.argv)}`")
        print()
        print("| law | end | t (s) | axis from vertical at the end (deg) | kinetic energy at the end / at the start | "
              "omega.gamma at the end (1/s) | work of friction (J) | of it against spin | least N/(m g) | wall (s) |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        messages, summaries = [], {}
        for law in laws:
            folder, s = run(a.exe, law, out, a.set, bounds.get(law))
            summaries[law] = s
            print(row(law, s, kinetic(s, start_state(folder)), law in bounds))
            if s["termination"]["message"]:
                messages.append(f"* `{law}`: {s['termination']['message']}")
        print()
        print("\n".join(messages))
        for law in laws:
            if law in bounds and law != "exact":
                _, ref = run(a.exe, "exact", out, a.set, bounds[law], tag=f"-to-{bounds[law]:g}")
                print(f"* `{law}` against `exact` at t = {bounds[law]:g} s: "
                      f"{compare(summaries[law]['final_state'], ref['final_state'])}")


if __name__ == "__main__":
    main()
