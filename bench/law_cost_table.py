#!/usr/bin/env python3
"""The cost table of docs/benchmarks.md: runs friction_bench once (every law and every pressure
spec, with repetitions) with JSON output and prints one markdown row per spec: the median time
per evaluation over the repetitions, its ratio to `pade-printed` from the same run, the spread of
the repetitions, and the benchmark's counters (largest error against `exact` in units of kN = k
times N and kNa = k N a, not kilonewtons; allocations).

    python3 bench/law_cost_table.py [--bench build/bench/friction_bench] [--repetitions 5]
                                    [--time cpu|real] [--filter REGEX] [--json out.json]
    python3 bench/law_cost_table.py --from-json out.json    # the table of a kept run again

Ratios between laws are meaningful within one run only (the machine may be shared): the median
of each law's repetitions is divided by the median of `pade-printed`'s in the same run.
"""

import argparse
import json
import platform
import re
import statistics
import subprocess
import sys
from datetime import datetime, timezone

BASELINE = "pade-printed"


def run_bench(bench, repetitions, filt, json_out):
    cmd = [bench, f"--benchmark_repetitions={repetitions}", "--benchmark_format=json"]
    if filt:
        cmd.append(f"--benchmark_filter={filt}")
    done = subprocess.run(cmd, check=True, capture_output=True, text=True)
    if json_out:
        with open(json_out, "w") as f:
            f.write(done.stdout)
    return cmd, json.loads(done.stdout)


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def fmt_time(ns):
    if ns >= 1e6:
        return f"{ns / 1e6:.3g} ms"
    if ns >= 1e3:
        return f"{ns / 1e3:.3g} us"
    return f"{ns:.3g} ns"


def counter(b, name, old_name):
    """A counter of the run; runs before 2026-11-28 named the errors without their unit."""
    return b.get(name, b.get(old_name))


def fmt_err(x):
    if x is None:
        return ""
    if x != x or x == float("inf"):
        return "inf"
    return "0" if x == 0 else f"{x:.2g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bench", default="build/bench/friction_bench")
    ap.add_argument("--repetitions", type=int, default=5)
    ap.add_argument("--time", choices=["cpu", "real"], default="cpu")
    ap.add_argument("--filter", default="BM_law/")
    ap.add_argument("--json", help="also keep the raw JSON of the run here")
    ap.add_argument("--from-json", help="print the table of a run kept with --json instead of running")
    args = ap.parse_args()
    if args.repetitions < 1:
        sys.exit("law_cost_table.py: error: --repetitions must be >= 1")

    if args.from_json:
        with open(args.from_json) as f:
            data = json.load(f)
        cmd = ["(kept run)", args.from_json]
        reps = max(b.get("repetitions", 1) for b in data["benchmarks"])
    else:
        cmd, data = run_bench(args.bench, args.repetitions, args.filter, args.json)
        reps = args.repetitions
    key = "cpu_time" if args.time == "cpu" else "real_time"
    runs = {}  # spec -> list of per-repetition results, in the benchmark's order
    order = []
    for b in data["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        spec = re.sub(r"/iterations:\d+$", "", b["run_name"].removeprefix("BM_law/"))
        if spec not in runs:
            runs[spec] = []
            order.append(spec)
        unit = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]]
        runs[spec].append((b[key] * unit, b))
    if BASELINE not in runs:
        sys.exit(f"law_cost_table.py: error: the run has no BM_law/{BASELINE} to compare with")
    median = {s: statistics.median(t for t, _ in r) for s, r in runs.items()}

    ctx = data.get("context", {})
    when = ctx.get("date") or datetime.now(timezone.utc).isoformat(timespec="minutes")
    print(f"Run of {when} on {ctx.get('host_name', platform.node())}: {cpu_model()}, {ctx.get('num_cpus', '?')} CPUs at "
          f"{ctx.get('mhz_per_cpu', '?')} MHz, load average {', '.join(f'{x:.1f}' for x in ctx.get('load_avg', []))} "
          f"at the start, {platform.system()} {platform.release()}.")
    print(f"Command: `{' '.join(cmd)}` (via `bench/law_cost_table.py`); {args.time.upper()} time per evaluation, "
          f"median of {reps} repetitions; ratio to the median of `{BASELINE}` in the same run.")
    print()
    print("| spec | time per evaluation | vs `pade-printed` | spread (min-max) | max err F1 / kN | max err F2 / kN "
          "| max err M / kNa | allocs per eval |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    base = median[BASELINE]
    for spec in order:
        times = [t for t, _ in runs[spec]]
        last = runs[spec][-1][1]
        inputs = last.get("inputs")
        timed = min(b.get("iterations", inputs or 0) for _, b in runs[spec]) if inputs else 0
        if inputs and timed < inputs:  # fewer evaluations than the set holds: its first ones only
            label = f"`{spec}` (first {timed} of {int(inputs)} inputs)"
        else:
            label = f"`{spec}`" + (f" ({int(inputs)} inputs)" if inputs and inputs < 4096 else "")
        ratio = median[spec] / base
        ratio_s = "1" if spec == BASELINE else (f"{ratio:,.0f}x" if ratio >= 100 else f"{ratio:.2g}x")
        print(f"| {label} | {fmt_time(median[spec])} | {ratio_s} | {fmt_time(min(times))} - {fmt_time(max(times))} "
              f"| {fmt_err(counter(last, 'max_err_F1_kN', 'max_err_F1'))} "
              f"| {fmt_err(counter(last, 'max_err_F2_kN', 'max_err_F2'))} "
              f"| {fmt_err(counter(last, 'max_err_M_kNa', 'max_err_M'))} "
              f"| {fmt_err(last.get('allocs_per_eval'))} |")


if __name__ == "__main__":
    main()
