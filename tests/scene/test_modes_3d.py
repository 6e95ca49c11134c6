#!/usr/bin/python3
"""Requirement (issue 26: -modes in 3D): `vibrotherm -modes` on a 3D box. The reference is
the 2D modal analysis (itself checked against closed forms in test_modes.py) through the
2D = 3D identity of a plane-strain slab: a slab of one Q2 hexahedron layer with roller
front and back faces and a through-thickness crack has the 2D twin's in-plane modes (the
twin: paper.opts on the slab's x-y section, scripts/slab_section), so that
 - the lowest modes near the target have the twin's frequencies to 1e-9 (the slab's
   thickness modes lie in the MHz, far above);
 - and its defect participation (3D: the strain energy within -modes_defect_radius of
   the crack's rectangle) to 1e-9;
 - 2 ranks give the serial frequencies and participations to 1e-9;
 - modes.csv, modes.h5 (3D hexahedra) and modes.xmf are written;
 - the check discriminates: free front and back faces (plane stress, in-plane stiffness
   E/(1 − ν²) instead of the plane-strain one) move a mode by more than 1 %;
 - before factoring, the run prints MUMPS's own memory estimate for the factorisation and
   refuses, in one line naming -modes_memory_limit, when it exceeds that limit.

usage: test_modes_3d.py VIBROTHERM MPIEXEC SOURCE_DIR"""
import os, re, subprocess, sys, tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, one_line_error, outputs

exe, mpiexec, src = sys.argv[1:4]
check = Checks("modes_3d")
DEPTH = 0.001
COARSE = ["-mesh_h", "0.004", "-mesh_h_crack", "0.001"]
MODES = ["-modes", "-modes_n", "6", "-modes_target_frequency", "6e4"]
SLAB = ["-options_file", os.path.join(src, "options/slab3d.opts"), "-specimen_depth", str(DEPTH),
        "-crack_center", "0.025,0.05,%g" % (DEPTH / 2), "-crack_width", str(DEPTH)] + COARSE
TWIN = ["-options_file", os.path.join(src, "options/paper.opts")] + COARSE


def run(args, out, ranks=1):
    command = ([mpiexec, "-n", str(ranks), "--oversubscribe"] if ranks > 1 else []) + [exe] + args
    r = subprocess.run(command + ["-output_dir", out], capture_output=True, text=True)
    check(r.returncode == 0, "%s: exit %d: %s" % (os.path.basename(out), r.returncode, r.stderr[-1500:]))
    return r.returncode == 0


def modes(out):
    """(frequency, participation) arrays of a modes run."""
    rows = outputs(out).rows("modes.csv")
    return (np.array([float(r["frequency"]) for r in rows]), np.array([float(r["participation"]) for r in rows]))


def agree(label, a, b, tol):
    (fa, pa), (fb, pb) = a, b
    check(len(fa) == len(fb) == 6, "%s: 6 modes each (%d, %d)" % (label, len(fa), len(fb)))
    if len(fa) != len(fb):
        return
    df, dp = np.abs(fa / fb - 1).max(), np.abs(pa - pb).max()
    print("%s: frequencies within %.2e, participations within %.2e" % (label, df, dp))
    check(df <= tol, "%s: frequencies differ by %.3g (tolerance %g): %s vs %s" % (label, df, tol, fa, fb))
    check(dp <= tol, "%s: participations differ by %.3g (tolerance %g): %s vs %s" % (label, dp, tol, pa, pb))


with tempfile.TemporaryDirectory() as tmp:
    path = lambda name: os.path.join(tmp, name)
    r = subprocess.run([exe] + SLAB + MODES + ["-modes_memory_limit", "1e-6", "-output_dir", path("limit")],
                       capture_output=True, text=True)
    estimate = re.search(r"Modes: MUMPS estimates (\S+) GB", r.stdout)
    check(estimate is not None and float(estimate.group(1)) > 0,
          "the run prints MUMPS's memory estimate (> 0): %s" % r.stdout[-600:])
    one_line_error(check, "-modes_memory_limit 1e-6", r.returncode, r.stderr, "-modes_memory_limit", "MUMPS")
    # The slab's grid for its 2D twin: a wave run of one output (no heat).
    grid = run(SLAB + ["-heat", "off", "-final_time", "1e-7", "-output_times", "1e-7"], path("grid"))
    if grid:
        r = subprocess.run(["/usr/bin/python3", os.path.join(src, "scripts/slab_section"), path("grid"),
                            path("section.msh")], capture_output=True, text=True)
        check(r.returncode == 0, "slab_section: %s" % r.stderr[-1000:])
    ok = grid and all([run(SLAB + MODES, path("slab")), run(TWIN + MODES + ["-mesh_file", path("section.msh")],
                                                              path("twin")),
                       run(SLAB + MODES, path("slab_np2"), ranks=2),
                       run(SLAB + MODES + ["-edge_front", "free", "-edge_back", "free"], path("free"))])
    if ok:
        slab, twin = modes(path("slab")), modes(path("twin"))
        print("slab modes [Hz]:", ", ".join("%.2f (%.3f)" % fp for fp in zip(*slab)))
        check(np.all((slab[1] > 0) & (slab[1] < 1)), "participations in (0, 1): %s" % slab[1])
        agree("slab vs 2D twin", slab, twin, 1e-9)
        agree("2 ranks vs serial", modes(path("slab_np2")), slab, 1e-9)
        free = modes(path("free"))[0]
        shift = np.abs(free[:len(slab[0])] / slab[0] - 1).max()
        print("free front/back faces: the modes move by up to %.3g" % shift)
        check(shift > 1e-2, "free front/back faces (plane stress) move no mode by 1 %% (%.3g)" % shift)
        for name in ("modes.h5", "modes.xmf"):
            check(os.path.exists(path("slab/" + name)), "slab: %s written" % name)
        with h5py.File(path("slab/modes.h5"), "r") as f:
            topology = f["wave/topology"]
            check(topology.shape[1] == 8 and f["wave/geometry"].shape[1] == 3,
                  "modes.h5: hexahedra in 3D (topology %s, geometry %s)" % (topology.shape, f["wave/geometry"].shape))
check.finish()
