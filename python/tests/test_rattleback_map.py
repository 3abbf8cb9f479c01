"""docs/examples/rattleback_map.py: the rattleback study's table and figure from a runs.csv. The
fixture is a runs.csv written here (the columns the study writes, docs/ensembles.md §3) with
outcomes chosen so that each marker and table entry is exercised; what the table says must follow
from those rows."""

import csv
import os
import subprocess
import sys

import pytest

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "examples")
SCRIPT = os.path.join(EXAMPLES, "rattleback_map.py")
sys.path.insert(0, EXAMPLES)
import rattleback_map  # noqa: E402

COLUMNS = ["run", "start", "replica", "law", "contact.lambda", "initial.omega3", "reason", "spin_reversals",
           "t_first_reversal"]


def write_runs(path):
    rows = [
        # law, lambda, omega3, replica, reason, reversals, t_first
        ("exact", 1e9, 5, 0, "rest", 0, ""),
        ("exact", 1e9, 5, 1, "rest", 0, ""),
        ("exact", 1e12, 5, 0, "rest", 1, "3.01"),
        ("exact", 1e12, 5, 1, "rest", 1, "3.05"),
        ("ellipsoidal", 1e9, 5, 0, "max-steps", 0, ""),
        ("ellipsoidal", 1e9, 5, 1, "max-steps", 0, ""),
        ("ellipsoidal", 1e12, 5, 0, "rest", 1, "3.2"),
        ("ellipsoidal", 1e12, 5, 1, "rest", 0, ""),
    ]
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        for i, (law, lam, om, rep, reason, n, t1) in enumerate(rows):
            w.writerow([i, i // 2, rep, law, lam, om, reason, n, t1])


def test_the_table_gives_each_cells_outcome_and_separates_replicas_that_differ(tmp_path):
    runs = tmp_path / "runs.csv"
    write_runs(runs)
    cells = rattleback_map.load(str(runs))
    text = rattleback_map.table(cells, ["exact", "ellipsoidal"])
    exact, ellipsoidal = text.split("ellipsoidal:")
    assert "| +5 | rest | 1x at 3.01 \\| 1x at 3.05 |" in exact
    assert "| +5 | max-steps | 1x at 3.20 \\| rest |" in ellipsoidal


def test_the_script_writes_the_figure_and_prints_the_tables(tmp_path):
    pytest.importorskip("matplotlib", reason="the figure needs python3-matplotlib")
    runs = tmp_path / "runs.csv"
    write_runs(runs)
    png = tmp_path / "map.png"
    r = subprocess.run([sys.executable, SCRIPT, str(runs), str(png)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert png.stat().st_size > 1000
    assert r.stdout.count("| omega3 (1/s) \\ contact.lambda |") == 2


def test_wrong_arguments_give_the_usage_and_exit_2():
    r = subprocess.run([sys.executable, SCRIPT], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr.startswith("usage: rattleback_map.py")
