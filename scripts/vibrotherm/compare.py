"""Do two runs give the same results, and by how much do they differ?

    compare_summaries(a, b)    the numbers of two summary.json side by side (a DataFrame)
    compare_energy(a, b)       energy.csv of two runs, column by column (a DataFrame)
    compare_directories(a, b)  every result file, as scripts/compare_outputs does: a list of differences

a and b are Run objects or run directories."""
import json
import math
import os

import numpy as np

from .run_dir import Run

# What describes the run rather than its results (times, host, commit, command line).
RUN_KEYS = {"version", "git_commit", "date", "host", "command_line", "wall_time_s", "stages",
            "options", "rate", "throughput"}


def _run(r):
    return r if isinstance(r, Run) else Run(r)


def _describes_the_run(key):
    top = key.split(".")[0]
    # PETSc's MUMPS reports -mat_mumps_view_info's default from uninitialised memory.
    return top in RUN_KEYS or top in ("option_values", "units", "derived_rules") or key.endswith("mumps_view_info")


def compare_summaries(a, b, rtol=0.0, all_keys=False):
    """The numbers of two runs' summary.json (Run.scalars) side by side: a DataFrame indexed by
    dotted key with columns a, b, difference (b − a), relative ((b − a) / max(|a|, |b|)), unit and
    differs (beyond rtol of the larger magnitude; a key in one run only differs). Without
    all_keys only the keys that differ are listed, and never what describes the run (times,
    host, commit, command line, option values)."""
    import pandas as pd

    sa, sb = _run(a).scalars(), _run(b).scalars()
    units = dict(sa.attrs["units"], **sb.attrs["units"])
    rows = []
    for key in sorted(set(sa.index) | set(sb.index)):
        if _describes_the_run(key) and not all_keys:
            continue
        x, y = sa.get(key), sb.get(key)
        if x is None or y is None:
            rows.append((key, x, y, np.nan, np.nan, units.get(key), True))
            continue
        x, y = float(x), float(y)
        scale = max(abs(x), abs(y))
        difference = y - x
        relative = difference / scale if scale > 0 else 0.0
        differs = not (x == y or (np.isnan(x) and np.isnan(y)) or abs(difference) <= rtol * scale)
        rows.append((key, x, y, difference, relative, units.get(key), differs))
    frame = pd.DataFrame(rows, columns=["key", "a", "b", "difference", "relative", "unit", "differs"]).set_index("key")
    return frame if all_keys else frame[frame["differs"]]


def compare_energy(a, b, columns=None):
    """energy.csv of two runs column by column, over the times both cover (b interpolated onto
    a's times): a DataFrame indexed by column with max_difference (largest |b − a|), scale
    (largest |a|), relative (their ratio), final_a, final_b (the last values) and unit."""
    import pandas as pd

    ea, eb = _run(a).energy(), _run(b).energy()
    names = [c for c in (columns or ea.columns) if c != "t" and c in eb.columns]
    ta, tb = ea["t"].to_numpy(), eb["t"].to_numpy()
    inside = (ta >= tb.min()) & (ta <= tb.max()) if len(tb) else np.zeros(len(ta), bool)
    rows = []
    for name in names:
        x = ea[name].to_numpy()[inside]
        y = np.interp(ta[inside], tb, eb[name].to_numpy()) if inside.any() else x
        worst = float(np.max(np.abs(y - x))) if len(x) else np.nan
        scale = float(np.max(np.abs(x))) if len(x) else np.nan
        rows.append((name, worst, scale, worst / scale if scale > 0 else (0.0 if worst == 0 else np.inf),
                     float(ea[name].iloc[-1]) if len(ea) else np.nan, float(eb[name].iloc[-1]) if len(eb) else np.nan,
                     ea.attrs["units"].get(name)))
    return pd.DataFrame(rows, columns=["column", "max_difference", "scale", "relative", "final_a", "final_b",
                                       "unit"]).set_index("column")


# --- every result file (scripts/compare_outputs) -------------------------------------------------


def _numbers_close(a, b, scale, rtol):
    return a == b or (math.isnan(a) and math.isnan(b)) or (rtol > 0 and abs(a - b) <= rtol * scale)


def _number(text):
    """A CSV field as a float, or None for a text field (a contact state, a crack name)."""
    try:
        return float(text)
    except ValueError:
        return None


def compare_csv_files(a, b, rtol, say):
    """CSV files byte for byte (rtol 0), else every number within rtol of its column's largest
    magnitude (NaN equals NaN) and every text field equal."""
    with open(a, "rb") as fa, open(b, "rb") as fb:
        da, db = fa.read(), fb.read()
    if da == db:
        return
    if rtol == 0:
        say("bytes differ")
        return
    ra = [line.split(",") for line in da.decode().splitlines()]
    rb = [line.split(",") for line in db.decode().splitlines()]
    if len(ra) != len(rb) or (ra and ra[0] != rb[0]):
        say("rows or header differ (%d vs %d rows)" % (len(ra), len(rb)))
        return
    columns = len(ra[0]) if ra else 0
    scale = [0.0] * columns
    rows = []
    for i, (x, y) in enumerate(zip(ra[1:], rb[1:])):
        if len(x) != len(y):
            say("row %d: %d vs %d fields" % (i + 1, len(x), len(y)))
            return
        fx, fy = [_number(v) for v in x], [_number(v) for v in y]
        for j, (u, v) in enumerate(zip(fx, fy)):
            if (u is None or v is None) and x[j] != y[j]:
                say("row %d column %s: %r vs %r" % (i + 1, ra[0][j], x[j], y[j]))
                return
        rows.append((fx, fy))
        scale = [s if v is None or math.isnan(v) else max(s, abs(v)) for s, v in zip(scale, fx)]
    for i, (fx, fy) in enumerate(rows):
        for j, (u, v) in enumerate(zip(fx, fy)):
            if u is not None and v is not None and not _numbers_close(u, v, scale[j], rtol):
                say("row %d column %s: %r vs %r" % (i + 1, ra[0][j], u, v))
                return


def compare_json_values(a, b, rtol, say, path=""):
    """Two summary.json trees, without what describes the run (RUN_KEYS, -output_dir)."""
    if isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            if key in RUN_KEYS or key == "-output_dir" or key.endswith("mumps_view_info"):
                continue
            if key not in a or key not in b:
                say("%s/%s only in one run" % (path, key))
            else:
                compare_json_values(a[key], b[key], rtol, say, path + "/" + key)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            say("%s: %d vs %d entries" % (path, len(a), len(b)))
        for i, (x, y) in enumerate(zip(a, b)):
            compare_json_values(x, y, rtol, say, "%s[%d]" % (path, i))
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        if not _numbers_close(a, b, max(abs(a), abs(b)), rtol):
            say("%s: %r vs %r" % (path, a, b))
    elif a != b:
        say("%s: %r vs %r" % (path, a, b))


def compare_h5_files(a, b, rtol, say):
    """Every dataset of two HDF5 files: equal values (or within rtol of the dataset's largest magnitude)."""
    import h5py

    def datasets(f):
        names = []
        f.visititems(lambda name, obj: names.append(name) if isinstance(obj, h5py.Dataset) else None)
        return set(names)

    with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
        na, nb = datasets(fa), datasets(fb)
        for name in sorted(na ^ nb):
            say("dataset %s only in one run" % name)
        for name in sorted(na & nb):
            x, y = fa[name][()], fb[name][()]
            if np.shape(x) != np.shape(y):
                say("%s: shape %s vs %s" % (name, np.shape(x), np.shape(y)))
            elif not np.array_equal(x, y):
                diff = np.max(np.abs(np.asarray(x, float) - np.asarray(y, float))) if np.size(x) else 0
                scale = np.max(np.abs(np.asarray(x, float))) if np.size(x) else 0
                if rtol == 0 or diff > rtol * scale:
                    say("%s: values differ (max %.3g, scale %.3g)" % (name, diff, scale))


def compare_directories(dir_a, dir_b, rtol=0.0):
    """Every result file of dir_a against dir_b ("name: what differs" lines; empty when the runs
    agree): CSV, summary.json, HDF5 datasets and XDMF files (see scripts/compare_outputs)."""
    differences = []
    for name in sorted(os.listdir(dir_a)):
        a, b = os.path.join(dir_a, name), os.path.join(dir_b, name)
        say = lambda what, name=name: differences.append("%s: %s" % (name, what))  # noqa: E731
        kind = os.path.splitext(name)[1]
        if kind not in (".csv", ".json", ".h5", ".xmf") or os.path.isdir(a):
            continue
        if not os.path.exists(b):
            say("missing in %s" % dir_b)
        elif kind == ".csv":
            compare_csv_files(a, b, rtol, say)
        elif kind == ".json":
            with open(a) as fa, open(b) as fb:
                compare_json_values(json.load(fa), json.load(fb), rtol, say)
        elif kind == ".h5":
            compare_h5_files(a, b, rtol, say)
        else:
            with open(a, "rb") as fa, open(b, "rb") as fb:
                if fa.read() != fb.read():
                    say("bytes differ")
    return differences
