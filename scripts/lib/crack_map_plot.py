"""crack_maps.png: a 3D run's crack surfaces (crack_state.csv, fields.h5), each in its crack plane
(one crack: 2 x 2 maps; several: a row of the four maps per crack).

    figure(run)        the figure, or raises vibrotherm.MissingOutput (scripts/plot's list; 2D runs
                       have crack_spacetime.png and temperature_maps.png instead)

Maps over (s1, s2), the position on the crack plane from its centre (s1 along t1, the
strike, or x for a crack parallel to z = const; s2 along t2 = n x t1: -z for a crack
containing z, the down-dip of a tilted one; both directions fitted from the cells' positions
and named on the axes), each contact cell at its node:
 (a) the friction energy dissipated per unit area, W, at the last crack_state time;
 (b) the friction power per unit area averaged over the last source period recorded;
 (c) the time in contact over that period;
 (d) the temperature rise on the crack plane at the last output of fields.h5 (the heat
     node at each contact cell's position: the heat grid's crack-plane nodes include the
     contact cells' Q2 nodes), when the run wrote one.
numpy, h5py and matplotlib only.
"""
import numpy as np
from matplotlib.tri import Triangulation

import package  # noqa: F401  (scripts/vibrotherm of this checkout)
from vibrotherm import MissingOutput as Skip


def _triangulation(s1, s2):
    """Delaunay triangles of the cells' nodes, without those bridging a gap of the lattice
    (a staircase crack's notches): edges longer than 1.5 diagonals of the lattice are masked.
    The lattice spacing is the largest over the nodes of each one's shortest Delaunay edge (the
    lattice's lines need not run along s1 and s2: a tilted, turned crack)."""
    tri = Triangulation(s1, s2)
    i, j = tri.edges[:, 0], tri.edges[:, 1]
    length = np.hypot(s1[i] - s1[j], s2[i] - s2[j])
    shortest = np.full(len(s1), np.inf)
    np.minimum.at(shortest, i, length)
    np.minimum.at(shortest, j, length)
    spacing = np.max(shortest)
    x, y = s1[tri.triangles], s2[tri.triangles]
    longest = np.max(np.hypot(x - np.roll(x, 1, axis=1), y - np.roll(y, 1, axis=1)), axis=1)
    tri.set_mask(longest > 1.5 * np.sqrt(2) * spacing)
    return tri


def _last_period(crack_state, period):
    """Rows of the last whole source period recorded (at least the last record)."""
    t = crack_state["t"]
    return t >= max(t[-1] - period * (1 - 1e-9), t.min())


def _crack_plane_rise(run, x):
    """Temperature rise at points x (n × 3) from the last heat output, by the nearest heat node."""
    import h5py

    path = run.output("fields.h5")
    try:
        f = h5py.File(path, "r")
    except OSError:
        return None, None
    with f:
        names = sorted((k for k in f.get("heat", {}) if k.startswith("temperature_rise_")),
                       key=lambda k: int(k.rsplit("_", 1)[1]))
        if not names:
            return None, None
        nodes, rise = f["heat/geometry"][:], f["heat/" + names[-1]][:].ravel()
    nearest, off = np.zeros(len(x), int), 0.0
    for k, p in enumerate(x):
        d2 = np.sum((nodes - p) ** 2, axis=1)
        nearest[k] = np.argmin(d2)
        off = max(off, np.sqrt(d2[nearest[k]]))
    if off > 1e-9:  # the heat grid's crack-plane nodes do not include every contact cell's
        print("  crack_maps.png: the crack-plane temperature is the nearest heat node's, up to %.3g m away" % off)
    return rise[nearest], len(names) - 1


def _plane_frame(x, s1, s2):
    """(centre, t1, t2) of the crack plane, fitted from the cells' positions x = centre + s1 t1 + s2 t2."""
    fit = np.linalg.lstsq(np.column_stack([np.ones_like(s1), s1, s2]), x, rcond=None)[0]
    return fit[0], fit[1], fit[2]


def _outline_in_plane(run, k, frame):
    """The crack's outline (vibrotherm.Run.crack_outlines: its true edge, which the contact cells,
    at the interior nodes, do not reach) in (s1, s2) [mm], or None when the run cannot place it."""
    outlines = run.crack_outlines()
    if len(outlines) < k:
        return None
    centre, t1, t2 = frame
    points = outlines[k - 1][1] - centre
    s = np.linalg.lstsq(np.column_stack([t1, t2]), points.T, rcond=None)[0].T
    return s * 1e3


def _tangent_names(frame):
    """The directions of s1 and s2 in space: '-z' and the like along an axis, else their components."""
    names = []
    for t in frame[1:]:
        t = t / np.linalg.norm(t)
        axis = int(np.argmax(np.abs(t)))
        names.append(("-" if t[axis] < 0 else "+") + "xyz"[axis] if abs(abs(t[axis]) - 1) < 1e-6
                     else "(%.2f, %.2f, %.2f)" % tuple(t))
    return names


def _panel(fig, ax, tri, values, title, label, tangents, outline, cmap="magma"):
    shading = ax.tripcolor(tri, values, shading="gouraud", cmap=cmap, vmin=0, vmax=max(np.nanmax(values), 1e-300))
    fig.colorbar(shading, ax=ax, label=label, shrink=0.85)
    if outline is not None:  # the crack's edge: its front is bonded, the contact cells stop a node inside
        ax.plot(outline[:, 0], outline[:, 1], color="0.3", lw=1.0, ls="--")
        pad = 0.05 * np.ptp(outline, axis=0).max()
        ax.set_xlim(outline[:, 0].min() - pad, outline[:, 0].max() + pad)
        ax.set_ylim(outline[:, 1].min() - pad, outline[:, 1].max() + pad)
    ax.set_title(title, fontsize=10)
    ax.set_aspect("equal")
    ax.set_xlabel("s1 along %s [mm]" % tangents[0])
    ax.set_ylabel("s2 along %s [mm]" % tangents[1])


def _crack_panels(fig, axes, run, crack_state, title, k):
    """The four maps of one crack (crack_state rows of that crack only) on axes[0..3]."""
    last = crack_state["t"] == crack_state["t"][-1]
    s1, s2 = crack_state["s1"][last] * 1e3, crack_state["s2"][last] * 1e3
    tri = _triangulation(s1, s2)
    window = _last_period(crack_state, run.period)
    keys = np.round(crack_state["s1"] * 1e9) * 1e9 + np.round(crack_state["s2"] * 1e9)
    order = {k: n for n, k in enumerate(keys[last])}
    power, contact, count = np.zeros(last.sum()), np.zeros(last.sum()), np.zeros(last.sum())
    for key, p, state in zip(keys[window], crack_state["power"][window], crack_state["state"][window]):
        n = order[key]
        power[n] += p
        contact[n] += state != 0
        count[n] += 1
    power, contact = power / np.maximum(count, 1), contact / np.maximum(count, 1)
    x = np.column_stack([crack_state[c][last] for c in ("x", "y", "z")])
    frame = _plane_frame(x, crack_state["s1"][last], crack_state["s2"][last])
    axis_names = _tangent_names(frame)
    outline = _outline_in_plane(run, k, frame)
    rise, output = _crack_plane_rise(run, x)
    t_last = crack_state["t"][-1]
    span = t_last - crack_state["t"][window].min()
    _panel(fig, axes[0], tri, crack_state["W"][last], "%s(a) dissipated friction energy W at t = %.4g ms"
           % (title, t_last * 1e3), "W [J/m²]", axis_names, outline)
    _panel(fig, axes[1], tri, power, "%s(b) friction power, mean over the last %.3g µs" % (title, span * 1e6),
           "power [W/m²]", axis_names, outline)
    _panel(fig, axes[2], tri, contact, "%s(c) share of those records in contact" % title, "fraction in contact",
           axis_names, outline, cmap="Blues")
    if rise is None:
        axes[3].set_axis_off()
        axes[3].text(0.5, 0.5, "no temperature field (give -output_times)", ha="center")
    else:
        try:
            when = "t = %.4g ms" % (run.field_times("heat")[output] * 1e3)
        except (Skip, IndexError):
            when = "output %d" % output
        _panel(fig, axes[3], tri, rise * 1e6, "%s(d) temperature rise on the crack plane at %s" % (title, when),
               "rise [µK]", axis_names, outline, cmap="inferno")
    return last.sum()


EDGE = ("\ndashed: the crack's edge; its front nodes are bonded, so the contact cells (the map) stop one node"
        " inside it")


def figure(run):
    import matplotlib.pyplot as plt

    if run.summary.get("dimension", 2) != 3:
        raise Skip("a 2D run (crack_spacetime.png and temperature_maps.png draw its cracks)")
    crack_state = run.table("crack_state.csv")
    cracks = np.unique(crack_state["crack"]).astype(int)
    if len(cracks) == 1:  # 2 x 2 maps
        fig, axes = plt.subplots(2, 2, figsize=(13, 10))
        cells = _crack_panels(fig, axes.ravel(), run, crack_state, "", int(cracks[0]))
        fig.suptitle("Crack surface of %s: %d contact cells (crack_state.csv)%s" % (run.crack_name(1), cells, EDGE))
    else:  # a row of four maps per crack
        fig, axes = plt.subplots(len(cracks), 4, figsize=(24, 5 * len(cracks)), squeeze=False)
        for row, k in zip(axes, cracks):
            rows = crack_state["crack"] == k
            _crack_panels(fig, row, run, {c: v[rows] for c, v in crack_state.items()}, "%s: " % run.crack_name(k), k)
        fig.suptitle("Crack surfaces of %d cracks (crack_state.csv; each map on its crack's plane)%s" % (len(cracks),
                                                                                                      EDGE))
    fig.tight_layout()
    return fig
