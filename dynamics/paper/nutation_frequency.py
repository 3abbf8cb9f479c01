#!/usr/bin/env python3
"""The nutation frequency of gamma3 in the runs of a `frictionlab paper` job, per 10-s window.

Reads DIR/runs/<egg>-<case>/<law>/trajectory.csv of a job run with --full-trajectories (every
sample: the default keeps every 50th, too coarse for this) and prints, for each run and each
window, half the rate at which gamma3 crosses its centred 1-s moving mean: the frequency of the
nutation, the fastest motion of the axis the sample interval must resolve (docs/experiments.md §1).
Python standard library only.

    build/frictionlab paper --out results/full --full-trajectories
    python3 dynamics/paper/nutation_frequency.py results/full [--laws exact]
"""
import argparse
import bisect
import csv
import pathlib
import sys

WINDOW = 10.0  # s, the windows over which crossings are counted
MEAN = 1.0     # s, the moving mean the crossings are taken about (removes the slow tilt)


def read(path):
    t, g = [], []
    with open(path, newline="") as f:
        rows = csv.reader(f)
        header = next(rows)
        it, ig = header.index("t"), header.index("gamma3")
        for row in rows:
            t.append(float(row[it]))
            g.append(float(row[ig]))
    return t, g


def moving_mean(t, g, width):
    prefix = [0.0]
    for x in g:
        prefix.append(prefix[-1] + x)
    out = []
    for ti in t:
        lo = bisect.bisect_left(t, ti - width / 2)
        hi = bisect.bisect_right(t, ti + width / 2)
        out.append((prefix[hi] - prefix[lo]) / (hi - lo))
    return out


def frequencies(t, g):
    m = moving_mean(t, g, MEAN)
    d = [a - b for a, b in zip(g, m)]
    out = []
    start = 0.0
    while start + WINDOW <= t[-1]:
        lo = bisect.bisect_left(t, start)
        hi = bisect.bisect_left(t, start + WINDOW)
        crossings = sum(1 for i in range(lo + 1, hi) if (d[i - 1] < 0) != (d[i] < 0))
        out.append((start, crossings / (2 * WINDOW)))
        start += WINDOW
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("job", type=pathlib.Path, help="the --out folder of a --full-trajectories job")
    p.add_argument("--laws", default="", help="comma-separated run labels to include (default: all)")
    a = p.parse_args()
    labels = set(a.laws.split(",")) if a.laws else None
    files = sorted(a.job.glob("runs/*/*/trajectory.csv"))
    if not files:
        sys.exit(f"nutation_frequency.py: error: no runs/*/*/trajectory.csv under {a.job}")
    print("run,window_start_s,nutation_hz")
    overall = 0.0
    for f in files:
        label = f.parent.name
        if labels is not None and label not in labels:
            continue
        t, g = read(f)
        if len(t) < 3 or t[-1] < WINDOW:
            continue  # shorter than one window (a run stopped at once)
        if t[1] - t[0] > 0.0101:
            print(f"nutation_frequency.py: skipping {f}: not every 0.01-s sample (run with --full-trajectories)",
                  file=sys.stderr)
            continue
        for start, hz in frequencies(t, g):
            print(f"{f.parent.parent.name}/{label},{start:g},{hz:.2f}")
            overall = max(overall, hz)
    print(f"# highest: {overall:.2f} Hz", file=sys.stderr)


if __name__ == "__main__":
    main()
