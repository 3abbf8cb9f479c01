"""frictionlab.ensemble against `frictionlab ensemble` (the command line, an independent process
running the same study): the same runs.csv but for the wall-time column, the counts the command
prints, its one-line errors, and stopping (progress, Ctrl-C) then resuming."""

import csv
import os
import re
import signal
import threading

import numpy as np
import pytest

import frictionlab
from conftest import bits, run_cli


@pytest.fixture(scope="session")
def studies():
    return os.path.join(os.environ["FRICTIONLAB_DATA_DIR"], "studies")


def rows_without_wall_time(path):
    """runs.csv as lists of fields, the wall_time field (the one that differs between two runs of
    the same ensemble) emptied; rows in file order."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    wall = rows[0].index("wall_time")
    for r in rows:
        r[wall] = ""
    return rows


def write_study(tmp_path, name, text):
    """A study of the egg of case a (data/scenarios/egg-printed-a.toml) with `text` appended."""
    scenario = os.path.join(os.environ["FRICTIONLAB_DATA_DIR"], "scenarios", "egg-printed-a.toml")
    path = tmp_path / name
    path.write_text(f'scenario = "{scenario}"\n{text}')
    return path


# 8 runs of the exact law, 6 s of motion each (about 0.1 s of wall time): long enough to stop.
EIGHT_REPLICAS = 'laws = ["exact"]\nset = ["run.t_end=6", "run.output_dt=0.1"]\nseed = 3\n[replicas]\ncount = 8\nsize = 1e-6\n'


def test_smoke_study_gives_the_command_lines_runs_csv(cli, studies, tmp_path):
    smoke = os.path.join(studies, "smoke.toml")
    done = run_cli(cli, "ensemble", smoke, "--out", tmp_path / "cli", "--threads", 1)
    result = frictionlab.ensemble(smoke, tmp_path / "py", threads=1)
    assert result.runs_csv == os.path.join(tmp_path / "py", "runs.csv")
    assert rows_without_wall_time(result.runs_csv) == rows_without_wall_time(tmp_path / "cli" / "runs.csv")
    # runs: the file read back, column by column (numbers bit for bit, text as is).
    expected = read_csv_columns_or_text(tmp_path / "cli" / "runs.csv")
    assert list(result.runs) == list(expected)
    assert len(result.runs["run"]) == 8
    for name, column in expected.items():
        if name == "wall_time":
            assert np.all(result.runs[name] >= 0)
        elif isinstance(column, list):
            assert result.runs[name] == column, name
        else:
            assert np.array_equal(bits(result.runs[name]), bits(column)), name
    # The summary: the counts the command prints.
    m = re.search(r"ensemble: (\d+) of (\d+) runs done \((\d+) this session: (\d+) failed, (\d+) stopped early\)",
                  done.stdout)
    assert m, done.stdout
    s = result.summary
    assert [s["done_before"] + s["done_now"], s["total"], s["done_now"], s["failed_now"], s["early_now"]] == \
        [int(g) for g in m.groups()]
    assert s["early_now"] == result.runs["final_class"].count("stopped") > 0  # the Padé law stops at its pole
    assert s["complete"] and not s["interrupted"] and s["remaining"] == 0 and s["threads"] == 1
    assert result.complete
    assert result.report == os.path.join(tmp_path / "py", "report.md")
    with open(result.report) as f, open(tmp_path / "cli" / "report.md") as g:
        assert f.readline() == g.readline()
    assert s["command"] == f"frictionlab ensemble {smoke} --out {tmp_path / 'py'} --threads 1"
    # The reference's runs carry the compared law as a shadow law (docs/ensembles.md §3): its
    # columns are numbers on the exact rows and NaN on the others.
    exact = np.array([law == "exact" for law in result.runs["law"]])
    for out in ("F_median", "F_p95", "F_max", "M_median", "M_max", "dE", "failures"):
        column = result.runs[f"shadow_{out}[pade-printed]"]
        assert np.all(np.isfinite(column[exact])) and np.all(np.isnan(column[~exact])), out
    assert np.all(result.runs["shadow_F_median[pade-printed]"][exact] > 0)


def read_csv_columns_or_text(path):
    """Like conftest.read_csv_columns, text columns kept as lists of str."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    out = {}
    for i, name in enumerate(rows[0]):
        values = [r[i] for r in rows[1:]]
        try:
            out[name] = np.array([float(v) if v else np.nan for v in values])
        except ValueError:
            out[name] = values
    return out


def test_bad_study_raises_the_command_lines_message_naming_the_key(cli, tmp_path):
    bad = write_study(tmp_path, "bad_key.toml", 'laws = ["exact"]\n[[vary]]\nkey = "contact.kk"\nvalues = [1]\n')
    done = run_cli(cli, "ensemble", bad, "--out", tmp_path / "cli", check=False)
    assert done.returncode == 1
    message = done.stderr.removeprefix("frictionlab: error: ").strip()
    with pytest.raises(ValueError) as e:
        frictionlab.ensemble(bad, tmp_path / "py")
    assert "contact.kk" in str(e.value)
    assert str(e.value) == message
    assert not (tmp_path / "py").exists(), "nothing may be written on bad input"
    with pytest.raises(FileNotFoundError, match="missing.toml"):
        frictionlab.ensemble(tmp_path / "missing.toml", tmp_path / "py")
    with pytest.raises(ValueError, match="--threads"):
        frictionlab.ensemble(bad, tmp_path / "py", threads=-1)


def test_progress_can_stop_the_job_and_resume_completes_it_like_the_command(cli, tmp_path):
    study = write_study(tmp_path, "eight.toml", EIGHT_REPLICAS)
    seen = []

    def stop_at_once(done, total):
        seen.append((done, total))
        return False

    out = tmp_path / "py"
    first = frictionlab.ensemble(study, out, threads=1, figures=False, progress=stop_at_once)
    assert len(seen) == 1 and 1 <= seen[0][0] < 8 and seen[0][1] == 8
    s = first.summary
    assert s["interrupted"] and not s["complete"] and first.report is None
    assert 1 <= s["done_now"] < 8 and s["remaining"] == 8 - s["done_now"]
    assert len(first.runs["run"]) == s["done_now"]
    with pytest.raises(ValueError, match="runs.csv"):
        frictionlab.ensemble(study, out, threads=1)  # a folder with runs.csv needs resume=True

    seen.clear()
    second = frictionlab.ensemble(study, out, threads=1, resume=True, figures=False,
                                  progress=lambda done, total: seen.append((done, total)))
    assert second.summary["done_before"] == s["done_now"]
    assert second.summary["done_before"] + second.summary["done_now"] == 8 and second.complete
    assert [d for d, _ in seen] == sorted(d for d, _ in seen) and all(t == 8 for _, t in seen)
    run_cli(cli, "ensemble", study, "--out", tmp_path / "cli", "--threads", 1, "--no-figures")
    assert rows_without_wall_time(second.runs_csv) == rows_without_wall_time(tmp_path / "cli" / "runs.csv")
    assert list(second.runs["run"]) == list(range(8))


def test_an_exception_in_progress_stops_the_job_and_is_raised(tmp_path):
    class Stop(Exception):
        pass

    def progress(done, total):
        raise Stop("enough")

    with pytest.raises(Stop) as e:
        frictionlab.ensemble(write_study(tmp_path, "eight.toml", EIGHT_REPLICAS), tmp_path / "py", threads=1,
                             figures=False, progress=progress)
    result = e.value.frictionlab_result
    assert result.summary["interrupted"] and not result.complete


def test_ctrl_c_stops_the_job_and_keeps_the_finished_runs(tmp_path):
    # Runs of 60 s of motion (about a second of wall time each); SIGINT comes at 0.3 s.
    study = write_study(tmp_path, "long.toml", EIGHT_REPLICAS.replace("run.t_end=6", "run.t_end=60"))
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(frictionlab.EnsembleInterrupted) as e:
            frictionlab.ensemble(study, tmp_path / "py", threads=1, figures=False)
    finally:
        timer.cancel()
    assert isinstance(e.value, KeyboardInterrupt)
    s = e.value.result.summary
    assert s["interrupted"] and not s["complete"] and s["remaining"] == 8 - s["done_now"] > 0
    assert len(read_csv_columns_or_text(tmp_path / "py" / "runs.csv")["run"]) == s["done_now"]


def test_the_docstring_names_the_units():
    assert "SI units" in frictionlab.ensemble.__doc__
    assert "SI units" in frictionlab.EnsembleResult.__doc__ and "(s)" in frictionlab.EnsembleResult.__doc__
