#!/usr/bin/python3
"""Requirement (issue 26, item 7, the 2D = 3D check): a slab of one Q2 hexahedron layer with
roller front and back faces (plane strain) and a through-thickness crack reproduces the 2D
paper scene. The slab is options/slab3d.opts made coarse for CI (4 mm, 1 mm on the crack
and through the 1 mm depth, 0.1 ms of excitation); its 2D twin is options/paper.opts on the
slab's x-y section (scripts/slab_section: the same nodes in x and y) at the same fixed step,
so the two discretisations are the same and only the crack law's two slip components
(the vector spring bed of the mmd law against the 2D memory diagram) differ:
 - the split: one cohesive cell per crack face (through the depth), 4 front vertices (the
   two tip lines only), a contact cell per Q2 node pair of the crack faces including those
   on the front and back faces;
 - energy.csv (3D in J divided by the depth, 2D in J/m), the same rows: the dissipated
   energy within 2e-3 (issue: 1 %; measured 3.8e-4, the vector bed's friction work being
   second order in the step where the diagram's is exact), every other column within 1e-4 of its largest value;
   the probes (mid-depth in 3D) within 1e-3 of each component's amplitude (issue: 1 %),
   uz below 1e-9 of the ux amplitude; the slab's step never reduced (wave_dt_reductions 0);
 - the crack-centre temperature (both runs with heat; the slab's front and back faces
   insulated, as plane strain is in z): at every source-period end within 2 % of the twin's
   peak (issue: 2 %; measured 0.6 %). A period end, not every heat step: a clapping burst
   heats the crack's first µm within one heat step, and the two laws' bursts may fall a
   step apart (pointwise 15 % at a burst's top). The check discriminates: the slab with
   sink front and back faces (the 3D default) differs by more than 2 %;
 - with the coulomb law (one component of the vector law is the 2D law operation for
   operation) the agreement is to rounding: energies and probes within 1e-9;
 - the check discriminates: absorbing front and back faces instead of rollers, or free ones
   (plane stress), change the dissipated energy and the probes by more than 1 %.

Serial runs, two at a time once the twin's mesh exists (a loaded 2-core machine runs two
ranks slower); the coulomb pair and the slabs with other faces run the first half of the
excitation only.

usage: test_slab_2d3d.py VIBROTHERM SOURCE_DIR"""
import concurrent.futures, csv, os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, run_scene, outputs

exe, src = sys.argv[1:3]
check = Checks("slab_2d3d")
DEPTH, DT, T = 0.001, 3.5e-8, 1e-4  # DT: 0.7 of the slab's stability limit 5.03e-8 s (0.84: reduced)
PROBES = [(0.025, 0.095), (0.025, 0.06), (0.0344, 0.0534)]  # near the top, above the crack, a tip
CENTRE, PERIOD = (0.025, 0.05), 1e-5  # the crack centre: a temperature probe only (its wave side is either face)
COARSE = ["-mesh_h", "0.004", "-mesh_h_crack", "0.001", "-source_duration", str(T), "-final_time", str(T),
          "-wave_dt", str(DT), "-probe_every", "5"]
SLAB = ["-options_file", os.path.join(src, "options/slab3d.opts"), "-specimen_depth", str(DEPTH),
        "-crack_center", "0.025,0.05,%g" % (DEPTH / 2), "-crack_width", str(DEPTH),
        "-probe_points", ",".join("%g,%g,%g" % (x, y, DEPTH / 2) for x, y in PROBES + [CENTRE])] + COARSE
TWIN = ["-options_file", os.path.join(src, "options/paper.opts"), "-output_times", str(T),
        "-probe_points", ",".join("%g,%g" % p for p in PROBES + [CENTRE])] + COARSE
CRACK_FACES, LAYERS = 20, 1  # 20 mm / 1 mm along the strike, 1 mm / 1 mm through the depth
CONTACT_CELLS = (2 * CRACK_FACES - 1) * (2 * LAYERS + 1)  # Q2 node pairs but the two tip lines


def number(text):
    try:
        return float(text)
    except ValueError:  # empty (no temperature in 3D) or a crack probe's state
        return float("nan")


def table(path):
    rows = list(csv.DictReader(open(path)))
    return {k: np.array([number(r[k]) for r in rows]) for k in rows[0]}


def run(args, out):
    """summary.json, energy.csv and probes.csv of a serial run (None if it failed)."""
    if not run_scene(check, exe, args, out):
        return None
    return (outputs(out).summary, table(os.path.join(out, "energy.csv")),
            table(os.path.join(out, "probes.csv")))


def at_times(table, times):
    """The rows of table whose t is one of times (the same step count: the same t)."""
    keep = np.isin(np.round(table["t"] / DT).astype(int), times)
    return {k: v[keep] for k, v in table.items()}


def differences(slab, twin):
    """Per energy column and probe component: the largest difference over the rows both
    runs wrote (the slab's last row may fall between the twin's), relative to the twin's
    largest magnitude (slab energies divided by the depth); None unless the twin has
    every row of the slab but its last."""
    if slab is None or twin is None:
        return None
    steps = lambda run: np.round(run[1]["t"] / DT).astype(int)
    common = np.intersect1d(steps(slab), steps(twin))
    if len(common) < len(steps(slab)) - 1:
        print("rows: the slab's %d energy rows, %d at the twin's times" % (len(steps(slab)), len(common)))
        return None
    (e3, p3), (e2, p2) = [(at_times(run[1], common), at_times(run[2], common)) for run in (slab, twin)]
    rows = lambda p, k: p["probe"] == k  # the point probes (the twin adds paper.opts' crack probes)
    d = {}
    for k in ("work_source", "kinetic", "strain", "radiated", "interface_stored", "dissipated"):
        d[k] = np.abs(e3[k] / DEPTH - e2[k]).max() / (np.abs(e2[k]).max() or 1.0)
    for p in range(len(PROBES)):
        m3, m2 = rows(p3, p), rows(p2, p)
        for c in ("ux", "uy", "vx", "vy"):
            d["probe%d %s" % (p, c)] = np.abs(p3[c][m3] - p2[c][m2]).max() / np.abs(p2[c][m2]).max()
    return d


def crack_centre_temperature(slab, twin):
    """The largest difference of the crack-centre rise at the source-period ends (the
    twin's rows), relative to the twin's largest rise over all its rows."""
    def centre(run):
        probes = run[2]
        mine = probes["probe"] == len(PROBES)
        return probes["t"][mine], probes["temperature"][mine] - 293.15

    (t3, T3), (t2, T2) = centre(slab), centre(twin)
    ends = np.arange(1, int(round(T / PERIOD)) + 1) * PERIOD
    check(np.array_equal(t3, t2), "the crack-centre probe has the same rows in both runs")
    check(np.isfinite(T3).all() and np.isfinite(T2).all() and T2.max() > 0, "the crack centre heats in both runs")
    if not np.array_equal(t3, t2):
        return np.inf
    return np.abs(np.interp(ends, t3, T3) - np.interp(ends, t2, T2)).max() / T2.max()


def agree(label, d, tol_dissipated, tol_energy, tol_probes):
    check(d is not None, "%s: the slab and the twin have the same rows" % label)
    for k, v in (d or {}).items():
        tol = tol_dissipated if k == "dissipated" else tol_probes if k.startswith("probe") else tol_energy
        check(v <= tol, "%s %s: slab and twin differ by %.3g (tolerance %g)" % (label, k, v, tol))
    if d:
        print("%s: dissipated %.3g, worst energy %.3g, worst probe %.3g" % (
            label, d["dissipated"], max(v for k, v in d.items() if not k.startswith("probe") and k != "dissipated"),
            max(v for k, v in d.items() if k.startswith("probe"))))


def check_split(summary):
    mesh = summary["mesh"]
    crack = mesh["cracks"][0]
    check(mesh["cohesive_cells"] == CRACK_FACES * LAYERS == crack["facets"],
          "cohesive cells %s = crack faces %s = %d" % (mesh["cohesive_cells"], crack["facets"], CRACK_FACES * LAYERS))
    check(crack["buried_tips"] == 2 * (LAYERS + 1), "front vertices %s: the two tip lines" % crack["buried_tips"])
    check(summary["contact_cells"] == CONTACT_CELLS,
          "contact cells %s, expected %d (front and back face nodes too)" % (summary["contact_cells"], CONTACT_CELLS))
    check(abs(crack["area"] - 0.02 * DEPTH) < 1e-12, "crack area %s: through the depth" % crack["area"])


with tempfile.TemporaryDirectory() as tmp:
    path = lambda name: os.path.join(tmp, name)
    slab = run(SLAB + ["-output_times", str(T)], path("slab"))
    if slab:
        check_split(slab[0])
        check(slab[0]["wave_dt_reductions"] == 0, "the slab's step was reduced: lower DT")
        points = slab[2]["probe"] < len(PROBES)  # not the crack centre: one face's node of the split
        uz = np.abs(slab[2]["uz"][points]).max() / np.abs(slab[2]["ux"][points]).max()
        check(uz < 1e-9, "plane strain: uz %.3g of the ux amplitude" % uz)
        r = subprocess.run(["/usr/bin/python3", os.path.join(src, "scripts/slab_section"), path("slab"),
                            path("section.msh")], capture_output=True, text=True)
        check(r.returncode == 0, "slab_section: %s" % r.stderr[-1000:])
    twin = run(TWIN + ["-mesh_file", path("section.msh")], path("twin")) if slab else None
    if slab and twin:
        check(twin[0]["mesh"]["cells"] == slab[0]["mesh"]["cells"], "the twin has the slab's cells in x-y")
        agree("mmd", differences(slab, twin), 2e-3, 1e-4, 1e-3)
        dT = crack_centre_temperature(slab, twin)
        print("crack-centre temperature at period ends: slab and twin differ by %.3g of the peak" % dT)
        check(dT <= 2e-2, "crack-centre temperature: slab and twin differ by %.3g of the peak (issue: 2 %%)" % dT)
        half = ["-final_time", str(T / 2)]
        coulomb = ["-crack_law", "coulomb"] + half
        faces = {kind: ["-edge_front", kind, "-edge_back", kind] for kind in ("absorbing", "free")}
        jobs = {"slab_c": SLAB + coulomb, "twin_c": TWIN + coulomb + ["-mesh_file", path("section.msh")],
                **{kind: SLAB + half + faces[kind] for kind in faces},
                "sink": SLAB + ["-heat_bc_front", "sink", "-heat_bc_back", "sink"]}
        with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:  # two cores: two serial runs at once
            runs = dict(zip(jobs, pool.map(lambda name: run(jobs[name], path(name)), jobs)))
        agree("coulomb", differences(runs["slab_c"], runs["twin_c"]), 1e-9, 1e-9, 1e-9)
        dT = runs["sink"] and crack_centre_temperature(runs["sink"], twin)
        print("sink front/back: crack-centre temperature differs by %.3g of the peak" % dT)
        check(dT > 2e-2, "sink front/back: the crack-centre temperature differs by %.3g only" % dT)
        for kind in faces:  # damped faces; free faces: plane stress, not strain
            d = differences(runs[kind], twin)
            probes = d and max(v for k, v in d.items() if k.startswith("probe"))
            print("%s front/back: dissipated %.3g, worst probe %.3g" % (kind, d["dissipated"], probes) if d else kind)
            check(d is not None and d["dissipated"] > 1e-2 and probes > 1e-2,
                  "%s front/back: the dissipated energy or the probes differ by 1 %% or less (%s, %s)" %
                  (kind, d and d["dissipated"], probes))
check.finish()
