"""A scenario given as a dict, written as TOML text for the C++ scenario reader (the one parser
of scenarios: a dict and a file are read by the same code, with the same checks and messages).

Numbers are written so that they read back to the same double: floats by ``repr`` (the shortest
text that round-trips), integers as integers. Only what a scenario holds is accepted: tables
(dicts), strings, booleans, numbers and lists of numbers or strings.
"""

import math
import numbers

__all__ = ["to_toml", "toml_value", "nesting", "check_nesting"]

# TOML integers are 64-bit signed: a larger Python int would fail in the parser, which could
# only name a line of the generated text; it is refused here, naming the key.
_INT_MIN, _INT_MAX = -2**63, 2**63 - 1


def _check_text(s, what):
    """Text that UTF-8 cannot hold (a lone surrogate) would fail on its way to the parser."""
    try:
        s.encode("utf-8")
    except UnicodeEncodeError:
        raise ValueError(f"{what} is invalid: it is not Unicode text (it holds a lone surrogate)") from None


def _key(k):
    if not isinstance(k, str):
        raise TypeError(f"scenario key {k!r} is invalid: keys must be strings")
    _check_text(k, f"scenario key {k!r}")
    if k and all(c.isalnum() and c.isascii() or c in "_-" for c in k):
        return k
    return _string(k)


def _string(s):
    out = ['"']
    for c in s:
        if c == '"':
            out.append('\\"')
        elif c == "\\":
            out.append("\\\\")
        elif ord(c) < 0x20 or ord(c) == 0x7F:
            out.append(f"\\u{ord(c):04X}")
        else:
            out.append(c)
    out.append('"')
    return "".join(out)


def toml_value(v, where="value"):
    """The TOML text of one value (str, bool, int, float, or a list of them)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        _check_text(v, f"scenario {where} = {v!r}")
        return _string(v)
    if isinstance(v, numbers.Integral):
        if not _INT_MIN <= int(v) <= _INT_MAX:
            raise ValueError(f"scenario {where} = {int(v)} is invalid: an integer must be within [-2^63, 2^63 - 1] "
                             "(TOML's 64 bits); write a larger number as a float")
        return str(int(v))
    if isinstance(v, numbers.Real):
        x = float(v)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)  # shortest round-trip text: "0.97", "1e-05", "1000.0"
    if isinstance(v, (list, tuple)) or hasattr(v, "tolist"):
        items = v.tolist() if hasattr(v, "tolist") else v
        if not isinstance(items, list):
            return toml_value(items, where)
        return "[" + ", ".join(toml_value(x, f"{where}[{i}]") for i, x in enumerate(items)) + "]"
    raise TypeError(f"scenario {where} = {v!r} is invalid: a scenario holds tables (dicts), strings, "
                    f"booleans, numbers and lists of them")


def nesting(value):
    """How many levels a value nests as TOML (dynamics/io/toml_nesting.h): each dict key and each
    list item one level below its container ({"run": {"t_end": 1}} is 2). Without recursion, so
    that any depth is measured."""
    deepest = 0
    todo = [(value, 0)]
    while todo:
        v, depth = todo.pop()
        if isinstance(v, dict):
            items = v.values()
        elif isinstance(v, (list, tuple)):
            items = v
        else:
            continue
        for item in items:
            deepest = max(deepest, depth + 1)
            todo.append((item, depth + 1))
    return deepest


def check_nesting(depth, where):
    """ValueError, as for a TOML file, if `depth` levels are too many to read back."""
    from . import _core  # the rule lives in the C++ reader

    _core._check_toml_nesting(depth, where)


def _table(d, path, lines):
    scalars = [(k, v) for k, v in d.items() if not isinstance(v, dict)]
    tables = [(k, v) for k, v in d.items() if isinstance(v, dict)]
    for k, v in scalars:
        where = ".".join(path + [str(k)])
        lines.append(f"{_key(k)} = {toml_value(v, where)}")
    for k, v in tables:
        sub = path + [str(k)]
        lines.append("")
        lines.append("[" + ".".join(_key(p) for p in sub) + "]")
        _table(v, sub, lines)


def to_toml(scenario):
    """TOML text of a scenario dict such as ``{"body": {...}, "contact": {...}, "run": {...}}``."""
    if not isinstance(scenario, dict):
        raise TypeError(f"a scenario must be a dict or a path, not {type(scenario).__name__}")
    check_nesting(nesting(scenario), "the scenario dict")  # before _table recurses into it
    lines = []
    _table(scenario, [], lines)
    return "\n".join(lines) + "\n"
