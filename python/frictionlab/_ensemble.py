"""frictionlab.ensemble: a study file of runs (docs/ensembles.md), as ``frictionlab ensemble`` runs it."""

import csv
import os

import numpy as np

from . import _core

__all__ = ["ensemble", "EnsembleResult", "EnsembleInterrupted"]

# Wall-clock seconds between two looks at Python while the job runs (signals, progress callback).
_PROGRESS_INTERVAL = 0.05


def _column(values):
    """A runs.csv column: float64 array if every field reads as a number (an empty field: NaN),
    else the list of its texts."""
    try:
        return np.array([float(v) if v != "" else np.nan for v in values], dtype=np.float64)
    except ValueError:
        return list(values)


def read_runs(path):
    """runs.csv as {column: numpy.ndarray (numbers) or list of str (text)}, rows in file order."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    return {name: _column([r[i] if i < len(r) else "" for r in body]) for i, name in enumerate(header)}


class EnsembleResult:
    """What one :func:`ensemble` job left in its folder, as Python objects.

    Attributes
    ----------
    runs : dict of str -> numpy.ndarray or list of str
        runs.csv read back, one entry per column in the file's order (docs/ensembles.md §3):
        numeric columns as float64 arrays (an empty field is NaN), text columns (``law``,
        ``reason``, ``final_class``, ...) as lists of str. SI units: times in s (``t_final``,
        ``wall_time``), energies in J, angular velocities in 1/s. Every run in the folder, those of
        earlier sessions (``resume=True``) included; sorted by ``run`` once the study is complete.
    summary : dict
        This session: ``total`` (runs of the study), ``done_before`` (by earlier sessions),
        ``done_now``, ``failed_now`` (could not run), ``early_now`` (stopped early: a law's pole,
        max-steps, ...), ``remaining``, ``complete`` (every run is in runs.csv), ``interrupted``,
        ``output_error`` ("" if none), ``threads``, ``ranks``, ``wall_time`` (s),
        ``figure_errors`` (figures gnuplot could not draw), ``command`` (the equivalent command line).
    out : str
        The folder.
    runs_csv : str
        The path of runs.csv.
    report : str or None
        The path of report.md, written once the study is complete (None before).
    """

    def __init__(self, runs, summary, out, report):
        self.runs = runs
        self.summary = summary
        self.out = out
        self.runs_csv = os.path.join(out, "runs.csv")
        self.report = report

    @property
    def complete(self):
        """Every run of the study is in runs.csv (bool)."""
        return self.summary["complete"]

    def __getitem__(self, column):
        """``result["reason"]`` is ``result.runs["reason"]``."""
        return self.runs[column]

    def __repr__(self):
        s = self.summary
        return (f"<frictionlab.EnsembleResult {self.out!r}: {s['done_before'] + s['done_now']} of {s['total']} runs "
                f"done ({s['failed_now']} failed, {s['early_now']} stopped early this session)>")


class EnsembleInterrupted(KeyboardInterrupt):
    """Ctrl-C (KeyboardInterrupt) stopped an :func:`ensemble` job.

    The runs in flight stopped between integrator steps and were not recorded; the finished ones
    are in runs.csv, and ``ensemble(..., resume=True)`` continues. ``result`` (an
    :class:`EnsembleResult`) holds what ran.
    """

    def __init__(self, result):
        s = result.summary
        super().__init__(f"the ensemble was interrupted with {s['remaining']} of {s['total']} runs to do; "
                         "resume=True continues; what ran is in this exception's .result")
        self.result = result


def ensemble(study, out, *, threads=0, resume=False, figures=True, progress=None):
    """ensemble(study, out, *, threads=0, resume=False, figures=True, progress=None) -> EnsembleResult

    Runs a study file exactly as ``frictionlab ensemble STUDY --out OUT [--threads N] [--resume]
    [--no-figures]`` does (the same C++ job: the same runs.csv, manifest and report), then reads
    runs.csv back. SI units throughout (m, s, kg, N, rad).

    Parameters
    ----------
    study : str or os.PathLike
        The study file (TOML, docs/ensembles.md §1): a scenario, the laws, the varied keys (SI
        units), the design, the replicas.
    out : str or os.PathLike
        The output folder (created if needed): runs.csv, ensemble.json, report.md, figures/.
    threads : int
        Worker threads (0: one per core).
    resume : bool
        Continue the ensemble already in ``out``: only the runs not in its runs.csv are done.
        Without it an existing runs.csv is an error (nothing is overwritten).
    figures : bool
        Run gnuplot for the report's maps (False: their data and scripts only, like ``--no-figures``).
    progress : callable, optional
        ``progress(done, total)`` (runs finished, runs of the study) is called from the calling
        thread after runs finish (at most about every 0.05 s of wall time); returning False stops
        the job like Ctrl-C does (the result is returned, ``summary["interrupted"]`` True); an
        exception it raises stops the job and is raised again once the folder is closed.

    Returns
    -------
    EnsembleResult
        ``runs`` (runs.csv by column), ``summary`` (the session's counts), ``runs_csv``, ``report``.

    Raises
    ------
    ValueError
        A bad study (key, value, law) or folder, or threads < 0, with the command line's
        one-line message (naming the key and the rule); nothing is run or written.
    FileNotFoundError, PermissionError, IsADirectoryError
        The study file cannot be read (OSErrors, with the command line's message).
    EnsembleInterrupted
        Ctrl-C during the job (a KeyboardInterrupt): ``.result`` holds what ran.
    OutputError
        The folder or a file could not be written (an OSError; the runs recorded before stay in
        runs.csv).

    Runs that stop early (a law's pole, max-steps) or fail are results, in runs.csv with their
    reason, not errors. The GIL is released while the job runs, except for the moments it looks at
    signals and progress.
    """
    out = os.fspath(out)
    summary, report, pending = _core._run_ensemble(os.fspath(study), out, int(threads), bool(resume), bool(figures),
                                                   progress, _PROGRESS_INTERVAL)
    if summary["output_error"]:
        raise _core.OutputError(f"frictionlab ensemble: the output failed: {summary['output_error']}")
    runs_csv = os.path.join(out, "runs.csv")
    runs = read_runs(runs_csv) if os.path.exists(runs_csv) else {}
    result = EnsembleResult(runs, summary, out, report or None)
    if pending is not None:
        if isinstance(pending, KeyboardInterrupt):
            raise EnsembleInterrupted(result) from pending
        pending.frictionlab_result = result
        raise pending
    return result
