"""frictionlab from Python: laws of coupled dry friction over an elliptic Hertz contact patch,
the rigid body of revolution they drive, and the accuracy study.

SI units everywhere (m, s, kg, N, rad). The functions run the same compiled code as the
``frictionlab`` command line, so their numbers are the command line's to the last bit.

* :func:`laws` lists the friction laws; :class:`Law` evaluates one over NumPy arrays.
* :func:`simulate` runs a scenario (a TOML file, or a dict shaped like one) and returns its
  summary and trajectory (:class:`SimulationResult`).
* :func:`accuracy` compares laws with the exact one on a grid (:class:`AccuracyResult`).
* :func:`ensemble` runs a study file of many runs (:class:`EnsembleResult`).
* :func:`register_law` adds a law written in Python, usable by name everywhere a law is.
* :class:`OutputError` (an OSError): a file or folder of the results could not be written.

docs/python.md is the guide; docs/model.md states the conventions (the directions e1, e2, the
sign of the spin).
"""

from ._version import __version__
from ._core import Law, OutputError, law_specs, laws
from ._simulate import Interrupted, SimulationResult, simulate
from ._accuracy import AccuracyResult, accuracy
from ._ensemble import EnsembleInterrupted, EnsembleResult, ensemble
from ._custom_law import register_law, unregister_law

__all__ = [
    "__version__",
    "Law",
    "laws",
    "law_specs",
    "OutputError",
    "simulate",
    "SimulationResult",
    "Interrupted",
    "accuracy",
    "AccuracyResult",
    "ensemble",
    "EnsembleResult",
    "EnsembleInterrupted",
    "register_law",
    "unregister_law",
]
