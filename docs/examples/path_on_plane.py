"""The path of a run on the plane: where the body's centre of mass went, coloured by time, with
the heading of its axis e1 drawn as short ticks at regular times.

    MPLBACKEND=Agg python3 docs/examples/path_on_plane.py                    # writes path_on_plane.png
    python3 docs/examples/path_on_plane.py ellipsoid-long-axis 5 -o long.png  # a scenario, t_end (s)
    python3 docs/examples/path_on_plane.py --run RUN_DIR                     # an existing run folder

Without --run it runs a shipped scenario (data/scenarios/NAME.toml, or $FRICTIONLAB_DATA_DIR's;
default ellipsoid-case-a for 30 s of its 60) with frictionlab.simulate; --keep-run DIR keeps that
run's folder (trajectory.csv, summary.json, scenario.toml) for animate_run.py.

What is drawn (docs/dynamics.md §6, docs/convex-bodies.md §11): trajectory.csv's pose columns.
`x, y` (m, world axes) are the centre of mass on the plane, not the contact point (they differ by
the horizontal part of the lever from the centre of mass to the contact, at most the body's
largest distance from its centre of mass).
`qw, qx, qy, qz` is the unit quaternion turning body vectors into world ones; a tick is the
horizontal part of the body's e1 = R(q) (1, 0, 0), so it shrinks to nothing when e1 is vertical.

The pose helpers here (read_run, rotation_matrix, heading_from_quaternion) are used by
animate_run.py too.
"""

import argparse
import csv
import json
import os
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENARIO = "ellipsoid-case-a"
DEFAULT_T_END = 30.0   # s: the ellipsoid turns over near 15 s and stands on its long axis by 25 s
DEFAULT_TICKS = 40     # heading ticks along the path


def data_dir():
    return os.environ.get("FRICTIONLAB_DATA_DIR", os.path.join(HERE, "..", "..", "data"))


def read_run(folder):
    """A run folder as (columns, summary): trajectory.csv as {name: float64 array} and
    summary.json as a dict (None when absent)."""
    path = os.path.join(folder, "trajectory.csv")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        raise ValueError(f"{path} holds no samples")
    header, body = rows[0], rows[1:]
    columns = {name: np.array([float(r[i]) for r in body]) for i, name in enumerate(header)}
    missing = [c for c in ("t", "x", "y", "qw", "qx", "qy", "qz") if c not in columns]
    if missing:
        raise ValueError(f"{path} has no pose columns {', '.join(missing)} (a run from before the pose)")
    summary = None
    if os.path.isfile(os.path.join(folder, "summary.json")):
        with open(os.path.join(folder, "summary.json"), encoding="utf-8") as f:
            summary = json.load(f)
    return columns, summary


def quaternions(columns):
    """The trajectory's quaternions (w, x, y, z) as an (n, 4) array."""
    return np.stack([columns["qw"], columns["qx"], columns["qy"], columns["qz"]], axis=-1)


def rotation_matrix(q):
    """R(q) for unit quaternions q = (w, x, y, z) (shape (..., 4)): world = R body, shape (..., 3, 3)."""
    q = np.asarray(q, dtype=float)
    w, x, y, z = q[..., 0], q[..., 1], q[..., 2], q[..., 3]
    return np.stack([
        np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], axis=-1),
        np.stack([2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], axis=-1),
        np.stack([2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], axis=-1),
    ], axis=-2)


def e1_on_plane(q):
    """The horizontal part (world x, y) of the body's e1 = R(q) (1, 0, 0): shape (..., 2); its
    length is the cosine of e1's tilt out of the plane."""
    return rotation_matrix(q)[..., :2, 0]


def heading_from_quaternion(q):
    """The heading of the body's e1 on the plane, rad in (-pi, pi], from world x towards world y:
    atan2 of e1_on_plane(q). A turn by theta about the vertical gives theta; a turn about e1 keeps it."""
    h = e1_on_plane(q)
    return np.arctan2(h[..., 1], h[..., 0])


def sample_times(t, count):
    """Indices of `count` samples at regular times over t (the sample at or after each time)."""
    wanted = np.linspace(t[0], t[-1], count)
    return np.unique(np.minimum(np.searchsorted(t, wanted), len(t) - 1))


def plot_path(ax, columns, ticks=DEFAULT_TICKS, tick_length=None):
    """Draws the path (x, y) coloured by t, start and end markers and heading ticks on ax.
    Returns {"path": LineCollection, "start": Line2D, "end": Line2D, "ticks": LineCollection}."""
    from matplotlib.collections import LineCollection

    t, x, y = columns["t"], columns["x"], columns["y"]
    points = np.column_stack([x, y])
    span = max(np.ptp(x), np.ptp(y), 1e-3)
    # viridis runs dark to light: time reads in grayscale too.
    path = LineCollection(np.stack([points[:-1], points[1:]], axis=1) if len(t) > 1 else [points],
                          cmap="viridis", linewidths=1.5, zorder=2)
    path.set_array(t[:-1] if len(t) > 1 else t)
    ax.add_collection(path)
    if tick_length is None:
        tick_length = 0.04 * span
    idx = sample_times(t, ticks)
    heads = e1_on_plane(quaternions(columns)[idx])
    tick_segments = np.stack([points[idx], points[idx] + tick_length * heads], axis=1)
    tick_lines = LineCollection(tick_segments, colors="black", linewidths=0.8, zorder=3,
                                label=f"e1 on the plane, every {(t[-1] - t[0]) / max(ticks - 1, 1):.3g} s")
    ax.add_collection(tick_lines)
    (start,) = ax.plot(x[:1], y[:1], "o", ms=8, mfc="white", mec="black", zorder=4, label=f"start, t = {t[0]:.3g} s")
    (end,) = ax.plot(x[-1:], y[-1:], "s", ms=7, color="black", zorder=4, label=f"end, t = {t[-1]:.3g} s")
    ax.set_aspect("equal", adjustable="datalim")
    pad = 0.08 * span
    ax.set_xlim(x.min() - pad, x.max() + pad)
    ax.set_ylim(y.min() - pad, y.max() + pad)
    ax.set(xlabel="x (m)", ylabel="y (m)")
    ax.legend(loc="best", fontsize="small")
    ax.figure.colorbar(path, ax=ax, label="t (s)")
    return {"path": path, "start": start, "end": end, "ticks": tick_lines}


def run_scenario(name, t_end, out):
    """Runs data/scenarios/NAME.toml (or a .toml path) to t_end into the folder out; returns
    read_run(out)."""
    import frictionlab

    scenario = name if name.endswith(".toml") else os.path.join(data_dir(), "scenarios", name + ".toml")
    run = frictionlab.simulate(scenario, overrides={"run.t_end": t_end}, out=out)
    print(f"{run.summary['scenario']['name']}: {run.reason} at t = {run.summary['final_time']:.4g} s, {len(run.t)} samples")
    return read_run(out)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scenario", nargs="?", default=DEFAULT_SCENARIO,
                        help=f"a shipped scenario's name or a .toml file (default {DEFAULT_SCENARIO})")
    parser.add_argument("t_end", nargs="?", type=float, default=DEFAULT_T_END,
                        help=f"run.t_end override, s (default {DEFAULT_T_END:g})")
    parser.add_argument("--run", metavar="DIR", help="draw this run folder instead of running a scenario")
    parser.add_argument("--keep-run", metavar="DIR", help="write the scenario's run folder here")
    parser.add_argument("-o", "--output", default="path_on_plane.png", help="the PNG to write (default path_on_plane.png)")
    parser.add_argument("--ticks", type=int, default=DEFAULT_TICKS, help=f"heading ticks (default {DEFAULT_TICKS})")
    args = parser.parse_args(argv)
    if args.ticks < 1:
        parser.error(f"--ticks {args.ticks} is invalid: at least 1")
    if not args.output.lower().endswith(".png"):
        parser.error(f"--output {args.output} is invalid: the figure is a .png file")

    import matplotlib.pyplot as plt

    try:
        if args.run:
            columns, summary = read_run(args.run)
        elif args.keep_run:
            columns, summary = run_scenario(args.scenario, args.t_end, args.keep_run)
        else:
            with tempfile.TemporaryDirectory(prefix="frictionlab-path-") as tmp:
                columns, summary = run_scenario(args.scenario, args.t_end, tmp)
    except (OSError, ValueError) as e:
        sys.exit(f"path_on_plane.py: error: {e}")
    name = summary["scenario"]["name"] if summary else os.path.basename(os.path.normpath(args.run))
    fig, ax = plt.subplots(figsize=(7, 6), constrained_layout=True)
    plot_path(ax, columns, ticks=args.ticks)
    ax.set_title(f"{name}: centre of mass on the plane")
    fig.savefig(args.output, dpi=100)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
