"""The Python module's overheads, measured against the C++ code it wraps (not a test: figures go
to docs/python.md with the machine and date).

    PYTHONPATH=build/python /usr/bin/python3 python/bench/bench_python.py [--build build] [--n 1000000]

1. Vectorised law evaluation: frictionlab.Law(law)(U, Omega, ...) on n contacts against the
   same contacts in a plain C++ loop over FrictionLaw::evaluate (python/bench/batch_loop.cpp,
   built with the benchmarks as build/python/bench/batch_loop). Target for exact: within 1.2x.
2. Per-call overhead of a scalar call: Python's time per call with float arguments minus the
   C++ loop's time per contact, for a cheap law (coulomb-decoupled) and for exact.
3. simulate() against `frictionlab simulate` on egg case a (data/scenarios/egg-printed-a.toml,
   its full run to rolling, sampled every 1e-3 s as the file did until 2026-11-28: 120 000
   samples, each copied into the arrays), both writing the same files. Target: within 1.1x.

Each figure is the best of --repeats runs (wall time; the machine is shared).
"""

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np

import frictionlab

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def contacts(n, seed=1):
    """n contacts spread over the laws' domain (slip ratios 1e-3..1e3, axis ratios 0.05..1)."""
    rng = np.random.default_rng(seed)
    a = 10.0 ** rng.uniform(-3, -2, n)
    omega = rng.choice([-1.0, 1.0], n) * 10.0 ** rng.uniform(0, 2, n)
    return np.stack([
        10.0 ** rng.uniform(-3, 3, n) * a * np.abs(omega),  # U = s a |Omega|
        omega,
        a,
        a * rng.uniform(0.05, 1.0, n),
        rng.uniform(0, np.pi, n),
        rng.uniform(1, 100, n),
        rng.uniform(0.1, 1.0, n),
    ], axis=1)


def best(f, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return min(times)


def cxx_loop(batch_loop, law, table, repeats):
    with tempfile.NamedTemporaryFile(suffix=".f64") as f:
        table.tofile(f.name)
        out = subprocess.run([batch_loop, law, f.name, str(repeats)], capture_output=True, text=True, check=True)
    seconds, checksum = out.stdout.split()
    return float(seconds), float(checksum)


def vectorised(batch_loop, law_name, n, repeats):
    table = contacts(n)
    law = frictionlab.Law(law_name)
    cols = [np.ascontiguousarray(table[:, i]) for i in range(7)]
    # Alternate the two, so that a slow moment of the shared machine hits both.
    py_times, cxx_times = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        F1, F2, M = law(*cols)
        py_times.append(time.perf_counter() - t0)
        seconds, checksum = cxx_loop(batch_loop, law_name, table, 1)
        cxx_times.append(seconds)
    ours = float(np.sum(F1 + F2 + M))  # summed in another order: a sanity check, not equality
    assert abs(ours - checksum) <= 1e-9 * abs(checksum), (ours, checksum)
    return min(py_times), min(cxx_times)


def scalar_overhead(batch_loop, law_name, calls, repeats):
    table = contacts(calls, seed=2)
    law = frictionlab.Law(law_name)
    rows = [tuple(float(x) for x in r) for r in table]
    py_times, cxx_times = [], []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for r in rows:
            law(*r)
        py_times.append(time.perf_counter() - t0)
        cxx_times.append(cxx_loop(batch_loop, law_name, table, 1)[0])
    return min(py_times) / calls, min(cxx_times) / calls


# The sample interval of the simulate comparison: the samples are what Python copies.
OUTPUT_DT = 1e-3


def simulate_vs_cli(cli, scenario, repeats):
    with tempfile.TemporaryDirectory() as tmp:
        def run_cli():
            subprocess.run([cli, "simulate", scenario, "--set", f"run.output_dt={OUTPUT_DT}", "--out",
                            os.path.join(tmp, "cli")], check=True,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

        def run_py():
            frictionlab.simulate(scenario, overrides={"run.output_dt": OUTPUT_DT}, out=os.path.join(tmp, "py"))

        # Alternate, so that a slow moment of the shared machine hits both.
        cli_times, py_times = [], []
        for _ in range(repeats):
            cli_times.append(best(run_cli, 1))
            py_times.append(best(run_py, 1))
        result = frictionlab.simulate(scenario, overrides={"run.output_dt": OUTPUT_DT})
    return min(py_times), min(cli_times), result


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", default=os.path.join(ROOT, "build"), help="frictionlab's build folder")
    p.add_argument("--n", type=int, default=1_000_000, help="contacts of the vectorised call")
    p.add_argument("--calls", type=int, default=100_000, help="scalar calls")
    p.add_argument("--repeats", type=int, default=3)
    args = p.parse_args()
    batch_loop = os.path.join(args.build, "python", "bench", "batch_loop")
    cli = os.path.join(args.build, "frictionlab")
    scenario = os.path.join(ROOT, "data", "scenarios", "egg-printed-a.toml")
    for f in (batch_loop, cli):
        if not os.access(f, os.X_OK):
            sys.exit(f"bench_python.py: {f} is missing: build frictionlab with FRICTIONLAB_BUILD_BENCHMARKS=ON")

    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    print(f"# {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; {cpu}, {os.cpu_count()} cores; "
          f"Python {platform.python_version()} ({sys.executable}), NumPy {np.__version__}")

    print(f"\n## Vectorised evaluation, {args.n:.0e} contacts (best of {args.repeats})")
    print("| law | Python (s) | C++ loop (s) | ratio |\n|---|---|---|---|")
    for law in ("exact", "coulomb-decoupled"):
        py, cxx = vectorised(batch_loop, law, args.n, args.repeats)
        print(f"| {law} | {py:.3f} | {cxx:.3f} | {py / cxx:.3f} |")

    print(f"\n## Scalar calls, {args.calls:.0e} calls (best of {args.repeats})")
    print("| law | Python per call (us) | C++ per contact (us) | overhead per call (us) |\n|---|---|---|---|")
    for law in ("coulomb-decoupled", "exact"):
        py, cxx = scalar_overhead(batch_loop, law, args.calls, args.repeats)
        print(f"| {law} | {py * 1e6:.3f} | {cxx * 1e6:.3f} | {(py - cxx) * 1e6:.3f} |")

    print(f"\n## simulate() against the command line, egg case a (best of {args.repeats})")
    py, cli_s, result = simulate_vs_cli(cli, scenario, args.repeats)
    print("| run | Python (s) | command line (s) | ratio |\n|---|---|---|---|")
    print(f"| egg-printed-a ({result.reason} at t = {result.summary['final_time']:.4g} s, "
          f"{result.summary['steps']} steps, {len(result.t)} samples) | {py:.3f} | {cli_s:.3f} | {py / cli_s:.3f} |")


if __name__ == "__main__":
    main()
