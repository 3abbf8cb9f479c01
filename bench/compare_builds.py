#!/usr/bin/env python3
"""Two builds of the frictionlab command on the same run, alternated: the speed of a change
measured as docs/benchmarks.md measures it. Each round runs every build once, in turn, so that a
drift of the machine falls on all of them alike; the report gives, per build, the median and the
least of the user CPU time of the process and of the run's own `wall_time_s` (summary.json), and
the ratios of the medians to the first build's.

    python3 bench/compare_builds.py --build before=OLD/frictionlab --build after=build/frictionlab \\
        [--set after:run.stick=false ...] [--scenario egg-printed-a] [--law exact] [--rounds 30]

`--set NAME:KEY=VALUE` passes `--set KEY=VALUE` to that build only (a key the other build does
not know, or a mode to switch off so that both take the same steps). The machine, the date and
the load average are printed with the table. Ratios mean something within one run only.
"""

import argparse
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
from datetime import datetime, timezone


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--build", action="append", required=True, metavar="NAME=PATH",
                   help="a build to time (the first is the reference)")
    p.add_argument("--set", action="append", default=[], metavar="NAME:KEY=VALUE",
                   help="an override for one build")
    p.add_argument("--scenario", default="egg-printed-a")
    p.add_argument("--law", default="exact")
    p.add_argument("--rounds", type=int, default=30)
    a = p.parse_args(argv)
    builds = {}
    for b in a.build:
        name, sep, path = b.partition("=")
        if not sep or not name or not path:
            p.error(f"--build '{b}': expected NAME=PATH")
        if not os.access(path, os.X_OK):
            p.error(f"--build '{b}': {path} is not an executable file")
        builds[name] = {"path": path, "sets": []}
    for s in a.set:
        name, sep, kv = s.partition(":")
        if not sep or name not in builds or "=" not in kv:
            p.error(f"--set '{s}': expected NAME:KEY=VALUE with NAME one of {', '.join(builds)}")
        builds[name]["sets"] += ["--set", kv]
    if a.rounds < 1:
        p.error(f"--rounds {a.rounds}: must be at least 1")
    return a, builds


def main(argv):
    a, builds = parse_args(argv)
    cpu = {n: [] for n in builds}
    wall = {n: [] for n in builds}
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(a.rounds):
            for name, b in builds.items():
                out = os.path.join(tmp, name)
                cmd = [b["path"], "simulate", a.scenario, "--law", a.law, *b["sets"], "--out", out]
                before = resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime
                subprocess.run(cmd, stdout=subprocess.DEVNULL, check=True)
                cpu[name].append(resource.getrusage(resource.RUSAGE_CHILDREN).ru_utime - before)
                with open(os.path.join(out, "summary.json")) as f:
                    wall[name].append(json.load(f)["wall_time_s"])
    ref = next(iter(builds))
    print(f"{a.scenario}, law {a.law}, {a.rounds} rounds; {platform.node()} {platform.machine()}, "
          f"{datetime.now(timezone.utc):%Y-%m-%d %H:%M} UTC, load average {os.getloadavg()[0]:.2f}")
    print("| build | user CPU, median (least) | wall_time_s, median (least) | CPU ratio | wall ratio |")
    print("|---|---|---|---|---|")
    for name in builds:
        c, w = statistics.median(cpu[name]), statistics.median(wall[name])
        print(f"| {name} | {c:.4f} s ({min(cpu[name]):.4f}) | {w:.4f} s ({min(wall[name]):.4f}) | "
              f"{c / statistics.median(cpu[ref]):.3f} | {w / statistics.median(wall[ref]):.3f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
