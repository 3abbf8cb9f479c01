"""An animation of a run: the body at its pose in 3-D over the trail of its path, and the whole
path on the plane beside it.

    python3 docs/examples/path_on_plane.py --keep-run run       # or: frictionlab simulate ... --out run
    MPLBACKEND=Agg python3 docs/examples/animate_run.py run     # writes animation.gif

Reads the run folder's trajectory.csv (the pose: x, y, qw, qx, qy, qz; eps) and summary.json (the
body as it ran; without it, scenario.toml); the conventions and the shapes are run_pose.py's.
Frames are taken at regular times, at most 200 of them (--frames); each is 640 x 320 pixels, so a
GIF of 120 frames is 1-2 MB (1.7 MB in 14 s for 60 s of ellipsoid-case-a). A GIF is written by
matplotlib's PillowWriter (python3-pil); a .mp4 needs ffmpeg (Debian package ffmpeg).

The body is drawn at its pose (docs/convex-bodies.md §11): its axes e1 (solid), e2 (dashed), e3
(dotted) from the centre of mass, and the outline of its shape: an ellipsoid's three principal
sections, a toroidal disk's rim and faces, a body of revolution's two meridians and widest circle.
The centre of mass stands at the height that puts the body's lowest point at eps (the contact's
height, < 0 in contact); the trail is the contact point's path. A shape not known here is drawn
as its axes only (of length summary.json's scales.size_R), its centre of mass at the height
size_R, its trail the centre of mass's path.
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_pose import contact_on_plane, pose_world, quaternions, read_body, read_run, sample_times, to_world  # noqa: E402

MAX_FRAMES = 200
DEFAULT_FRAMES = 120
DEFAULT_FPS = 20
FIGSIZE = (8, 4)   # inches
DPI = 80           # FIGSIZE * DPI = 640 x 320 pixels


def check_output(path):
    """None if the output's format can be written here, else the one-line error."""
    ext = os.path.splitext(path)[1].lower()
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):  # before the frames are drawn, which takes seconds
        return f"cannot write {path}: no folder {folder}"
    if ext == ".gif":
        return None
    if ext == ".mp4":
        from matplotlib import animation

        if not animation.writers.is_available("ffmpeg"):
            return (f"writing {path} needs ffmpeg, which is not installed (Debian package ffmpeg); "
                    "write a .gif instead")
        return None
    return f"--output {path} is invalid: the animation is a .gif (or a .mp4, with ffmpeg)"


def animate(folder, output, frames=DEFAULT_FRAMES, fps=DEFAULT_FPS):
    """Writes the animation of the run in folder to output; returns the number of frames."""
    import matplotlib.pyplot as plt
    from matplotlib import animation

    columns, summary = read_run(folder)
    body = read_body(folder, summary)
    t, xs, ys = columns["t"], columns["x"], columns["y"]
    eps = columns.get("eps", np.zeros_like(t))
    contact = contact_on_plane(body, columns)
    # The trail is the contact point's path where the shape is known, else the centre of mass's.
    px, py = (xs, ys) if contact is None else (contact[:, 0], contact[:, 1])
    qs = quaternions(columns)
    idx = sample_times(t, frames)
    size = float(body.axes.max())
    half = 2.0 * size  # half-width of the 3-D view, which follows the body

    fig = plt.figure(figsize=FIGSIZE, dpi=DPI)
    ax3 = fig.add_axes([0.0, 0.0, 0.56, 0.95], projection="3d")
    ax2 = fig.add_axes([0.64, 0.13, 0.33, 0.74])
    name = summary["scenario"]["name"] if summary else os.path.basename(os.path.normpath(folder))
    fig.suptitle(name, fontsize=10)

    ax2.plot(px, py, color="0.75", lw=1)
    (trail2,) = ax2.plot([], [], color="black", lw=1.2)
    (here2,) = ax2.plot([], [], "o", ms=6, mfc="white", mec="black")
    ax2.plot(px[:1], py[:1], "o", ms=4, color="black")
    span = max(np.ptp(px), np.ptp(py), 2 * half)
    cx, cy = (px.max() + px.min()) / 2, (py.max() + py.min()) / 2
    ax2.set_xlim(cx - 0.55 * span, cx + 0.55 * span)
    ax2.set_ylim(cy - 0.55 * span, cy + 0.55 * span)
    ax2.set_aspect("equal")
    ax2.set(xlabel="x (m)", ylabel="y (m)")
    ax2.tick_params(labelsize=7)
    label = ax2.set_title("", fontsize=9)

    (trail3,) = ax3.plot([], [], [], color="0.4", lw=1)
    outline = [ax3.plot([], [], [], color="tab:blue", lw=0.8)[0] for _ in body.curves]
    axis_lines = [ax3.plot([], [], [], color="black", lw=lw, ls=ls)[0]
                  for lw, ls in ((2.0, "-"), (1.2, "--"), (1.2, ":"))]
    ax3.set_box_aspect((1, 1, 0.5))
    ax3.set(xlabel="x", ylabel="y", zlabel="z")
    ax3.tick_params(labelsize=6)

    def draw(frame):
        k = idx[frame]
        centre, R = pose_world(body, qs[k], xs[k], ys[k], eps[k])
        for line, curve in zip(outline, body.curves):
            w = to_world(body, curve, centre, R)
            line.set_data_3d(w[:, 0], w[:, 1], w[:, 2])
        for i, line in enumerate(axis_lines):
            tip = centre + body.axes[i] * R[:, i]
            line.set_data_3d([centre[0], tip[0]], [centre[1], tip[1]], [centre[2], tip[2]])
        # The trail inside the view only: mplot3d does not clip lines at its box.
        tx, ty = px[: k + 1], py[: k + 1]
        inside = (np.abs(tx - centre[0]) <= half) & (np.abs(ty - centre[1]) <= half)
        trail3.set_data_3d(np.where(inside, tx, np.nan), np.where(inside, ty, np.nan), np.zeros_like(tx))
        ax3.set_xlim(centre[0] - half, centre[0] + half)
        ax3.set_ylim(centre[1] - half, centre[1] + half)
        ax3.set_zlim(0, half)
        trail2.set_data(tx, ty)
        here2.set_data(px[k : k + 1], py[k : k + 1])
        label.set_text(f"t = {t[k]:.2f} s")
        return [trail3, trail2, here2, label, *outline, *axis_lines]

    anim = animation.FuncAnimation(fig, draw, frames=len(idx), blit=False)
    writer = animation.PillowWriter(fps=fps) if output.lower().endswith(".gif") else animation.FFMpegWriter(fps=fps)
    anim.save(output, writer=writer, dpi=DPI)
    plt.close(fig)
    return len(idx)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], epilog=__doc__.split("\n\n", 2)[2],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="a run folder (trajectory.csv with the pose columns, summary.json)")
    parser.add_argument("-o", "--output", default="animation.gif",
                        help="the animation to write: .gif (default animation.gif) or .mp4 (needs ffmpeg)")
    parser.add_argument("--frames", type=int, default=DEFAULT_FRAMES,
                        help=f"frames at regular times, 2..{MAX_FRAMES} (default {DEFAULT_FRAMES}; "
                             "fewer if the run has fewer samples); 640 x 320 pixels each")
    parser.add_argument("--fps", type=float, default=DEFAULT_FPS, help=f"frames per second, (0, 60] (default {DEFAULT_FPS})")
    args = parser.parse_args(argv)
    if not 2 <= args.frames <= MAX_FRAMES:
        parser.error(f"--frames {args.frames} is invalid: 2..{MAX_FRAMES}")
    if not 0 < args.fps <= 60:
        parser.error(f"--fps {args.fps:g} is invalid: (0, 60]")
    problem = check_output(args.output)
    if problem:
        sys.exit(f"animate_run.py: error: {problem}")
    try:
        n = animate(args.run, args.output, args.frames, args.fps)
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"animate_run.py: error: {e}")
    print(f"wrote {args.output} ({n} frames, {os.path.getsize(args.output)} bytes)")


if __name__ == "__main__":
    main()
