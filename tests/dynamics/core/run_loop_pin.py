#!/usr/bin/env python3
"""Regression pin of the one run loop (dynamics/core/run_loop.h): every shipped scenario, run
with every law (and, for the bodies, both contact models), must give the trajectory.csv columns
and summary.json values it gave before the loop was shared by the models: every
shipped scenario reproduces its trajectory bit for bit across that refactor.

The pinned values (reference/run_loop_pin.csv) were recorded by the frictionlab command built
from the commit before that refactor, not by the code under test:

    python3 tests/dynamics/core/run_loop_pin.py record BUILD/frictionlab \\
        tests/dynamics/core/reference/run_loop_pin.csv

and every run is checked against them with

    python3 tests/dynamics/core/run_loop_pin.py check BUILD/frictionlab PIN.csv [--scenario NAME]

This is a regression pin, not a physical check: it holds the numbers still. A change that moves
them on purpose (a better law, a new integrator default) records the pin again, in its own commit,
saying why. Only what the pin holds is compared: columns and keys added later are ignored.

Re-recorded since: `summary:rejected_steps` of the 44 runs whose steps start afresh after a jump of
the mode (the pucks, whose slip or spin stops and stays at zero; the bodies under `decoupled` and
`decoupled:r_spin=0`, whose slip or spin is held at zero): GSL zeroes its count of rejected steps
when the stepper is reset, and the summary had reported only the count since the last reset. The
count now goes on (dynamics/core/ode_stepping.cpp, FreeStepper::reset;
DynOdeStepping.RejectedStepsAreCountedAcrossResets); those rows were recorded again by the fixed
build, every other value is the first recording's.

What is pinned, per run: for each trajectory.csv column, the number of rows and a 64-bit FNV-1a
hash of the column's cells as written (so bit for bit: the command writes 17 significant digits);
every leaf of summary.json but the wall time and the scenario's path, as written by json.dumps.
The bodies run for 0.2 s sampled every 2 ms (the start of every motion: lift-offs,
the first slip and spin, the printed Pade law's first pole); the pucks run to their end (their
stops are located events; each takes milliseconds).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
SCENARIOS = os.path.join(REPO, "data", "scenarios")
LAWS = ["exact", "exact:pressure=uniform", "exact:pressure=punch", "pade-printed", "pade-printed-minor",
        "pade-reconstructed", "ellipsoidal", "mujoco-elliptic", "decoupled", "decoupled:r_spin=0"]
BODY_T_END = 0.2  # s
BODY_OUTPUT_DT = 0.002  # s
SKIPPED_KEYS = {"wall_time_s", "scenario.source"}
# The size of a body's trajectory.csv follows from its columns, which are pinned one by one: it grew
# when the body's `stick` column and its pose (x, y, qw..qz) were added (docs/dynamics.md §6),
# which the pin allows.
BODY_UNCOMPARED_KEYS = {"summary:output.trajectory_bytes"}
# Shipped scenarios the build that recorded the pin could not run (shapes other than bodies of
# revolution, docs/convex-bodies.md): not pinned; their physics is checked by DynConvexBodyMotion
# (docs/convex-bodies.md §12). Their DynRunLoopPin tests run nothing.
AFTER_THE_PIN = {"ellipsoid-case-a", "ellipsoid-long-axis", "disk-rolling-circle", "disk-spin-to-rest",
                 "rattleback-braked", "rattleback-reversal"}


def fnv1a64(texts):
    h = 0xcbf29ce484222325
    for t in texts:
        for byte in t.encode() + b"\n":
            h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return f"{h:016x}"


def is_puck(path):
    with open(path) as f:
        return any(line.split("#")[0].replace(" ", "").strip() == 'model="puck"' for line in f)


def runs(scenario_filter=None):
    for name in sorted(os.listdir(SCENARIOS)):
        if not name.endswith(".toml") or (scenario_filter and name[:-5] != scenario_filter):
            continue
        if name[:-5] in AFTER_THE_PIN:
            continue
        path = os.path.join(SCENARIOS, name)
        patches = [None] if is_puck(path) else ["section", "hertz"]
        for law in LAWS:
            for patch in patches:
                yield name[:-5], path, law, patch


def flatten(obj, prefix=""):
    if isinstance(obj, dict):
        for k, v in obj.items():
            yield from flatten(v, f"{prefix}.{k}" if prefix else k)
    else:
        yield prefix, json.dumps(obj)


def pinned_values(binary, path, law, patch):
    """The values a run pins: {key: text}."""
    with tempfile.TemporaryDirectory() as out:
        cmd = [binary, "simulate", path, "--law", law, "--out", out]
        if patch is not None:
            cmd += ["--set", f"contact.patch={patch}", "--set", f"run.output_dt={BODY_OUTPUT_DT}",
                    "--set", f"run.t_end={BODY_T_END}"]
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode not in (0, 3):
            raise RuntimeError(f"{' '.join(cmd)}: exit {p.returncode}: {p.stderr.strip()}")
        values = {}
        with open(os.path.join(out, "trajectory.csv"), newline="") as f:
            rows = list(csv.reader(f))
        header, body = rows[0], rows[1:]
        for i, column in enumerate(header):
            values[f"trajectory:{column}"] = f"rows={len(body)} fnv1a64={fnv1a64(r[i] for r in body)}"
        with open(os.path.join(out, "summary.json")) as f:
            for key, text in flatten(json.load(f)):
                if key not in SKIPPED_KEYS:
                    values[f"summary:{key}"] = text
        return values


def label(scenario, law, patch):
    return f"{scenario} --law {law}" + (f" --set contact.patch={patch}" if patch else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("mode", choices=["record", "check"])
    ap.add_argument("frictionlab", help="the frictionlab command")
    ap.add_argument("pin", help="the pin file (CSV: scenario, law, patch, key, value)")
    ap.add_argument("--scenario", help="only this shipped scenario (its name without .toml)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    a = ap.parse_args()
    todo = list(runs(a.scenario))
    if not todo and a.scenario in AFTER_THE_PIN:
        print(f"run_loop_pin: {a.scenario} was added after the pin was recorded: nothing pinned")
        return
    if not todo:
        sys.exit(f"run_loop_pin: error: no shipped scenario named {a.scenario!r} in {SCENARIOS}")
    with ThreadPoolExecutor(a.jobs) as ex:
        results = list(ex.map(lambda r: pinned_values(a.frictionlab, r[1], r[2], r[3]), todo))
    if a.mode == "record":
        with open(a.pin, "w", newline="") as f:
            w = csv.writer(f, lineterminator="\n")
            w.writerow(["scenario", "law", "patch", "key", "value"])
            for (scenario, _, law, patch), values in zip(todo, results):
                for key, value in values.items():
                    w.writerow([scenario, law, patch or "", key, value])
        print(f"run_loop_pin: recorded {len(todo)} runs into {a.pin}")
        return
    pinned = {}
    with open(a.pin, newline="") as f:
        for row in csv.DictReader(f):
            pinned.setdefault((row["scenario"], row["law"], row["patch"] or None), {})[row["key"]] = row["value"]
    failures = 0
    for (scenario, _, law, patch), values in zip(todo, results):
        expected = pinned.get((scenario, law, patch))
        if expected is None:
            print(f"FAIL {label(scenario, law, patch)}: not in the pin {a.pin}")
            failures += 1
            continue
        differ = [k for k, v in expected.items()
                  if values.get(k) != v and not (patch is not None and k in BODY_UNCOMPARED_KEYS)]
        if differ:
            failures += 1
            print(f"FAIL {label(scenario, law, patch)}: {len(differ)} of {len(expected)} pinned values differ")
            for k in differ[:8]:
                print(f"    {k}: pinned {expected[k]}, now {values.get(k, '(absent)')}")
    print(f"run_loop_pin: {len(todo) - failures} of {len(todo)} runs as pinned"
          + (f" ({a.scenario})" if a.scenario else ""))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
