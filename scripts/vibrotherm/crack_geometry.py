"""Where the cracks are, for drawing them over maps and camera frames.

    outlines(run)   [(name, points)]: each crack as a polyline in specimen coordinates [m]
                    (2D: the crack's line from mesh.h5, tip to tip; 3D: its closed outline,
                    the rectangle or ellipse of -crack_center/-crack_length/-crack_width/
                    -crack_angle/-crack_tilt/-crack_shape, methods "Tilted cracks")
    project(points, face)   3D points onto a camera face's axes (front/back: x, y;
                    top/bottom: x, z; left/right: z, y)

A crack the options do not describe (a 3D mesh file) has no outline: it is left out."""
import numpy as np

FACE_AXES = {"front": (0, 1), "back": (0, 1), "top": (0, 2), "bottom": (0, 2), "left": (2, 1), "right": (2, 1)}


def _chains(segments):
    """Segments (S × 2 × d) joined end to end into polylines (one per crack: cracks do not touch)."""
    key = lambda p: tuple(np.round(p, 12))  # noqa: E731
    ends = {}
    for i, (a, b) in enumerate(segments):
        ends.setdefault(key(a), []).append(i)
        ends.setdefault(key(b), []).append(i)
    used, chains = set(), []
    for start in range(len(segments)):
        if start in used:
            continue
        # walk to one end of this chain, then collect it from there
        i, point = start, key(segments[start][0])
        seen = {start}
        while True:
            nxt = [j for j in ends[point] if j not in seen]
            if not nxt:
                break
            i = nxt[0]
            seen.add(i)
            a, b = map(key, segments[i])
            point = b if a == point else a
        line = [np.array(point)]
        while i is not None:
            used.add(i)
            a, b = map(key, segments[i])
            point = b if a == point else a
            line.append(np.array(point))
            nxt = [j for j in ends[point] if j not in used]
            i = nxt[0] if nxt else None
        chains.append(np.array(line))
    return chains


def _outlines_2d(run):
    import h5py

    if not run.has("mesh.h5"):
        return []
    with h5py.File(run.output("mesh.h5"), "r") as f:
        if "cracks/topology" not in f or "wave/geometry" not in f:
            return []
        segments = f["wave/geometry"][:][f["cracks/topology"][:]]
    lines = _chains(segments)
    # the crack of each line: the one whose contact cells (crack_state.csv) lie nearest it
    names = [run.crack_name(k + 1) for k in range(len(lines))]
    try:
        columns = run.columns("crack_state.csv")
        first = columns["t"] == columns["t"][0]
        for n, line in enumerate(lines):
            distance = {}
            for k in np.unique(columns["crack"][first]).astype(int):
                rows = first & (columns["crack"] == k)
                cells = np.column_stack([columns["x"][rows], columns["y"][rows]])
                distance[k] = np.min(np.sum((cells[:, None, :] - line[None, :, :]) ** 2, axis=2))
            names[n] = run.crack_name(min(distance, key=distance.get))
    except LookupError:
        pass
    return list(zip(names, lines))


def _per_crack(text, count):
    """One float per crack of an option "v" (all cracks) or "v1,v2,..." (one a crack); "none" is 0."""
    values = [0.0 if v.strip().lower() in ("none", "") else float(v) for v in str(text).split(",")]
    return values * count if len(values) == 1 else values


def frame_3d(angle_deg, tilt_deg):
    """(strike s, up-dip w, normal n) of a crack (METHODS.md "Tilted cracks")."""
    theta, delta = np.radians(angle_deg), np.radians(tilt_deg)
    s = np.array([np.cos(theta), np.sin(theta), 0.0])
    n0 = np.array([-np.sin(theta), np.cos(theta), 0.0])
    z = np.array([0.0, 0.0, 1.0])
    return s, np.cos(delta) * z - np.sin(delta) * n0, np.cos(delta) * n0 + np.sin(delta) * z


def _outlines_3d(run, points):
    centres = run.option("crack_center")
    if not centres or run.option("mesh_file"):
        return []
    centres = np.array([float(v) for v in centres.split(",")]).reshape(-1, 3)
    count = len(centres)
    try:
        length = _per_crack(run.option("crack_length", "0"), count)
        width = _per_crack(run.option("crack_width", "0"), count)
        angle = _per_crack(run.option("crack_angle", "0"), count)
        tilt = _per_crack(run.option("crack_tilt", "0"), count)
    except ValueError:
        return []
    shapes = str(run.option("crack_shape", "rectangle")).split(",")
    shapes = shapes * count if len(shapes) == 1 else shapes
    out = []
    for k in range(count):
        s, w, _ = frame_3d(angle[k], tilt[k])
        if shapes[k].strip() == "ellipse":
            phi = np.linspace(0, 2 * np.pi, points + 1)
            a, b = 0.5 * length[k] * np.cos(phi), 0.5 * width[k] * np.sin(phi)
        else:
            a = 0.5 * length[k] * np.array([-1, 1, 1, -1, -1])
            b = 0.5 * width[k] * np.array([-1, -1, 1, 1, -1])
        out.append((run.crack_name(k + 1), centres[k] + np.outer(a, s) + np.outer(b, w)))
    return out


def outlines(run, points=64):
    """[(crack name, polyline (n × dim) [m])] of every crack the run can place (see the module)."""
    return _outlines_3d(run, points) if run.dimension == 3 else _outlines_2d(run)


def project(points, face):
    """The columns of 3D points on a camera face's two axes (FACE_AXES)."""
    a, b = FACE_AXES.get(face or "front", (0, 1))
    return np.column_stack([points[:, a], points[:, b]])
