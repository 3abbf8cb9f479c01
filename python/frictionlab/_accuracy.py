"""frictionlab.accuracy: laws against the exact one on a grid (docs/accuracy.md)."""

import numpy as np

from . import _core

__all__ = ["accuracy", "AccuracyResult"]


class AccuracyResult:
    """The accuracy study's numbers as arrays.

    Every law's F1/(kN), F2/(kN), M/(kNa) depends only on the slip ratio s = U/(a|Omega|), the
    axis ratio mu = b/a, the orientation psi and sign(Omega); the study evaluates the laws at
    a = 1 m, b = mu m, U = s m/s, Omega = sign 1/s, N = 1 N, k = 1, so values are per kN (forces)
    and per kNa (moment), dimensionless.

    Attributes
    ----------
    s, mu, psi : numpy.ndarray
        The grid's nodes: slip ratios (log-spaced), axis ratios, orientations (rad).
    sign : numpy.ndarray
        The signs of Omega, [-1, 1].
    reference : str
        The reference law ("exact").
    values : dict of str -> dict of str -> numpy.ndarray
        ``values[law]["F1"|"F2"|"M"]``, shape (len(mu), len(psi), 2, len(s)) in that index
        order; the reference law included.
    errors : dict of str -> dict of str -> dict
        ``errors[law]["F1"|"F2"|"M"]``: max_abs, rms, median_abs, p95_abs of value - reference
        over the finite points, and the counts finite, nonfinite.
    laws : list of str
        The laws compared, in order.
    summaries : dict of str -> dict
        Per law: ``summary`` (the registry's line), ``dissipation_violations`` (points with
        F1 U + M Omega < 0), ``singular_points``, ``seconds`` (wall time of its evaluation).
    """

    def __init__(self, raw):
        self.s = raw["s"]
        self.mu = raw["mu"]
        self.psi = raw["psi"]
        self.sign = raw["sign"]
        self.reference = raw["reference"]
        self.values = {self.reference: raw["reference_values"]}
        self.errors = {}
        self.summaries = {}
        self.laws = []
        for entry in raw["laws"]:
            name = entry["law"]
            self.laws.append(name)
            self.values[name] = entry["values"]
            self.errors[name] = entry["errors"]
            self.summaries[name] = {k: entry[k] for k in
                                    ("summary", "dissipation_violations", "singular_points", "seconds")}

    def error(self, law, component):
        """value - reference of `law`'s `component` ("F1", "F2" or "M") at every grid point,
        shape (len(mu), len(psi), 2, len(s)); per kN or per kNa."""
        return self.values[law][component] - self.values[self.reference][component]

    def grid(self):
        """The grid as four arrays of the values' shape: s, mu, psi, sign at every point."""
        mu, psi, sign, s = np.meshgrid(self.mu, self.psi, self.sign, self.s, indexing="ij")
        return s, mu, psi, sign

    def __repr__(self):
        shape = (len(self.mu), len(self.psi), 2, len(self.s))
        return f"<frictionlab.AccuracyResult {self.laws} against {self.reference!r} on a grid {shape}>"


def accuracy(laws=None, *, s_points=200, mu_points=20, psi_points=25, s_min=1e-3, s_max=1e3,
             mu_min=0.05, threads=0):
    """accuracy(laws=None, *, s_points=200, mu_points=20, psi_points=25, s_min=1e-3, s_max=1e3, mu_min=0.05, threads=0) -> AccuracyResult

    Runs the accuracy study of ``frictionlab accuracy`` (the same code) and returns its values
    and error statistics as arrays instead of writing tables.

    Parameters
    ----------
    laws : str or list of str, optional
        Laws to compare with the reference ("exact"); default: every registered law that is
        neither the reference nor slow, laws registered from Python included.
    s_points, mu_points, psi_points : int
        Grid sizes: slip ratios log-spaced over [s_min, s_max] (>= 2); axis ratios evenly over
        [mu_min, 1] (>= 2); orientations evenly over [0, pi] rad (odd, >= 3).
    s_min, s_max : float
        Range of the slip ratio U/(a|Omega|), dimensionless, 0 < s_min < s_max.
    mu_min : float
        Smallest axis ratio b/a, in (0, 1).
    threads : int
        Worker threads (0: one per hardware thread).

    Raises ValueError (naming the value and the rule) for a bad grid or law, RuntimeError if a
    law fails at a grid point (naming the point).
    """
    if laws is None:
        laws = []
    elif isinstance(laws, str):
        laws = [laws]
    for name, n in (("s_points", s_points), ("mu_points", mu_points), ("psi_points", psi_points),
                    ("threads", threads)):
        if int(n) != n or n < 0:
            raise ValueError(f"{name} = {n!r} is invalid: a count must be a whole number >= 0")
    raw = _core._accuracy(list(laws), int(s_points), int(mu_points), int(psi_points), float(s_min),
                          float(s_max), float(mu_min), int(threads))
    return AccuracyResult(raw)
