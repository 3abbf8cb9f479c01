"""frictionlab.register_law: a friction law written in Python, known by name everywhere."""

import atexit

from . import _core

__all__ = ["register_law", "unregister_law"]

_registered = []


def register_law(name, f, *, summary, slow=False):
    """register_law(name, f, *, summary, slow=False)

    Adds a friction law written in Python to the registry, under ``name``: from then on
    ``Law(name)``, ``simulate(..., law=name)``, ``accuracy([name])`` and :func:`laws` know it,
    like a built-in law (the C++ counterpart is friction/registry.h's register_law()).

    Parameters
    ----------
    name : str
        A new name: letters, digits and ``._+-``, starting with a letter or digit; not a
        registered law's name (ValueError otherwise).
    f : callable
        ``f(U, Omega, a, b, psi, N, k) -> (F1, F2, M)``, called with Python floats for one
        contact in SI units (U m/s >= 0, Omega 1/s, a >= b > 0 m, psi rad, N >= 0 N, k >= 0),
        already checked like every law's input; returns F1, F2 in N and M in N m, with the
        conventions of :class:`Law` (force -F1 e1 - F2 e2, torque -M gamma). It must return
        finite numbers, or raise ValueError for a contact outside its domain (the message then
        reaches the caller as a ValueError, or a simulation's "law-error").
    summary : str
        One line: what the law is and where it comes from (shown by :func:`laws`).
    slow : bool
        True if a call takes milliseconds: the law is then left out of the default accuracy
        study and full grids.

    The law is called once per contact, taking the GIL each time: it works from any thread,
    including the accuracy study's workers, but runs one contact at a time, at Python's speed
    (about a microsecond of overhead per call, plus f itself). It stays registered until
    :func:`unregister_law` or the end of the interpreter.
    """
    if not callable(f):
        raise TypeError(f"register_law: f = {f!r} is not callable; expected f(U, Omega, a, b, psi, N, k)")
    _core._register_law(name, f, summary, bool(slow))
    _registered.append(name)


def unregister_law(name):
    """unregister_law(name) -> bool

    Removes a law added by :func:`register_law` (laws already made keep working). Returns False
    if no such law was registered; ValueError for a built-in law.
    """
    removed = _core._unregister_law(name)
    if name in _registered:
        _registered.remove(name)
    return removed


@atexit.register
def _unregister_all():
    # The registry is C++ and outlives the interpreter: let go of the Python functions first.
    for name in list(_registered):
        unregister_law(name)
