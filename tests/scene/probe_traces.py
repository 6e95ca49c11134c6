"""Probe traces of a run (probes.csv) and their differences, for the tests that compare a
run with a reference run at other time steps (local time stepping in 2D and 3D)."""
import bisect
import math
import os

from checks import outputs


def traces(out, components, probes):
    """{(probe, component): [(t, value), ...]} of the bulk probes numbered in `probes`."""
    series = {}
    for row in outputs(out).rows("probes.csv"):
        if not row["probe"].isdigit() or int(row["probe"]) not in probes:
            continue
        for c in components:
            series.setdefault((row["probe"], c), []).append((float(row["t"]), float(row[c])))
    return series


def interpolate(points, t):
    """Linear interpolation of a series sorted in time."""
    times = [p[0] for p in points]
    k = min(max(bisect.bisect_left(times, t), 1), len(points) - 1)
    (t0, x0), (t1, x1) = points[k - 1], points[k]
    return x0 + (x1 - x0) * (t - t0) / (t1 - t0) if t1 > t0 else x1


def trace_error(run, reference):
    """Largest relative L2 difference between two runs' traces, on the reference's times
    (infinite when a trace is missing or the run ends a sample early)."""
    worst = 0.0
    for key, points in reference.items():
        if key not in run or run[key][-1][0] < points[-1][0] - (points[-1][0] - points[-2][0]):
            return math.inf
        norm = math.sqrt(sum(x * x for _, x in points))
        if norm == 0.0:
            continue
        diff = math.sqrt(sum((interpolate(run[key], t) - x) ** 2 for t, x in points if t <= run[key][-1][0]))
        worst = max(worst, diff / norm)
    return worst


def largest_difference(a, b):
    """The largest sample-by-sample difference of two runs' traces over the largest value
    (infinite when their probes or samples differ, or nothing moved)."""
    if a.keys() != b.keys() or any(len(a[key]) != len(b[key]) for key in a):
        return math.inf
    scale = max(abs(x) for points in a.values() for _, x in points)
    worst = max(abs(x - y[1]) for key in a for (_, x), y in zip(a[key], b[key]))
    return worst / scale if scale > 0.0 else math.inf
