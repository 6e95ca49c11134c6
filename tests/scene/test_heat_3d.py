#!/usr/bin/python3
"""Requirement (issue 26, heat in 3D): a 3D run (options/block3d_small.opts: a box with a
buried inclined crack, waves, MMD contact) heats its own heat mesh (the box again, unsplit,
with layers graded across the crack plane) with the friction power of its contact cells:
 - conservation: the heat the friction deposited is the energy the crack dissipated
   (1e-10), and the heat content plus what left through the faces is what was deposited;
   crack_heat.h5 lists every contact cell with its area (Σ: the crack's area less the
   unsplit front's share, (L1 − h/3)(L2 − h/3) for Q2 faces of size h);
 - the crack-centre temperature is the continuum temperature of the friction power the
   centre cell exchanged (crack_heat.h5), through the kernel of a plane source in an
   infinite body, θ(t) = Σ_k q_k (√(t − t_{k−1}) − √(t − t_k)) / (ρ c √(π α)) (the
   diffusion length, 44 µm at 20 µs, is far below the crack's 0.5 mm node spacing, so the
   crack is a plane there): within 1 % on average over the heat steps of the last third
   of the run and at its end, 5 % at every one of them (the first step after a clapping
   burst carries the time discretisation's error);
 - the camera films the front face (-camera_face front): its frames are written;
 - crack_state.csv is keyed by the position on the crack plane (s1, s2 from the centre
   along the strike and along t2 = -z: the Q2 node lattice inside the 6 x 4 mm crack,
   every contact cell at every record time), and Σ W × area over its rows is the crack's
   dissipated energy in energy.csv at the same time (1e-7: W has 9 digits there);
 - 2 ranks = serial: probe temperatures and camera frames within 1e-6 of the field's peak rise (what the
   solver guarantees: CG to a relative 1e-8 of each heat step's update, whose preconditioner's sums
   and partition differ between the runs; it was 1e-10 while CG iterated to 1e-12, only for this check);
 - the coupled heat steps are mass-dominated (summary.json heat_stiffness_ratio <= 10), so their
   CG takes Jacobi; a run that forces BoomerAMG on them (-heat_pc_type hypre, which also
   checks that a user's -heat_free_pc_type jacobi is taken without the 3D BoomerAMG
   defaults being flagged as unused) gives the same crack-centre temperatures (1e-6 of
   the peak: two preconditioners, each to CG's 1e-8).

usage: test_heat_3d.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import os, subprocess, sys, tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, run_scene, outputs

exe, src, mpiexec = sys.argv[1:4]
check = Checks("heat 3d")
CENTRE = (0.01, 0.01, 0.005)  # the crack's centre (a split vertex: a contact cell)
RHO_C, ALPHA = 2700 * 900.0, 237 / (2700 * 900.0)
opts = ["-options_file", os.path.join(src, "options/block3d_small.opts"),
        "-probe_points", "%g,%g,%g,0.004,0.01,0.002" % CENTRE,
        "-camera_face", "front", "-camera_fps", "2e5", "-camera_integration", "5e-6", "-camera_pixel", "5e-4",
        "-crack_state_every", "40"]


def plane_source(t, q, n):
    """Rise after heat step n of a plane source of density q[k] over (t[k-1], t[k]]."""
    tk = np.concatenate([[0.0], t])
    return np.sum(q[:n + 1] * (np.sqrt(t[n] - tk[:n + 1]) - np.sqrt(t[n] - tk[1:n + 2]))) / (
        RHO_C * np.sqrt(np.pi * ALPHA))


def check_crack_state(out, cells, count):
    rows = outputs(out).rows("crack_state.csv")
    check(rows and list(rows[0].keys()) == "t,crack,xi,s1,s2,x,y,z,a,b,b2,N,T,T2,state,power,W".split(","),
          "crack_state.csv header %s" % (list(rows[0].keys()) if rows else None))
    times = sorted({float(r["t"]) for r in rows})
    check(len(rows) == count * len(times), "%d rows: %d cells x %d times" % (len(rows), count, len(times)))
    s1, s2 = np.array([float(r["s1"]) for r in rows]), np.array([float(r["s2"]) for r in rows])
    check(np.abs(s1).max() <= 3e-3 - 5e-4 + 1e-12 and np.abs(s2).max() <= 2e-3 - 5e-4 + 1e-12,
          "s1, s2 inside the crack less its front: |s1| <= %.4g, |s2| <= %.4g" % (np.abs(s1).max(), np.abs(s2).max()))

    def area(r):  # the cell's area from crack_heat.h5 (crack_state.csv has 9 digits)
        d = np.linalg.norm(cells[:, :3] - np.array([float(r["x"]), float(r["y"]), float(r["z"])]), axis=1)
        return cells[np.argmin(d), 3] if d.min() < 1e-8 else np.nan
    energy = {float(r["t"]): float(r["dissipated"]) for r in outputs(out).rows("energy.csv")}
    matched = [t for t in times if any(abs(t - e) <= 1e-12 for e in energy)]
    check(bool(matched), "a crack_state.csv time that energy.csv has")
    if matched:
        t = matched[-1]
        W = sum(float(r["W"]) * area(r) for r in rows if float(r["t"]) == t)
        D = [v for e, v in energy.items() if abs(e - t) <= 1e-12][0]
        check(D > 0 and abs(W - D) <= 1e-7 * D, "crack_state.csv: sum W x area %.6g = dissipated %.6g at %.4g s"
              % (W, D, t))


def check_heat(out):
    summary = outputs(out).summary
    W, by = summary["dissipated_energy"], summary["heat_deposited_by"]
    check(W > 0 and abs(by.get("friction", 0) - W) <= 1e-10 * W,
          "friction heat %s = dissipated %s" % (by.get("friction"), W))
    balance = summary["heat_content"] + summary["heat_boundary_loss"] - summary["heat_deposited"]
    check(abs(balance) <= 1e-8 * W, "heat content + losses - deposited = %.3g of %.3g" % (balance, W))
    check(summary["max_budget_error"] < 1e-5, "energy budget %.3g" % summary["max_budget_error"])
    check(summary["mesh"]["heat_cells"] > summary["mesh"]["cells"], "a heat mesh of its own, finer across the crack")
    with outputs(out).h5("crack_heat.h5") as f:
        t, q, cells = f["time"][:].ravel(), f["density"][:], f["cells"][:]
    # Q2 faces of size h: a node's area is its Simpson weights' product; the unsplit front
    # carries no cell, so the cells cover (L1 - h/3)(L2 - h/3) of the 6 x 4 mm crack.
    area = (6e-3 - 1e-3 / 3) * (4e-3 - 1e-3 / 3)
    check(abs(cells[:, 3].sum() - area) <= 1e-10 * area, "crack_heat.h5 cell areas sum to %.6g of %.6g"
          % (cells[:, 3].sum(), area))
    i = int(np.argmin(np.linalg.norm(cells[:, :3] - np.array(CENTRE), axis=1)))
    check(np.linalg.norm(cells[i, :3] - np.array(CENTRE)) < 1e-12, "a contact cell at the crack centre")
    rows = {float(r["t"]): float(r["temperature"]) - 293.15
            for r in outputs(out).rows("probes.csv") if r["probe"] == "0"}
    worst, compared, last, errors = 0.0, 0, None, []
    for n in range(len(t)):
        match = [s for s in rows if abs(s - t[n]) <= 1e-12]
        if t[n] < 2 / 3 * t[-1] or not match:
            continue
        reference = plane_source(t, q[:, i], n)
        check(reference > 0, "the crack centre heated by %.3g K at %.4g s" % (reference, t[n]))
        error = abs(rows[match[0]] / reference - 1)
        worst, compared, last = max(worst, error), compared + 1, error
        errors.append(error)
    check(compared >= 5, "%d heat steps compared with the plane source" % compared)
    check(worst <= 0.05, "crack centre vs plane source: worst %.4f over the last third" % worst)
    check(bool(errors) and np.mean(errors) <= 0.01, "crack centre vs plane source: mean %.4f over the last third"
          % (np.mean(errors) if errors else -1))
    check(last is not None and last <= 0.01, "crack centre vs plane source at the end: %s" % last)
    print("plane source: %d steps, worst %.4f, last %.4f" % (compared, worst, last or -1))
    with outputs(out).h5("camera.h5") as f:
        count = summary["camera"]["frames"]
        frames = np.array([f["camera/clean_%d" % k][:] for k in range(count) if "clean_%d" % k in f["camera"]])
    check(count >= 3 and len(frames) == count, "camera.h5: %d noise-free frames of %d" % (len(frames), count))
    check(np.isfinite(frames).all() and frames.max() > 0, "camera frames finite, the face warmed (%.3g K)"
          % frames.max())
    check_crack_state(out, cells, summary["contact_cells"])
    return rows, frames, summary["field_max_temperature_rise"]


with tempfile.TemporaryDirectory() as tmp:
    serial = parallel = None
    if run_scene(check, exe, opts, os.path.join(tmp, "np1")):
        serial = check_heat(os.path.join(tmp, "np1"))
    if run_scene(check, exe, opts, os.path.join(tmp, "np2"), mpiexec, 2):
        parallel = check_heat(os.path.join(tmp, "np2"))
    if serial and parallel:
        a, b = serial[0], parallel[0]
        peak = max(abs(v) for v in a.values())
        worst = max(abs(a[s] - b.get(s, np.inf)) for s in a)
        check(worst <= 1e-6 * peak, "2 ranks: crack-centre temperatures differ by %.3g of %.3g" % (worst, peak))
        if serial[1].shape == parallel[1].shape:  # the face is barely warm: against the field's peak
            diff = np.abs(serial[1] - parallel[1]).max()
            check(diff <= 1e-6 * serial[2], "2 ranks: camera frames differ by %.3g (field peak %.3g)" % (diff, serial[2]))
    out = os.path.join(tmp, "info")  # the coupled steps' solver, as PETSc's -info says it was chosen
    r = subprocess.run([exe] + opts + ["-final_time", "2e-6", "-info", ":ksp", "-output_dir", out],
                       capture_output=True, text=True)
    chosen = [l for l in r.stdout.splitlines() if "heat_: stiffness-to-mass ratio" in l]
    check(r.returncode == 0 and bool(chosen) and chosen[0].endswith(": Jacobi"),
          "the coupled heat steps take CG + Jacobi: %s" % chosen[:2])
    if parallel:
        ratio = outputs(tmp, "np2").summary["derived"].get("heat_stiffness_ratio")
        check(ratio is not None and 0 < ratio <= 10, "coupled heat steps mass-dominated: ratio %s" % ratio)
        amg = os.path.join(tmp, "amg")
        if run_scene(check, exe, opts + ["-heat_pc_type", "hypre", "-heat_free_pc_type", "jacobi"], amg, mpiexec, 2):
            other = {float(r["t"]): float(r["temperature"]) - 293.15
                     for r in outputs(amg).rows("probes.csv") if r["probe"] == "0"}
            a = parallel[0]
            peak = max(abs(v) for v in a.values())
            worst = max(abs(a[s] - other.get(s, np.inf)) for s in a)
            check(worst <= 1e-6 * peak, "BoomerAMG on the coupled steps: crack-centre temperatures differ by %.3g "
                  "of %.3g" % (worst, peak))
check.finish()
