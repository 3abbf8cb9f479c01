"""frictionlab.simulate: one run of the body of revolution on the Hertz plane (docs/dynamics.md)."""

import json
import os
import tempfile

from . import _core
from ._toml import check_nesting, nesting, to_toml, toml_value

__all__ = ["simulate", "SimulationResult", "Interrupted"]

# Wall-clock seconds between two looks at Python from inside a run (signals, progress callback).
_PROGRESS_INTERVAL = 0.05


class SimulationResult:
    """What one run produced: what ``frictionlab simulate`` writes, as Python objects.

    Attributes
    ----------
    summary : dict
        summary.json as a dict: ``summary["termination"]["reason"]`` ("t_end", "rest",
        "rolling", "interrupted", ...), ``final_time`` (s), ``steps``, energies (J), the
        final state, the thresholds applied (docs/dynamics.md §6). Non-finite numbers are None.
    trajectory : dict of str -> numpy.ndarray
        One array per column of trajectory.csv, in its order (SI units, body frame): t (s),
        gamma1..3, omega1..3 (1/s), v1..3 (m/s), eps (m), N (N), U (m/s), Omega (1/s), F1, F2
        (N), M (N m), a, b (m), psi (rad), energy, kinetic, W_slide, W_spin (J), in_contact
        (bool), stick (bool: rolling without slip and spin, docs/dynamics.md §5), and the pose:
        x, y (m, the centre of mass on the plane, world axes), qw, qx, qy, qz (the orientation
        quaternion, body to world; left out with ``run.pose = false``). One element per sample (every run.output_dt seconds, and the
        final time).
    shadow : dict of str -> numpy.ndarray, or None
        With shadow laws (``shadow=[...]``), shadow.csv as arrays (docs/dynamics.md §10): t (s),
        phase (int: 0 airborne, 1 bouncing, 2 sliding, 3 rolling-spin, 4 near-rest), s, b_over_a,
        a (m), psi (rad), N (N), and per shadow law LAW ``dF1[LAW]``, ``dF2[LAW]`` (per k N),
        ``dM[LAW]`` (per k N a), ``dP[LAW]`` (W): the law's friction minus the run's own at each
        sample's contact. Its statistics are ``summary["shadow"]``. None without shadow laws.
    scenario_toml : str
        The resolved scenario (scenario.toml beside the run): rerunning it reproduces the run.
    out : str or None
        The folder holding trajectory.csv, summary.json and scenario.toml, if one was asked for.
    """

    def __init__(self, summary, trajectory, scenario_toml, out, shadow=None):
        self.summary = summary
        self.trajectory = trajectory
        self.shadow = shadow
        self.scenario_toml = scenario_toml
        self.out = out

    @property
    def reason(self):
        """Why the run ended (str): summary["termination"]["reason"]."""
        return self.summary["termination"]["reason"]

    @property
    def t(self):
        """Sample times, s (the trajectory's first column)."""
        return self.trajectory["t"]

    def __getitem__(self, column):
        """``result["gamma3"]`` is ``result.trajectory["gamma3"]``."""
        return self.trajectory[column]

    def __repr__(self):
        n = len(self.trajectory["t"])
        return (f"<frictionlab.SimulationResult {self.summary['scenario']['name']!r}: {self.reason} at "
                f"t = {self.summary['final_time']:.6g} s, {n} samples>")


class Interrupted(KeyboardInterrupt):
    """Ctrl-C (KeyboardInterrupt) stopped a run of :func:`simulate`.

    The run stopped between two integrator steps and its files and summary are whole, the
    summary's reason being "interrupted"; ``result`` (a :class:`SimulationResult`) holds what ran.
    A KeyboardInterrupt like any other: an unhandled one ends the script.
    """

    def __init__(self, result):
        super().__init__(f"the run was interrupted at t = {result.summary['final_time']:.6g} s; "
                         "what ran is in this exception's .result")
        self.result = result


def _override_list(overrides):
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        for k, v in overrides.items():  # the key's parts and the value nest (--set checks the same)
            check_nesting(str(k).count(".") + 1 + nesting(v), f"override {k}")
        return [f"{k}={toml_value(v, k)}" for k, v in overrides.items()]
    if isinstance(overrides, str):
        return [overrides]
    return [str(o) for o in overrides]


def _shadow_override(shadow):
    """run.shadow=[...] for a list of law specs (or one string holding a list); the scenario reader
    checks each spec, with an error naming run.shadow."""
    specs = [shadow] if isinstance(shadow, str) else [str(x) for x in shadow]
    return "run.shadow=" + toml_value(specs, "run.shadow")


def simulate(scenario, law=None, overrides=None, *, out=None, progress=None, shadow=None):
    """simulate(scenario, law=None, overrides=None, *, out=None, progress=None, shadow=None) -> SimulationResult

    Runs a scenario exactly as ``frictionlab simulate SCENARIO [--law LAW] [--set K=V]... --out
    OUT`` does (the same C++ code: the same summary, the same trajectory, bit for bit).

    Parameters
    ----------
    scenario : str, os.PathLike or dict
        A scenario file (TOML), or a dict shaped like one: ``{"name": ..., "body": {...},
        "contact": {...}, "initial": {...}, "run": {...}}`` with the keys, SI units and defaults
        of docs/dynamics.md §7. A dict is written as TOML (numbers to the last bit) and read by
        the same parser as a file, with the same checks.
    law : str, optional
        A law spec (see :func:`laws`), replacing contact.law, like ``--law``.
    overrides : dict or list of str, optional
        Keys to override, like ``--set``: ``{"run.t_end": 2.0}`` or ``["run.t_end=2"]``.
    out : str or os.PathLike, optional
        A folder to write trajectory.csv, summary.json and scenario.toml into (created if
        needed). Without it they go to a temporary folder, removed before returning.
    progress : callable, optional
        ``progress(t, t_end)`` (both in s) is called about every 0.05 s of wall time while the
        run goes; returning False stops it (reason "interrupted"); an exception it raises stops
        the run and is raised again once the run's files are written.
    shadow : list of str, optional
        Law specs evaluated along the run beside its own law without changing it, like
        ``--shadow`` (sets run.shadow): ``result.shadow`` holds shadow.csv as arrays and
        ``result.summary["shadow"]`` their statistics (docs/dynamics.md §10).

    Returns
    -------
    SimulationResult
        ``summary`` (dict, as summary.json), ``trajectory`` (dict of NumPy arrays by column).

    Raises
    ------
    ValueError
        A bad scenario, key, value or law, with the command line's message (naming the key, for
        a dict the dict's key, and the rule); nothing is run.
    TypeError
        A dict holding something a scenario cannot (None, a complex number, ...), naming its key.
    FileNotFoundError, PermissionError, IsADirectoryError
        The scenario file cannot be read (OSErrors, with the command line's message).
    Interrupted
        Ctrl-C during the run (a KeyboardInterrupt): ``.result`` holds what ran.
    OutputError
        The output folder or a file could not be written (an OSError).

    A run that stops early for a physical or numerical reason (a pole of the law, the chatter of
    a discontinuous law, a failed integrator, max-steps) is not an error: its summary says why (``result.reason``). The GIL is
    released while the run integrates, except for the moments it looks at signals and progress.
    """
    overrides = _override_list(overrides)
    if law is not None:
        # Like the command line's --law: a wrong spec is the argument's fault.
        try:
            _core.Law(law)
        except ValueError as e:
            raise ValueError(f"law {law}: {e}") from None
        overrides.append(f"contact.law={law}")
    if shadow is not None:
        overrides.append(_shadow_override(shadow))
    if isinstance(scenario, dict):
        path, text = None, to_toml(scenario)
        source = str(scenario.get("name", "scenario"))
    else:
        path, text, source = os.fspath(scenario), "", ""
    if out is not None:
        return _run(path, text, source, overrides, os.fspath(out), progress, keep=True)
    with tempfile.TemporaryDirectory(prefix="frictionlab-") as tmp:
        return _run(path, text, source, overrides, tmp, progress, keep=False)


def _run(path, text, source, overrides, out_dir, progress, keep):
    trajectory, pending = _core._run_scenario(path, text, source, overrides, out_dir, progress,
                                              _PROGRESS_INTERVAL)
    with open(os.path.join(out_dir, "summary.json"), encoding="utf-8") as f:
        summary = json.load(f)
    with open(os.path.join(out_dir, "scenario.toml"), encoding="utf-8") as f:
        scenario_toml = f.read()
    shadow = _read_shadow(os.path.join(out_dir, "shadow.csv")) if "shadow" in summary else None
    result = SimulationResult(summary, trajectory, scenario_toml, out_dir if keep else None, shadow)
    if pending is not None:
        if isinstance(pending, KeyboardInterrupt):
            raise Interrupted(result) from pending
        pending.frictionlab_result = result
        raise pending
    return result


def _read_shadow(path):
    """shadow.csv as a dict of NumPy arrays by column (its header may quote a law spec)."""
    import csv

    import numpy as np

    with open(path, encoding="utf-8", newline="") as f:
        header = next(csv.reader(f))
        rows = f.read().splitlines()
    data = np.loadtxt(rows, delimiter=",", ndmin=2) if rows else np.empty((0, len(header)))
    columns = {name: data[:, i].copy() for i, name in enumerate(header)}
    columns["phase"] = columns["phase"].astype(np.int8)
    return columns
