"""The path of a run on the plane: where the body touched it, coloured by time, with the
heading of its axis e1 drawn as short ticks at regular times.

    MPLBACKEND=Agg python3 docs/examples/path_on_plane.py                    # writes path_on_plane.png
    python3 docs/examples/path_on_plane.py ellipsoid-long-axis 5 -o long.png  # a scenario, t_end (s)
    python3 docs/examples/path_on_plane.py --run RUN_DIR                     # an existing run folder

Without --run it runs a shipped scenario (data/scenarios/NAME.toml, or $FRICTIONLAB_DATA_DIR's;
default ellipsoid-case-a for 30 s of its 60) with frictionlab.simulate; --keep-run DIR keeps that
run's folder (trajectory.csv, summary.json, scenario.toml) for animate_run.py.

What is drawn (run_pose.py; docs/convex-bodies.md §11): trajectory.csv's `x, y` are the centre of
mass on the plane (thin grey line); the contact point, the body's lowest point, is that plus the
horizontal part of R(q) (lowest(gamma) - c), from the shape in summary.json (coloured line; for a
shape run_pose.py does not know, the centre of mass is coloured instead). A tick is the horizontal
part of the body's e1 = R(q) (1, 0, 0), drawn from the coloured path: it shrinks to nothing when e1
stands vertical.
"""

import argparse
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_pose import contact_on_plane, e1_on_plane, quaternions, read_body, read_run, sample_times  # noqa: E402
from run_pose import heading_from_quaternion  # noqa: E402,F401 (the heading, for users of this script)

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENARIO = "ellipsoid-case-a"
DEFAULT_T_END = 30.0   # s: the ellipsoid turns over between 10 and 25 s and then stands on its long axis
DEFAULT_TICKS = 40     # heading ticks along the path


def data_dir():
    return os.environ.get("FRICTIONLAB_DATA_DIR", os.path.normpath(os.path.join(HERE, "..", "..", "data")))


def plot_path(ax, columns, contact=None, ticks=DEFAULT_TICKS, tick_length=None):
    """Draws on ax the path coloured by t (the contact point's (n, 2) if given, else the centre
    of mass), the centre of mass in grey beside a contact path, start and end markers, and
    heading ticks. Returns {"path": LineCollection, "start": Line2D, "end": Line2D,
    "ticks": LineCollection, "centre": Line2D or None}."""
    from matplotlib.collections import LineCollection

    t = columns["t"]
    centre_xy = np.column_stack([columns["x"], columns["y"]])
    points = centre_xy if contact is None else np.asarray(contact, float)
    x, y = points[:, 0], points[:, 1]
    span = max(np.ptp(x), np.ptp(y), 1e-3)
    centre = None
    if contact is not None:
        (centre,) = ax.plot(centre_xy[:, 0], centre_xy[:, 1], color="0.6", lw=0.8, zorder=1,
                            label="centre of mass")
    # viridis runs dark to light: time reads in grayscale too.
    path = LineCollection(np.stack([points[:-1], points[1:]], axis=1) if len(t) > 1 else [points],
                          cmap="viridis", linewidths=1.5, zorder=2)
    path.set_array(t[:-1] if len(t) > 1 else t)
    ax.add_collection(path)
    if tick_length is None:
        tick_length = 0.04 * span
    idx = sample_times(t, ticks)
    heads = e1_on_plane(quaternions(columns)[idx])
    tick_lines = LineCollection(np.stack([points[idx], points[idx] + tick_length * heads], axis=1),
                                colors="black", linewidths=0.8, zorder=3,
                                label=f"e1 on the plane, every {(t[-1] - t[0]) / max(ticks - 1, 1):.3g} s")
    ax.add_collection(tick_lines)
    (start,) = ax.plot(x[:1], y[:1], "o", ms=8, mfc="white", mec="black", zorder=4, label=f"start, t = {t[0]:.3g} s")
    (end,) = ax.plot(x[-1:], y[-1:], "s", ms=7, color="black", zorder=4, label=f"end, t = {t[-1]:.3g} s")
    both = points if contact is None else np.vstack([points, centre_xy])
    pad = 0.08 * span
    ax.set_xlim(both[:, 0].min() - pad, both[:, 0].max() + pad)
    ax.set_ylim(both[:, 1].min() - pad, both[:, 1].max() + pad)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set(xlabel="x (m)", ylabel="y (m)")
    ax.legend(loc="best", fontsize="small")
    ax.figure.colorbar(path, ax=ax, label="t (s)")
    return {"path": path, "start": start, "end": end, "ticks": tick_lines, "centre": centre}


def run_scenario(name, t_end, out):
    """Runs data/scenarios/NAME.toml (or a .toml path) to t_end (s) into the folder out; returns
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
    parser.add_argument("-o", "--output", default="path_on_plane.png", help="the PNG to write, 700 x 600 px (default path_on_plane.png)")
    parser.add_argument("--ticks", type=int, default=DEFAULT_TICKS, help=f"heading ticks (default {DEFAULT_TICKS})")
    args = parser.parse_args(argv)
    if args.ticks < 1:
        parser.error(f"--ticks {args.ticks} is invalid: at least 1")
    if not args.output.lower().endswith(".png"):
        parser.error(f"--output {args.output} is invalid: the figure is a .png file")
    if not os.path.isdir(os.path.dirname(os.path.abspath(args.output))):  # before the run
        sys.exit(f"path_on_plane.py: error: cannot write {args.output}: no folder {os.path.dirname(os.path.abspath(args.output))}")

    import matplotlib.pyplot as plt

    try:
        if args.run:
            folder = args.run
            columns, summary = read_run(folder)
            body = read_body(folder, summary)
        else:
            with tempfile.TemporaryDirectory(prefix="frictionlab-path-") as tmp:
                folder = args.keep_run or tmp
                columns, summary = run_scenario(args.scenario, args.t_end, folder)
                body = read_body(folder, summary)
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"path_on_plane.py: error: {e}")
    contact = contact_on_plane(body, columns)
    name = summary["scenario"]["name"] if summary else os.path.basename(os.path.normpath(args.run))
    fig, ax = plt.subplots(figsize=(7, 6), constrained_layout=True)
    plot_path(ax, columns, contact, ticks=args.ticks)
    ax.set_title(f"{name}: {'contact point' if contact is not None else 'centre of mass'} on the plane")
    try:
        fig.savefig(args.output, dpi=100)
    except OSError as e:
        sys.exit(f"path_on_plane.py: error: cannot write {args.output}: {e}")
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
