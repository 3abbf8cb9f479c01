"""frictionlab.simulate: the command line's run, bit for bit; dicts; interrupts; progress."""

import json
import os
import signal
import threading
import tomllib

import numpy as np
import pytest

import frictionlab
from conftest import bits, read_csv_columns, run_cli

# Fields of summary.json that measure the machine, not the run.
TIMING = ("wall_time_s",)


def without_timing(summary):
    return {k: v for k, v in summary.items() if k not in TIMING}


def assert_same_trajectory(result, csv_columns):
    assert list(result.trajectory) == list(csv_columns)
    for name, column in csv_columns.items():
        got = result.trajectory[name]
        if name in ("in_contact", "stick", "slip_held"):
            assert got.dtype == bool
            np.testing.assert_array_equal(got, column != 0)
        else:
            assert got.dtype == np.float64
            np.testing.assert_array_equal(bits(got), bits(column), err_msg=name)


@pytest.mark.parametrize("scenario,sets", [
    ("sphere-sliding.toml", []),
    ("egg-printed-a.toml", ["run.t_end=0.5"]),
    ("egg-homogeneous-b.toml", ["run.t_end=0.3", "contact.law=pade-printed-minor"]),
    ("ellipsoid-case-a.toml", ["run.t_end=0.2"]),
    ("disk-rolling-circle.toml", ["run.t_end=0.2", "contact.patch=hertz", "contact.lambda_gamma3=0"]),
])
def test_simulate_equals_the_command_line_bit_for_bit(cli, scenarios, tmp_path, scenario, sets):
    path = os.path.join(scenarios, scenario)
    args = ["simulate", path, "--out", tmp_path / "cli"]
    for s in sets:
        args += ["--set", s]
    run_cli(cli, *args)
    result = frictionlab.simulate(path, overrides=sets)
    with open(tmp_path / "cli" / "summary.json") as f:
        expected = json.load(f)
    assert without_timing(result.summary) == without_timing(expected)
    assert_same_trajectory(result, read_csv_columns(tmp_path / "cli" / "trajectory.csv"))
    assert result.scenario_toml == (tmp_path / "cli" / "scenario.toml").read_text()
    assert result.out is None
    assert result.t[-1] == result.summary["final_time"]


def test_out_writes_the_command_lines_files(cli, scenarios, tmp_path):
    path = os.path.join(scenarios, "sphere-spinning.toml")
    run_cli(cli, "simulate", path, "--law", "coulomb-decoupled", "--set", "run.t_end=0.2", "--out", tmp_path / "cli")
    result = frictionlab.simulate(path, law="coulomb-decoupled", overrides={"run.t_end": 0.2}, out=tmp_path / "py")
    assert result.out == str(tmp_path / "py")
    for name in ("trajectory.csv", "scenario.toml"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    with open(tmp_path / "py" / "summary.json") as f:
        assert without_timing(json.load(f)) == without_timing(result.summary)


def test_shadow_laws_come_back_as_arrays_like_the_command_lines_shadow_csv(cli, scenarios, tmp_path):
    # A sphere spinning in place: U = 0 throughout, so every law's force error is exactly 0, and
    # the run's own law against itself is exactly right at every sample (docs/dynamics.md §10).
    path = os.path.join(scenarios, "sphere-spinning.toml")
    run_cli(cli, "simulate", path, "--shadow", "exact,ellipsoidal", "--set", "run.t_end=0.2", "--out",
            tmp_path / "cli")
    result = frictionlab.simulate(path, overrides={"run.t_end": 0.2}, shadow=["exact", "ellipsoidal"],
                                  out=tmp_path / "py")
    for name in ("trajectory.csv", "shadow.csv"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    shadow = result.shadow
    assert list(shadow)[:7] == ["t", "phase", "s", "b_over_a", "a", "psi", "N"]
    np.testing.assert_array_equal(shadow["t"], result.t)
    assert shadow["phase"].dtype == np.int8
    assert set(shadow["phase"]) == {3}  # rolling-spin: no slip, spinning
    for out in ("dF1", "dF2", "dM", "dP"):
        np.testing.assert_array_equal(shadow[f"{out}[exact]"], 0.0)
        assert np.all(shadow[f"{out}[ellipsoidal]"] == 0.0) or out in ("dM", "dP")
    laws = [law["law"] for law in result.summary["shadow"]["laws"]]
    assert laws == ["exact", "ellipsoidal"]
    assert frictionlab.simulate(path, overrides={"run.t_end": 0.05}).shadow is None


def test_a_bad_shadow_law_is_the_scenario_readers_error(scenarios):
    path = os.path.join(scenarios, "sphere-spinning.toml")
    with pytest.raises(ValueError, match="run.shadow"):
        frictionlab.simulate(path, shadow=["no-such-law"])


def test_a_dict_runs_like_the_file_it_was_read_from(cli, scenarios, tmp_path):
    path = os.path.join(scenarios, "egg-printed-a.toml")
    with open(path, "rb") as f:
        scenario = tomllib.load(f)
    run_cli(cli, "simulate", path, "--set", "run.t_end=0.4", "--out", tmp_path / "cli")
    result = frictionlab.simulate(scenario, overrides={"run.t_end": 0.4})
    assert_same_trajectory(result, read_csv_columns(tmp_path / "cli" / "trajectory.csv"))
    with open(tmp_path / "cli" / "summary.json") as f:
        expected = without_timing(json.load(f))
    got = without_timing(result.summary)
    # Only where the scenario came from differs.
    assert got["scenario"]["source"] == "egg-printed-a" and expected["scenario"]["source"] == path
    del got["scenario"]["source"], expected["scenario"]["source"]
    assert got == expected


def test_bad_input_raises_the_command_lines_message(cli, scenarios, tmp_path):
    path = os.path.join(scenarios, "sphere-sliding.toml")
    done = run_cli(cli, "simulate", path, "--set", "run.t_end=-1", "--out", tmp_path / "x", check=False)
    assert done.returncode == 1
    message = done.stderr.removeprefix("frictionlab: error: ").strip()
    with pytest.raises(ValueError) as e:
        frictionlab.simulate(path, overrides=["run.t_end=-1"])
    assert str(e.value) == message
    with pytest.raises(ValueError, match="unknown key run.bogus"):
        frictionlab.simulate(path, overrides={"run.bogus": 1})
    done = run_cli(cli, "simulate", path, "--law", "nope", "--out", tmp_path / "x", check=False)
    with pytest.raises(ValueError) as e:
        frictionlab.simulate(path, law="nope")
    assert str(e.value) == done.stderr.removeprefix("frictionlab: error: --").strip()
    with pytest.raises(ValueError, match="body"):
        frictionlab.simulate({"name": "empty"})
    with pytest.raises(TypeError):
        frictionlab.simulate({"run": {"t_end": object()}})


def test_progress_is_called_and_can_stop_the_run(scenarios):
    path = os.path.join(scenarios, "egg-printed-a.toml")
    seen = []

    def progress(t, t_end):
        seen.append((t, t_end))
        return len(seen) < 3

    # Sampled every 1e-3 s (as the file did until 2026-11-28): the run lasts long enough (~1 s of
    # wall time) for three calls 0.05 s apart.
    result = frictionlab.simulate(path, overrides={"run.output_dt": 1e-3}, progress=progress)
    assert len(seen) == 3
    assert all(t_end == 1000.0 for _, t_end in seen)
    assert [t for t, _ in seen] == sorted(t for t, _ in seen)
    assert result.reason == "interrupted"
    assert result.t[-1] == result.summary["final_time"] >= seen[-1][0]
    assert len(result.t) == result.summary["output"]["trajectory_rows"]


def test_an_exception_in_progress_stops_the_run_and_is_raised(scenarios):
    class Stop(Exception):
        pass

    def progress(t, t_end):
        raise Stop("enough")

    with pytest.raises(Stop) as e:
        frictionlab.simulate(os.path.join(scenarios, "egg-printed-a.toml"), progress=progress)
    assert e.value.frictionlab_result.reason == "interrupted"


def test_ctrl_c_stops_the_run_and_keeps_what_ran(scenarios, tmp_path):
    # egg-printed-a runs ~120 s of simulated time (about a second of wall time when sampled every
    # 1e-3 s, as the file did until 2026-11-28); SIGINT comes at 0.3 s.
    timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(frictionlab.Interrupted) as e:
            frictionlab.simulate(os.path.join(scenarios, "egg-printed-a.toml"), overrides={"run.output_dt": 1e-3},
                                 out=tmp_path)
    finally:
        timer.cancel()
    result = e.value.result
    assert isinstance(e.value, KeyboardInterrupt)
    assert result.reason == "interrupted"
    assert 0 < result.summary["final_time"] < 120
    assert result.t[-1] == result.summary["final_time"]
    with open(tmp_path / "summary.json") as f:
        assert json.load(f)["termination"]["reason"] == "interrupted"
    assert_same_trajectory(result, read_csv_columns(tmp_path / "trajectory.csv"))


DEEP = 40000  # toml++ recursed out of the stack at this depth and the interpreter died


def test_deeply_nested_input_raises_value_error_not_a_crash(scenarios, tmp_path):
    rule = "nested more than 64 levels deep"
    dotted = ".".join(["a"] * DEEP)
    for name, text in [("table", f"[{dotted}]\nx = 1\n"), ("dotted", f"{dotted} = 1\n"),
                       ("arrays", "x = " + "[" * DEEP + "]" * DEEP + "\n")]:
        path = tmp_path / f"{name}.toml"
        path.write_text(text)
        with pytest.raises(ValueError, match=rule):
            frictionlab.simulate(path)
    # A dict nested as deeply is refused before it is written as TOML (whose writer recurses).
    deep = {"x": 1}
    for _ in range(DEEP):
        deep = {"a": deep}
    with pytest.raises(ValueError, match="the scenario dict: " + rule):
        frictionlab.simulate(deep)
    nested_list = 1
    for _ in range(DEEP):
        nested_list = [nested_list]
    path = os.path.join(scenarios, "sphere-sliding.toml")
    with pytest.raises(ValueError, match="override run.x: " + rule):
        frictionlab.simulate(path, overrides={"run.x": nested_list})
    with pytest.raises(ValueError, match=rule):
        frictionlab.simulate(path, overrides=[dotted + "=1"])


@pytest.mark.parametrize("scenario", ["ellipsoid-case-a.toml", "ellipsoid-long-axis.toml", "disk-rolling-circle.toml",
                                      "disk-spin-to-rest.toml"])
def test_convex_scenarios_run(scenarios, scenario):
    """The shipped shapes other than bodies of revolution run from Python, with their pose."""
    result = frictionlab.simulate(os.path.join(scenarios, scenario), overrides={"run.t_end": 0.1})
    assert result.summary["termination"]["reason"] == "t_end"
    assert result.summary["body"]["shape"] in ("ellipsoid", "toroidal-disk")
    q = np.stack([result.trajectory[c] for c in ("qw", "qx", "qy", "qz")])
    np.testing.assert_allclose(np.linalg.norm(q, axis=0), 1.0, rtol=0, atol=1e-15)
    assert len(result.summary["final_state"]["position"]) == 2
    # The centre of mass moves on the plane as its world velocity says (x' = (R(q) v)_x): a rolling
    # disk covers ground, the others at most drift.
    assert np.all(np.isfinite(result.trajectory["x"]))


def test_without_the_pose_the_rest_is_the_same(scenarios):
    """run.pose = false leaves the pose's columns out and every other column as it was, bit for bit."""
    path = os.path.join(scenarios, "disk-spin-to-rest.toml")
    with_pose = frictionlab.simulate(path, overrides={"run.t_end": 0.2})
    without = frictionlab.simulate(path, overrides={"run.t_end": 0.2, "run.pose": False})
    pose_columns = {"x", "y", "qw", "qx", "qy", "qz"}
    assert pose_columns <= set(with_pose.trajectory)
    assert not pose_columns & set(without.trajectory)
    assert list(without.trajectory) == [c for c in with_pose.trajectory if c not in pose_columns]
    for name, column in without.trajectory.items():
        np.testing.assert_array_equal(column, with_pose.trajectory[name], err_msg=name)
    assert "position" not in without.summary["final_state"]
    assert without.summary["steps"] == with_pose.summary["steps"]
