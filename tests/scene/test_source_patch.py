#!/usr/bin/python3
"""Requirement (issue 24): a transducer patch source on a segment of an edge
(-source_patch_edge, -source_patch_center, -source_patch_width); the rest of the edge keeps its
own kind. Checked: inside the patch the prescribed component follows the source, just outside
the edge is free; a patch covering the whole edge is the edge source (same outputs); driving a
free specimen through a patch closes the energy budget (work of the source = kinetic + strain
energy, 1e-5 as for every displacement source); bad patches are refused naming the option.

usage: test_source_patch.py VIBROTHERM SOURCE_DIR"""
import os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, run_scene, outputs

exe, src = sys.argv[1:3]
check = Checks("source patch")
paper = ["-options_file", os.path.join(src, "options/paper.opts"), "-final_time", "4e-5", "-heat", "off",
         "-wave_degree", "2"]
top_probes = ["-probe_points", "0.03,0.1,0.0345,0.1,0.0356,0.1,0.01,0.1", "-crack_probe", "0.5"]


def probes(out):
    return outputs(out).columns("probes.csv")


with tempfile.TemporaryDirectory() as tmp:
    patch = os.path.join(tmp, "patch")
    if run_scene(check, exe, paper + top_probes + ["-edge_top", "free", "-source_patch_edge", "top",
                                                   "-source_patch_center", "0.03", "-source_patch_width", "0.01"], patch):
        p = probes(patch)
        ux = [p["ux"][p["probe"] == k] for k in range(4)]
        check(np.allclose(ux[0], ux[1], rtol=0, atol=1e-12 * abs(ux[0]).max()) and abs(ux[0]).max() > 1e-8,
              "inside the patch ux is the prescribed signal")
        check(np.abs(ux[2] - ux[1]).max() > 1e-3 * abs(ux[1]).max(), "just outside the patch the edge moves freely")
    whole, edge = os.path.join(tmp, "whole"), os.path.join(tmp, "edge")
    ok = run_scene(check, exe, paper + ["-edge_top", "free", "-source_patch_edge", "top", "-source_patch_width",
                                        "0.05"], whole)
    if ok and run_scene(check, exe, paper, edge):
        a, b = probes(whole), probes(edge)
        check(a["ux"].shape == b["ux"].shape and np.allclose(a["ux"], b["ux"], rtol=0, atol=1e-12 * abs(b["ux"]).max()),
              "a patch over the whole edge is the edge source")
    free = os.path.join(tmp, "free")
    if run_scene(check, exe, ["-specimen_width", "0.04", "-specimen_height", "0.02", "-mesh_h", "0.002",
                              "-wave_degree", "2", "-edge_top", "free", "-edge_bottom", "free", "-edge_left", "free",
                              "-edge_right", "free", "-source_patch_edge", "top", "-source_patch_width", "0.008",
                              "-source_component", "normal", "-source_duration", "5e-5", "-final_time", "8e-5",
                              "-heat", "off"], free):
        s = outputs(free).summary
        check(s["max_budget_error"] < 1e-5, "free specimen driven by a patch: budget error %g" % s["max_budget_error"])
    bad = {
        "leaves the top edge": ["-source_patch_edge", "top", "-source_patch_center", "0.048", "-source_patch_width",
                                "0.01"],
        "-source_patch_width must be > 0": ["-source_patch_edge", "top", "-source_patch_width", "0"],
        "cannot be source": ["-source_patch_edge", "top", "-source_patch_width", "0.01"],
        "given without -source_patch_edge": ["-source_patch_width", "0.01"],
    }
    for message, extra in bad.items():
        r = subprocess.run([exe] + paper + extra + ["-output_dir", os.path.join(tmp, "bad")], capture_output=True,
                           text=True)
        check(r.returncode == 2 and message in r.stderr + r.stdout,
              "bad patch (%s): exit %d, %s" % (message, r.returncode, (r.stderr + r.stdout)[-300:]))
check.finish()
