#!/usr/bin/python3
"""Requirement: `vibrotherm -mesh_only` on the paper scene writes summary.json,
mesh.h5 and mesh.xmf (complete, readable; grids wave, cracks, heat), and the serial and 2-rank runs give
the same mesh (counts, crack facets, node pairs, length).

usage: test_mesh_scene.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs
import xml.etree.ElementTree as ET

exe, src, mpiexec = sys.argv[1:4]
check = Checks("mesh scene")


summaries = {}
with tempfile.TemporaryDirectory() as tmp:
    for ranks in (1, 2):
        out = os.path.join(tmp, "np%d" % ranks)
        cmd = [mpiexec, "-n", str(ranks), "--oversubscribe", exe, "-options_file",
               os.path.join(src, "options/paper.opts"), "-mesh_only", "-output_dir", out]
        r = subprocess.run(cmd, capture_output=True, text=True)
        check(r.returncode == 0, "run on %d ranks: %s" % (ranks, r.stderr))
        if r.returncode:
            continue
        s = outputs(out).summary
        summaries[ranks] = s
        # The memory estimate printed before meshing counts cells within a factor 2.
        estimate = [l for l in r.stdout.splitlines() if l.startswith("Memory estimate:")]
        check(len(estimate) == 1, "one memory estimate line: %s" % r.stdout[:500])
        if estimate:
            cells = float(estimate[0].split()[2])
            check(0.5 < cells / s["mesh"]["cells"] < 2.0,
                  "estimated %g wave cells vs %d made" % (cells, s["mesh"]["cells"]))
        check(s["ranks"] == ranks, "ranks in summary")
        check(not any(f.endswith(".partial") for f in os.listdir(out)), "partial files left")
        xmf = ET.parse(os.path.join(out, "mesh.xmf")).getroot()
        grids = {g.get("Name"): g for g in xmf.iter("Grid") if g.get("GridType") == "Uniform"}
        check(set(grids) == {"wave", "cracks", "heat"}, "xmf grids %s" % set(grids))
        counts = {"wave": s["mesh"]["cells"], "cracks": s["mesh"]["cohesive_cells"], "heat": s["mesh"]["heat_cells"]}
        for name, cells in counts.items():
            if name in grids:
                topo = grids[name].find("Topology")
                check(int(topo.get("NumberOfElements")) == cells, "xmf %s cell count" % name)
        try:
            with outputs(out).h5("mesh.h5") as f:
                for name, cells in counts.items():
                    check(f[name + "/topology"].shape[0] == cells, "h5 %s cells" % name)
                check(f["wave/geometry"].shape[0] == s["mesh"]["vertices"], "h5 wave vertices")
                check(f["heat/geometry"].shape[0] == s["mesh"]["heat_vertices"], "h5 heat vertices")
        except ImportError:
            check.fail("python3-h5py missing")

if 1 in summaries and 2 in summaries:
    m1, m2 = summaries[1]["mesh"], summaries[2]["mesh"]
    for key in ("cells", "vertices", "cohesive_cells", "heat_cells", "heat_vertices", "h_min", "h_max"):
        check(m1[key] == m2[key], "%s: serial %s vs 2 ranks %s" % (key, m1[key], m2[key]))
    for c1, c2 in zip(m1["cracks"], m2["cracks"]):
        same_counts = all(c1[k] == c2[k] for k in ("name", "facets", "contact_node_pairs", "buried_tips"))
        check(same_counts, "crack counts differ between 1 and 2 ranks: %s vs %s" % (c1, c2))
        # Summation order differs across ranks: equal to rounding.
        check(abs(c1["length"] - c2["length"]) <= 1e-14 * c1["length"], "crack length differs across ranks")
    c = m1["cracks"][0]
    check(abs(c["length"] - 0.02) <= 1e-12 * 0.02, "paper crack length %r" % c["length"])
    check(c["contact_node_pairs"] == c["facets"] - 1 and c["buried_tips"] == 2, "paper crack pairs/tips")
    check(sum(m2["cells_per_rank"]) == m2["cells"], "cells per rank add up")

check.finish()
