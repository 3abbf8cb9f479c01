"""The pose of a run, for the figures of path_on_plane.py and animate_run.py: a run folder read
back, the quaternion turned into axes and headings, and the body's shape put at its pose.

Conventions (docs/dynamics.md §6, docs/convex-bodies.md §1 and §11): trajectory.csv's `x, y` (m,
world axes) are the centre of mass on the plane; `qw, qx, qy, qz` is the unit quaternion q with
world = R(q) body; the body frame is the shape frame moved to the centre of mass c; `gamma`, the
upward vertical seen from the body, is R(q)^T e_z; `eps` (m) is the height of the lowest point.
"""

import csv
import json
import os

import numpy as np

CURVE_POINTS = 73       # points on each outline curve (every 5 degrees)
PROFILE_POINTS = 2001   # a body of revolution's meridian, sampled for its lowest point


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
        raise ValueError(f"{path} has no pose columns {', '.join(missing)} "
                         "(a run with run.pose = false, or from before the pose)")
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
    """Indices of at most `count` samples at regular times over t (the sample at or after each)."""
    wanted = np.linspace(t[0], t[-1], count)
    return np.unique(np.minimum(np.searchsorted(t, wanted), len(t) - 1))


class Body:
    """A shape as drawn: `curves` (each (n, 3), shape frame, m), the centre of mass `com` (shape
    frame, m), the axes' half-lengths `axes` (m), and `lowest(gamma)`: the lowest point (shape
    frame, m) for upward verticals gamma (shape (..., 3)), or None for a shape not known here."""

    def __init__(self, kind, curves, com, axes, lowest):
        self.kind, self.curves, self.lowest = kind, curves, lowest
        self.com, self.axes = np.asarray(com, float), np.asarray(axes, float)

    def centre_height(self, gamma, eps):
        """The height (m) of the centre of mass that puts the lowest point at height eps:
        eps - (lowest - c) . gamma; None for a shape not known here."""
        if self.lowest is None:
            return None
        gamma = np.asarray(gamma, float)
        return eps - np.sum((self.lowest(gamma) - self.com) * gamma, axis=-1)


def _horizontal_direction(gamma):
    """The unit horizontal part (gamma1, gamma2, 0) / |.|, and |.|; (0, 0, 0) where it vanishes."""
    s = np.hypot(gamma[..., 0], gamma[..., 1])
    safe = np.where(s > 0, s, 1.0)
    return np.stack([gamma[..., 0] / safe, gamma[..., 1] / safe, np.zeros_like(s)], axis=-1), s


def _ellipse(r1, r2, plane, z=0.0):
    phi = np.linspace(0, 2 * np.pi, CURVE_POINTS)
    c, s, o = r1 * np.cos(phi), r2 * np.sin(phi), np.full_like(phi, z)
    return {"xy": np.column_stack([c, s, o]), "xz": np.column_stack([c, o, s]), "yz": np.column_stack([o, c, s])}[plane]


def ellipsoid(semi_axes, com=(0, 0, 0)):
    """Semi-axes (a1, a2, a3) along e1, e2, e3 (m). Lowest point -A^2 gamma / |A gamma|."""
    a = np.asarray(semi_axes, float)
    curves = [_ellipse(a[0], a[1], "xy"), _ellipse(a[0], a[2], "xz"), _ellipse(a[1], a[2], "yz")]

    def lowest(gamma):
        return -a * a * gamma / np.sqrt(np.sum((a * gamma) ** 2, axis=-1))[..., None]

    return Body("ellipsoid", curves, com, a, lowest)


def toroidal_disk(radius, rim_radius, com=(0, 0, 0)):
    """A disk of mid-plane e1 e2 whose rim is a tube of radius rho about the circle of radius R
    (m). Lowest point: the tube's centre circle point furthest down, less rho gamma; a disk lying
    flat touches along a circle, of which the centre of the face is given."""
    R, rho = float(radius), float(rim_radius)
    curves = [_ellipse(R + rho, R + rho, "xy"), _ellipse(R, R, "xy", rho), _ellipse(R, R, "xy", -rho)]

    def lowest(gamma):
        h, _ = _horizontal_direction(gamma)
        return -R * h - rho * gamma

    return Body("toroidal-disk", curves, com, [R + rho, R + rho, rho], lowest)


def revolution(chi2, z_lo, z_hi, com=(0, 0, 0)):
    """A body of revolution about e3: radius rho(z) = sqrt(sum_k chi2[k] z^k) for z in
    [z_lo, z_hi] (m; summary.json's body, docs/dynamics.md §7). The meridian is taken at
    z = z_lo + (z_hi - z_lo) (1 - cos theta) / 2, theta in [0, pi]: even steps in theta are even
    steps along the meridian near the poles too, where rho is steep in z. Lowest point: the least
    of xi . gamma over PROFILE_POINTS thetas, refined four times tenfold about it (to ~1e-7 of
    the size; the body is convex, so the least is one)."""
    z_lo, z_hi = float(z_lo), float(z_hi)

    def meridian(theta):
        z = z_lo + (z_hi - z_lo) * (1 - np.cos(theta)) / 2
        return np.sqrt(np.maximum(np.polynomial.polynomial.polyval(z, chi2), 0.0)), z

    theta = np.linspace(0, np.pi, PROFILE_POINTS)
    rho, z = meridian(theta)
    k = int(np.argmax(rho))
    side, zz = np.concatenate([rho, -rho[::-1]]), np.concatenate([z, z[::-1]])
    o = np.zeros_like(zz)
    curves = [np.column_stack([side, o, zz]), np.column_stack([o, side, zz]), _ellipse(rho[k], rho[k], "xy", z[k])]

    def lowest(gamma):
        h, s = _horizontal_direction(gamma)
        s, g3 = s[..., None], gamma[..., 2, None]
        # On the meridian facing -gamma, xi . gamma = -rho s + z gamma3: its least is the lowest point.
        best = theta[np.argmin(-rho * s + z * g3, axis=-1)]
        step = theta[1]
        for _ in range(4):
            local = np.clip(best[..., None] + np.linspace(-step, step, 21), 0, np.pi)
            r, zl = meridian(local)
            best = np.take_along_axis(local, np.argmin(-r * s + zl * g3, axis=-1)[..., None], axis=-1)[..., 0]
            step /= 10
        r, zl = meridian(best)
        return -r[..., None] * h + zl[..., None] * np.array([0.0, 0.0, 1.0])

    return Body("revolution", curves, com, [rho[k], rho[k], max(abs(z_lo), abs(z_hi))], lowest)


def body_from_run(summary, scenario=None):
    """The Body of a run: from summary.json's resolved body, else from scenario.toml (a dict);
    a shape not known here is its axes only (of length scales.size_R, else 0.1 m)."""
    if summary is not None:
        b, p = summary["body"], summary["body"].get("parameters", {})
        com = b.get("centre_of_mass", [0, 0, 0])
        if b.get("shape") == "ellipsoid":
            return ellipsoid(p["semi_axes"], com)
        if b.get("shape") == "toroidal-disk":
            return toroidal_disk(p["radius"], p["rim_radius"], com)
        if b.get("shape") == "revolution" and "chi2" in b:
            return revolution(b["chi2"], b["z_lo"], b["z_hi"], com)
        return Body(b.get("shape", "unknown"), [], com, [summary.get("scales", {}).get("size_R", 0.1)] * 3, None)
    b = (scenario or {}).get("body", {})
    com = b.get("com", [0, 0, 0])
    com = [0, 0, com] if np.isscalar(com) else com
    if b.get("shape") == "ellipsoid":
        return ellipsoid(b["semi_axes"], com)
    if b.get("shape") == "toroidal-disk":
        return toroidal_disk(b["radius"], b["rim_radius"], com)
    return Body(b.get("shape", "revolution"), [], com, [0.1] * 3, None)  # a profile is named only


def read_body(folder, summary):
    """The Body of the run in folder (summary: its summary.json, or None: then scenario.toml)."""
    if summary is None and os.path.isfile(os.path.join(folder, "scenario.toml")):
        import tomllib  # Python 3.11

        with open(os.path.join(folder, "scenario.toml"), "rb") as f:
            return body_from_run(None, tomllib.load(f))
    return body_from_run(summary)


def pose_world(body, q, x, y, eps):
    """The centre of mass in world axes (m) and R(q) for one sample; a shape not known here
    stands at the height of its axes."""
    R = rotation_matrix(q)
    z = body.centre_height(R[2, :], eps)  # R^T e_z = gamma
    return np.array([x, y, float(body.axes.max()) if z is None else z]), R


def to_world(body, points, centre, R):
    """Shape-frame points (n, 3) in world axes at the pose (centre of mass, R)."""
    return centre + (points - body.com) @ R.T


def contact_on_plane(body, columns):
    """The lowest point's (x, y) on the plane (m, world axes) at every sample, (n, 2), or None for
    a shape not known here: (x, y) + the horizontal part of R(q) (lowest(gamma) - c)."""
    if body.lowest is None:
        return None
    R = rotation_matrix(quaternions(columns))
    gamma = R[:, 2, :]  # R^T e_z, the vertical the pose holds
    lever = np.einsum("nij,nj->ni", R, body.lowest(gamma) - body.com)
    return np.column_stack([columns["x"], columns["y"]]) + lever[:, :2]
