"""docs/examples/path_on_plane.py, animate_run.py and their run_pose.py: the pose read right
(closed forms for the heading, the body's height and its contact point, the quaternion against
the run's gamma), the figures written and valid, the limits (frames, .mp4 without ffmpeg) one
clear line."""

import os
import subprocess
import sys

import numpy as np
import pytest

from conftest import run_cli

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from PIL import Image
except ImportError as e:  # the examples need python3-matplotlib (and python3-pil, its dependency)
    pytest.skip(f"the figure examples need matplotlib and Pillow: {e}", allow_module_level=True)

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "docs", "examples")
sys.path.insert(0, EXAMPLES)
import animate_run  # noqa: E402
import path_on_plane  # noqa: E402
import run_pose  # noqa: E402

PATH_SCRIPT = os.path.join(EXAMPLES, "path_on_plane.py")
ANIMATE_SCRIPT = os.path.join(EXAMPLES, "animate_run.py")

# Rounding of a few products of quaternion components.
ROUNDING = 1e-12
# R(q)^T e_z against the gamma columns, integrated apart (docs/convex-bodies.md §11: equal to the
# integration's accuracy; 5e-9 seen over 60 s of ellipsoid-case-a). The convention is what is
# checked: the transposed R gives differences of order 1.
POSE_VS_GAMMA = 1e-6
# A body of revolution's lowest point is searched on its meridian to ~1e-6 of its size (run_pose.revolution).
SAMPLED_PROFILE = 1e-6


def turn(axis, angle):
    """The unit quaternion (w, x, y, z) of a turn by angle (rad) about a unit axis."""
    return np.concatenate([[np.cos(angle / 2)], np.sin(angle / 2) * np.asarray(axis, float)])


def cli_run(cli, scenarios, folder, scenario, t_end):
    """A run of a shipped scenario by the command line: (folder, columns, summary)."""
    run_cli(cli, "simulate", os.path.join(scenarios, scenario), "--set", f"run.t_end={t_end}", "--out", folder)
    columns, summary = run_pose.read_run(folder)
    return str(folder), columns, summary


@pytest.fixture(scope="module")
def ellipsoid_run(cli, scenarios, tmp_path_factory):
    """3 s of ellipsoid-case-a (output_dt = 0.01 s)."""
    return cli_run(cli, scenarios, tmp_path_factory.mktemp("ellipsoid-run"), "ellipsoid-case-a.toml", 3)


def run_script(*args, env=None):
    return subprocess.run([sys.executable, *map(str, args)], capture_output=True, text=True,
                          env=dict(os.environ, MPLBACKEND="Agg") if env is None else env)


# --- the pose ---------------------------------------------------------------------------------

@pytest.mark.parametrize("theta", np.linspace(-3.1, 3.1, 13))
def test_heading_of_a_turn_about_the_vertical_is_its_angle(theta):
    assert path_on_plane.heading_from_quaternion(turn([0, 0, 1], theta)) == pytest.approx(theta, abs=ROUNDING)


@pytest.mark.parametrize("alpha", [-2.5, -0.7, 0.3, 1.5707963267948966, 3.0])
def test_turn_about_e1_keeps_heading_zero_and_e1_in_the_plane(alpha):
    q = turn([1, 0, 0], alpha)
    assert path_on_plane.heading_from_quaternion(q) == pytest.approx(0.0, abs=ROUNDING)
    np.testing.assert_allclose(run_pose.e1_on_plane(q), [1, 0], atol=ROUNDING)


@pytest.mark.parametrize("beta", [-1.2, 0.4, 1.3, 2.0, -2.8])
def test_tilting_e1_about_e2_shortens_its_tick_by_the_cosine(beta):
    # e1 turned about y: (cos beta, 0, -sin beta); beyond a right angle it points backwards.
    q = turn([0, 1, 0], beta)
    np.testing.assert_allclose(run_pose.e1_on_plane(q), [np.cos(beta), 0], atol=ROUNDING)
    want = 0.0 if np.cos(beta) > 0 else np.pi
    assert abs(path_on_plane.heading_from_quaternion(q)) == pytest.approx(want, abs=ROUNDING)


def test_rotation_matrix_turns_the_world_vertical_into_the_runs_gamma(ellipsoid_run):
    _, columns, _ = ellipsoid_run
    R = run_pose.rotation_matrix(run_pose.quaternions(columns))
    gamma = np.stack([columns["gamma1"], columns["gamma2"], columns["gamma3"]], axis=-1)
    np.testing.assert_allclose(R[:, 2, :], gamma, atol=POSE_VS_GAMMA)  # R^T e_z is R's last row


# --- path_on_plane.py -------------------------------------------------------------------------

def test_path_drawn_runs_from_the_first_to_the_last_sample(ellipsoid_run):
    _, columns, _ = ellipsoid_run
    fig, ax = plt.subplots()
    drawn = path_on_plane.plot_path(ax, columns, ticks=7)
    segments = drawn["path"].get_segments()
    x, y = columns["x"], columns["y"]
    assert len(segments) == len(x) - 1
    np.testing.assert_array_equal(segments[0][0], [x[0], y[0]])
    np.testing.assert_array_equal(segments[-1][1], [x[-1], y[-1]])
    np.testing.assert_array_equal(drawn["start"].get_xydata()[0], [x[0], y[0]])
    np.testing.assert_array_equal(drawn["end"].get_xydata()[0], [x[-1], y[-1]])
    # 7 ticks at t = 0, 0.5, ..., 3 s (output_dt = 0.01 s), each from the sample's (x, y).
    ticks = drawn["ticks"].get_segments()
    starts = np.array([s[0] for s in ticks])
    idx = [int(round(k * 50)) for k in range(7)]
    np.testing.assert_array_equal(starts, np.column_stack([x[idx], y[idx]]))
    plt.close(fig)


def test_path_on_plane_runs_a_scenario_and_writes_a_png(tmp_path):
    out, keep = tmp_path / "path.png", tmp_path / "run"
    done = run_script(PATH_SCRIPT, "ellipsoid-case-a", "2", "-o", out, "--keep-run", keep)
    assert done.returncode == 0, done.stderr
    with Image.open(out) as im:
        assert im.format == "PNG" and im.size == (700, 600)
    columns, summary = run_pose.read_run(keep)
    assert columns["t"][-1] == 2.0 and summary["scenario"]["name"] == "ellipsoid-case-a"


def test_path_on_plane_draws_a_run_folder(ellipsoid_run, tmp_path):
    folder, _, _ = ellipsoid_run
    done = run_script(PATH_SCRIPT, "--run", folder, "-o", tmp_path / "p.png")
    assert done.returncode == 0, done.stderr
    with Image.open(tmp_path / "p.png") as im:
        assert im.format == "PNG"


def test_path_on_plane_names_a_missing_run_folder_in_one_line(tmp_path):
    done = run_script(PATH_SCRIPT, "--run", tmp_path / "nothing", "-o", tmp_path / "p.png")
    assert done.returncode == 1
    assert done.stderr.count("\n") == 1 and done.stderr.startswith("path_on_plane.py: error: ")
    assert "trajectory.csv" in done.stderr


# --- run_pose.py: the body at its pose --------------------------------------------------------

@pytest.mark.parametrize("gamma", [[0, 0, 1], [1, 0, 0], [0, -1, 0], [0.48, -0.6, 0.64]])
def test_ellipsoid_centre_height_is_its_support(gamma):
    a, eps = np.array([0.2, 0.17, 0.14]), -3e-5
    body = run_pose.ellipsoid(a)
    want = eps + np.sqrt(np.sum((a * gamma) ** 2))  # the ellipsoid's support, closed form
    assert body.centre_height(np.array(gamma, float), eps) == pytest.approx(want, abs=ROUNDING)


@pytest.mark.parametrize("gamma,want", [([0, 0, 1], 0.003), ([0, 0, -1], 0.003), ([1, 0, 0], 0.023),
                                        ([0.6, 0, 0.8], 0.02 * 0.6 + 0.003)])
def test_toroidal_disk_centre_height_is_rim_plus_tube(gamma, want):
    body = run_pose.toroidal_disk(0.02, 0.003)
    assert body.centre_height(np.array(gamma, float), 0.0) == pytest.approx(want, abs=ROUNDING)


@pytest.mark.parametrize("gamma", [[0, 0, 1], [0, 0, -1], [0.6, 0, 0.8], [0, 0.28, -0.96]])
def test_sphere_with_offset_mass_centre_height(gamma):
    # The tippe top: a sphere of radius r, its centre of mass c below the centre on the axis;
    # the centre of mass stands at r + c gamma3 (+ eps) whatever the turn.
    r, c, eps = 0.015, -0.003, -1e-6
    body = run_pose.revolution([r * r, 0.0, -1.0], -r, r, com=[0, 0, c])
    assert body.centre_height(np.array(gamma, float), eps) == pytest.approx(r + c * gamma[2] + eps,
                                                                            abs=SAMPLED_PROFILE * r)


def test_drawn_ellipsoid_touches_the_plane_at_eps_below_the_runs_centre(ellipsoid_run):
    # The lowest point of the ellipsoid, closed form -A^2 gamma / |A gamma| from the gamma
    # column, put at the pose of the quaternion, is at height eps and the centre over (x, y).
    folder, columns, summary = ellipsoid_run
    body = run_pose.read_body(folder, summary)
    assert body.kind == "ellipsoid"
    a = np.array(summary["body"]["parameters"]["semi_axes"])
    for k in [0, len(columns["t"]) // 2, len(columns["t"]) - 1]:
        q = run_pose.quaternions(columns)[k]
        gamma = np.array([columns["gamma1"][k], columns["gamma2"][k], columns["gamma3"][k]])
        centre, R = run_pose.pose_world(body, q, columns["x"][k], columns["y"][k], columns["eps"][k])
        np.testing.assert_array_equal(centre[:2], [columns["x"][k], columns["y"][k]])
        lowest = -a * a * gamma / np.sqrt(np.sum((a * gamma) ** 2))
        world = run_pose.to_world(body, lowest[None, :], centre, R)[0]
        assert world[2] == pytest.approx(columns["eps"][k], abs=POSE_VS_GAMMA * a.max())


def test_body_of_revolution_read_from_a_run_stands_on_its_pole(cli, scenarios, tmp_path):
    # The printed egg (summary.json: chi2, z_lo = -0.1 m, com at 0) upright: its lowest point is
    # the pole z_lo, so the centre of mass is -z_lo above eps.
    _, _, summary = cli_run(cli, scenarios, tmp_path, "egg-printed-a.toml", 0.01)
    body = run_pose.read_body(str(tmp_path), summary)
    assert body.kind == "revolution"
    z_lo = summary["body"]["z_lo"]
    assert body.centre_height(np.array([0.0, 0.0, 1.0]), -2e-5) == pytest.approx(-2e-5 - z_lo, abs=ROUNDING)


def test_sphere_lowest_point_is_minus_radius_gamma_in_every_direction():
    r = 0.05
    gamma = np.random.default_rng(7).normal(size=(500, 3))
    gamma /= np.linalg.norm(gamma, axis=1)[:, None]
    gamma[:2] = [[0, 0, 1], [0, 0, -1]]  # the poles, where the meridian is steepest in z
    lowest = run_pose.revolution([r * r, 0.0, -1.0], -r, r).lowest(gamma)
    np.testing.assert_allclose(lowest, -r * gamma, atol=SAMPLED_PROFILE * r)


@pytest.mark.parametrize("alpha", [0.0, 0.4, 1.2, 2.9])
def test_toroidal_disk_lowest_point_is_below_the_rim(alpha):
    # Leaning by alpha about e2: gamma = (sin alpha, 0, cos alpha); the rim's lowest point is
    # -R e1 - rho gamma for alpha > 0; flat (alpha = 0) the centre of the face, -rho gamma.
    R, rho = 0.02, 0.003
    gamma = np.array([np.sin(alpha), 0.0, np.cos(alpha)])
    want = (-R if alpha > 0 else 0.0) * np.array([1.0, 0, 0]) - rho * gamma
    np.testing.assert_allclose(run_pose.toroidal_disk(R, rho).lowest(gamma), want, atol=ROUNDING)


def test_sphere_touches_straight_below_its_centre(cli, scenarios, tmp_path):
    # A homogeneous sphere (sphere-sliding: radius 0.05 m, com at the centre): the contact point's
    # path is the centre of mass's, whatever the turn.
    folder, columns, summary = cli_run(cli, scenarios, tmp_path, "sphere-sliding.toml", 0.3)
    body = run_pose.read_body(folder, summary)
    contact = run_pose.contact_on_plane(body, columns)
    np.testing.assert_allclose(contact, np.column_stack([columns["x"], columns["y"]]),
                               atol=SAMPLED_PROFILE * 0.05)


def test_tippe_top_touches_off_its_centre_of_mass_by_the_tilted_offset(cli, scenarios, tmp_path):
    # A sphere whose centre of mass is c e3 off its centre: the contact point is straight below the
    # sphere's centre, so it lies -c times the horizontal part of the world e3 = R(q) e3 off (x, y).
    folder, columns, summary = cli_run(cli, scenarios, tmp_path, "tippe-top.toml", 0.5)
    body = run_pose.read_body(folder, summary)
    c = summary["body"]["com"]
    e3 = run_pose.rotation_matrix(run_pose.quaternions(columns))[:, :2, 2]
    assert np.abs(e3).max() > 0.1  # the top is tilted: the offset is seen
    want = np.column_stack([columns["x"], columns["y"]]) - c * e3
    np.testing.assert_allclose(run_pose.contact_on_plane(body, columns), want, atol=SAMPLED_PROFILE * 0.015)


def test_path_drawn_from_the_contact_point_starts_there(ellipsoid_run):
    folder, columns, summary = ellipsoid_run
    contact = run_pose.contact_on_plane(run_pose.read_body(folder, summary), columns)
    assert np.abs(contact - np.column_stack([columns["x"], columns["y"]])).max() > 0.01  # off the centre
    fig, ax = plt.subplots()
    drawn = path_on_plane.plot_path(ax, columns, contact, ticks=3)
    np.testing.assert_array_equal(drawn["path"].get_segments()[0][0], contact[0])
    np.testing.assert_array_equal(drawn["end"].get_xydata()[0], contact[-1])
    np.testing.assert_array_equal(drawn["centre"].get_xydata()[0], [columns["x"][0], columns["y"][0]])
    plt.close(fig)


# --- animate_run.py: the file -----------------------------------------------------------------

def test_animation_is_a_gif_of_the_frames_asked_for(ellipsoid_run, tmp_path):
    folder, _, _ = ellipsoid_run
    out = tmp_path / "run.gif"
    done = run_script(ANIMATE_SCRIPT, folder, "-o", out, "--frames", 12, "--fps", 10)
    assert done.returncode == 0, done.stderr
    with Image.open(out) as im:
        assert im.format == "GIF" and im.size == (640, 320)
        assert 1 < im.n_frames <= 12


def test_animation_refuses_more_frames_than_its_cap(ellipsoid_run, tmp_path):
    folder, _, _ = ellipsoid_run
    done = run_script(ANIMATE_SCRIPT, folder, "-o", tmp_path / "a.gif", "--frames", animate_run.MAX_FRAMES + 1)
    assert done.returncode == 2 and f"--frames {animate_run.MAX_FRAMES + 1} is invalid" in done.stderr
    assert not (tmp_path / "a.gif").exists()


def test_mp4_without_ffmpeg_is_one_line_naming_the_package(ellipsoid_run, tmp_path):
    # No ffmpeg on an empty PATH, whether or not this machine has one.
    folder, _, _ = ellipsoid_run
    env = dict(os.environ, MPLBACKEND="Agg", PATH=str(tmp_path / "empty"))
    done = run_script(ANIMATE_SCRIPT, folder, "-o", tmp_path / "a.mp4", env=env)
    assert done.returncode == 1
    assert done.stderr.count("\n") == 1 and done.stderr.startswith("animate_run.py: error: ")
    assert "Debian package ffmpeg" in done.stderr
    assert not (tmp_path / "a.mp4").exists()
