#!/usr/bin/python3
"""Requirement: a run's mesh and fields open right in ParaView (issue item 7).

A short paper scene runs serially and on 2 ranks. Checked with h5py and the XDMF text
(always): mesh.xmf holds the grids wave, cracks, heat as one spatial collection; each
fields_<grid>.xmf (wave, heat, cracks) is one temporal collection whose times equal the
`time` attributes of the datasets it names; vectors are N × 3 (z = 0); every dataset
but topologies carries its `units`; temperature_rise = temperature − T0 (-heat_T0);
contact_state is a cell field of the cracks grid with codes 0..3, one cell per contact
cell, whose segments add up to the crack length less the tips' shares (closed form for
a straight crack of equal facets); the 2-rank files hold the serial values at the same
points. Then, when pvpython and Xvfb exist, paraview_check.py opens the files in
ParaView, checks what the readers see and saves screenshots to PNG_DIR; otherwise the
test is skipped (exit 77) once the h5py checks have passed.

usage: test_paraview_fields.py VIBROTHERM SOURCE_DIR MPIEXEC PNG_DIR
       test_paraview_fields.py --existing RUN_DIR SOURCE_DIR PNG_DIR   (checks a finished run)"""
import math, os, shutil, subprocess, sys, tempfile
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

SCENE = ["-final_time", "5e-5", "-output_times", "2e-5,4.6e-5", "-mesh_h", "0.004"]
UNITS = {"geometry": "m", "displacement": "m", "velocity": "m/s", "temperature": "K", "temperature_rise": "K",
         "contact_state": "1", "friction_power": "W/m^2", "dissipated_energy": "J/m^2"}
check = Checks("paraview fields")


def option(summary, name, default):
    words = summary["options"].split()
    return words[words.index("-" + name) + 1] if "-" + name in words else default


def uniform_grids(path):
    return [g for g in ET.parse(path).getroot().iter("Grid") if g.get("GridType") == "Uniform"]


def check_mesh(out, summary):
    root = ET.parse(os.path.join(out, "mesh.xmf")).getroot()
    top = root.find("Domain").findall("Grid")
    check(len(top) == 1 and top[0].get("CollectionType") == "Spatial", "mesh.xmf: one spatial collection")
    names = [g.get("Name") for g in uniform_grids(os.path.join(out, "mesh.xmf"))]
    check(names == ["wave", "cracks", "heat"], "mesh.xmf grids %s" % names)
    with outputs(out).h5("mesh.h5") as f:
        for grid, cells in (("wave", "cells"), ("cracks", "cohesive_cells"), ("heat", "heat_cells")):
            check(grid in f and f[grid + "/topology"].shape[0] == summary["mesh"][cells], "mesh.h5 %s cells" % grid)
        for grid in ("wave", "heat"):
            check(grid in f and f[grid].get("geometry") is not None and
                  f[grid + "/geometry"].attrs.get("units") in (b"m", "m"), "mesh.h5 %s/geometry units" % grid)
        if "cracks" in f and "wave" in f:
            check(f["cracks/topology"][:].max() < f["wave/geometry"].shape[0], "cracks on the wave vertices")


def read_series(out, grid):
    """{k: (time, {field: (data, center)})} from fields_<grid>.xmf, checking it against fields.h5."""
    path = os.path.join(out, "fields_%s.xmf" % grid)
    if not os.path.exists(path):
        check.fail("fields_%s.xmf missing" % grid)
        return {}
    top = ET.parse(path).getroot().find("Domain").findall("Grid")
    check(len(top) == 1 and top[0].get("CollectionType") == "Temporal" and top[0].get("Name") == grid,
          "fields_%s.xmf: one temporal collection named %s" % (grid, grid))
    series = {}
    with outputs(out).h5("fields.h5") as f:
        for k, g in enumerate(uniform_grids(path)):
            t = float(g.find("Time").get("Value"))
            fields = {}
            for a in g.findall("Attribute"):
                item = a.find("DataItem")
                dataset = item.text.split(":", 1)[1]
                data = f[dataset][:]
                dims = tuple(int(n) for n in item.get("Dimensions").split())
                name = a.get("Name")
                check(data.shape == dims, "%s: shape %s, xmf says %s" % (dataset, data.shape, dims))
                check(a.get("AttributeType") == ("Vector" if dims[1] == 3 else "Scalar") and dims[1] in (1, 3),
                      "%s: %s with %d components" % (dataset, a.get("AttributeType"), dims[1]))
                attrs = f[dataset].attrs
                units = attrs.get("units")
                units = units.decode() if isinstance(units, bytes) else units
                check(units == UNITS.get(name), "%s: units %r" % (dataset, units))
                check(abs(attrs.get("time", -1) - t) <= 1e-9 * t, "%s: time %s, xmf %s" % (dataset, attrs.get("time"), t))
                fields[name] = (data, a.get("Center"))
            series[k] = (t, fields)
        units = f[grid + "/geometry"].attrs.get("units") if grid in f else None
        check(units in (b"m", "m"), "%s/geometry units %r" % (grid, units))
    return series


def check_fields(out, summary):
    wave, heat, cracks = (read_series(out, g) for g in ("wave", "heat", "cracks"))
    T0 = float(option(summary, "heat_T0", "293.15"))
    for k, (t, fields) in wave.items():
        for name in ("displacement", "velocity"):
            data = fields.get(name, (np.zeros((0, 2)), ""))[0]
            check(data.shape[1:] == (3,) and not np.any(data[:, 2:]), "wave %s_%d: N × 3 with z = 0" % (name, k))
    for k, (t, fields) in heat.items():
        if "temperature" in fields and "temperature_rise" in fields:
            T, rise = fields["temperature"][0], fields["temperature_rise"][0]
            check(np.abs(T - T0 - rise).max() <= 1e-9, "heat %d: temperature_rise = temperature - T0" % k)
            check(rise.max() > 0, "heat %d: the crack heats" % k)
        else:
            check.fail("heat %d: temperature and temperature_rise" % k)
    check_cracks(out, cracks, summary)
    return wave, heat, cracks


def check_cracks(out, cracks, summary):
    degree = int(option(summary, "wave_degree", "1"))
    crack = summary["mesh"]["cracks"][0]
    facet = crack["length"] / crack["facets"]
    # Tributary lengths tile the crack but for the unsplit tips' shares: a facet's
    # half (Q1) or sixth (Q2, ∫φ of an end node) at each tip.
    expected = crack["length"] - 2 * facet * (0.5 if degree == 1 else 1 / 6)
    previous = None
    for k, (t, fields) in cracks.items():
        state, center = fields.get("contact_state", (np.zeros((0, 1)), None))
        check(center == "Cell", "cracks contact_state_%d is cell-centred" % k)
        check(len(state) == summary["contact_cells"], "cracks: %d cells, %d contact cells" % (len(state), summary["contact_cells"]))
        check(set(np.unique(state)) <= {0.0, 1.0, 2.0, 3.0}, "contact_state codes %s" % np.unique(state))
        dissipated = fields.get("dissipated_energy", (np.zeros((0, 1)), None))[0]
        check(dissipated.min(initial=0) >= 0 and (previous is None or np.all(dissipated >= previous - 1e-15)),
              "dissipated_energy is cumulative")
        previous = dissipated
    if cracks:
        with outputs(out).h5("fields.h5") as f:
            ends = f["cracks/geometry"][:].reshape(-1, 2, 2)
        total = np.linalg.norm(ends[:, 1] - ends[:, 0], axis=1).sum()
        check(abs(total - expected) <= 1e-9 * expected, "crack segments add up to %.12g m, expected %.12g" % (total, expected))


def by_position(xy, values, digits=9):
    order = np.lexsort((np.round(xy[:, 1], digits), np.round(xy[:, 0], digits)))
    return xy[order], values[order]


def compare_ranks(a, b):
    """The 2-rank files hold the serial values at the same points (numberings differ)."""
    with outputs(a).h5("fields.h5") as fa, outputs(b).h5("fields.h5") as fb:
        for grid, field in (("wave", "displacement_1"), ("heat", "temperature_rise_1")):
            xa, va = by_position(fa[grid + "/geometry"][:], fa[grid + "/" + field][:])
            xb, vb = by_position(fb[grid + "/geometry"][:], fb[grid + "/" + field][:])
            same_points = xa.shape == xb.shape and np.abs(xa - xb).max() <= 1e-12
            check(same_points, "%s: the same points on 1 and 2 ranks" % grid)
            if same_points:
                # Partitions change rounding in the solves (the heat's direct solve: ~1e-9);
                # a misplaced value from the parallel writing would be O(1).
                worst = np.abs(va - vb).max() / np.abs(va).max()
                check(worst <= 1e-6, "%s: 2 ranks differ from serial by %.2g of the peak" % (field, worst))
        mid = lambda f: f["cracks/geometry"][:].reshape(-1, 2, 2).mean(axis=1)
        xa, sa = by_position(mid(fa), fa["cracks/contact_state_1"][:])
        xb, sb = by_position(mid(fb), fb["cracks/contact_state_1"][:])
        check(xa.shape == xb.shape and np.abs(xa - xb).max() <= 1e-12 and np.array_equal(sa, sb),
              "cracks: the same cells and states on 1 and 2 ranks")


def virtual_display():
    """Starts Xvfb on a display it picks itself and returns (server, ":N") once it accepts
    clients: what `xvfb-run -a` does, without guessing a free number from lock files
    (back-to-back runs raced there and once left an orphan server)."""
    read, write = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", "1280x1024x24", "-nolisten", "tcp"],
                              pass_fds=(write,), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write)
    number = b""
    while not number.endswith(b"\n"):  # "N\n", written once the server is ready; closing the
        chunk = os.read(read, 16)      # pipe before the newline kills the server
        if not chunk:
            break
        number += chunk
    os.close(read)
    return server, ":" + number.decode().strip()


def paraview(out, png_dir):
    """Runs paraview_check.py under pvpython; False when pvpython or Xvfb is missing."""
    if not (shutil.which("pvpython") and shutil.which("Xvfb")):
        return False
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paraview_check.py")
    for attempt in (1, 2):
        server, display = virtual_display()
        try:
            r = subprocess.run(["pvpython", script, out, png_dir], capture_output=True, text=True, timeout=600,
                               env=dict(os.environ, DISPLAY=display))
        finally:
            server.terminate()
            server.wait(timeout=30)
        # Killed by a signal: on this loaded 2-core machine pvpython aborted in about 1 run
        # of 30 creating its first X window (vtkXOpenGLRenderWindow::CreateAWindow, no
        # display connection); a real crash repeats, and check failures exit 1.
        if r.returncode >= 0:
            break
        print("pvpython killed by signal %d (attempt %d)" % (-r.returncode, attempt))
    print(r.stdout)
    os.makedirs(png_dir, exist_ok=True)
    with open(os.path.join(png_dir, "paraview_check.log"), "w") as log:
        log.write("DISPLAY=%s\n%s\n%s" % (display, r.stdout, r.stderr))
    errors = [l for l in r.stderr.splitlines() if "ERR|" in l or "FAILED" in l or "Error" in l]
    check(r.returncode == 0, "paraview_check.py: exit %d (log: %s/paraview_check.log)\n%s"
          % (r.returncode, png_dir, "\n".join(errors[:20])))
    return True


def run(exe, src, mpiexec, ranks, out):
    cmd = [mpiexec, "-n", str(ranks), "--oversubscribe", exe, "-options_file", os.path.join(src, "options/paper.opts")]
    r = subprocess.run(cmd + SCENE + ["-output_dir", out], capture_output=True, text=True)
    check(r.returncode == 0, "run on %d ranks: %s" % (ranks, r.stderr[-2000:]))
    return r.returncode == 0


def check_run(out):
    summary = outputs(out).summary
    for what in (check_mesh, check_fields):
        try:
            what(out, summary)
        except (KeyError, OSError, ValueError) as e:  # outputs of another layout
            check.fail("%s: %s: %s" % (what.__name__, type(e).__name__, e))


ran_paraview = False
if sys.argv[1] == "--existing":
    out, src, png_dir = sys.argv[2:5]
    check_run(out)
    ran_paraview = paraview(out, png_dir)
else:
    exe, src, mpiexec, png_dir = sys.argv[1:5]
    with tempfile.TemporaryDirectory() as tmp:
        outs = [os.path.join(tmp, "np%d" % n) for n in (1, 2)]
        ok = all([run(exe, src, mpiexec, n, o) for n, o in zip((1, 2), outs)])
        if ok:
            for o in outs:
                check_run(o)
            compare_ranks(*outs)
            ran_paraview = paraview(outs[0], png_dir)
if not ran_paraview and not check.failures:
    print("%s: %d passed; skipped: pvpython not installed (apt-get install python3-paraview xvfb)"
          % (check.name, check.count))
    sys.exit(77)
check.finish()
