#!/usr/bin/python3
"""Short runs that cover every 2D data path (generated quad and triangle meshes, a mesh
file with two cracks, Q1 and Q2, MMD and Coulomb contact, heat, camera, local time
stepping, patch source with damping, damping heat and thermoelastic heat, harmonic
start, the periodic continuation with its heat ladder, waves without heat (energy and
crack-state rows per step), heat alone after quiet waves, modes, the contact app, 2 ranks)
and one 3D box (a through crack, camera, crack state). A refactoring that must not change 2D results
runs them before and after and compares each pair with scripts/compare_outputs
(byte-identical CSVs; equal HDF5 datasets).

usage: reference_scenes.py BUILD_DIR OUT_ROOT [MPIEXEC] [NAME ...]
Run from the repository root (the options files include each other by relative path)."""
import os
import subprocess
import sys

PAPER = ["-options_file", "options/paper.opts", "-final_time", "1e-4", "-source_duration", "1e-4",
         "-output_times", "5e-5,1e-4"]
SCENES = {
    "paper": (1, PAPER),
    "paper_np2": (2, PAPER),
    "tri_q1_coulomb": (1, PAPER + ["-mesh_cell", "tri", "-wave_degree", "1", "-crack_law", "coulomb"]),
    "lts": (1, ["-options_file", "options/paper.opts", "-final_time", "6e-5", "-wave_lts", "on",
                "-output_times", "6e-5"]),
    "camera_quiet": (1, ["-options_file", "options/paper.opts", "-source_duration", "5e-5", "-final_time", "3e-3",
                         "-wave_quiet_fraction", "0.05", "-camera", "-camera_fps", "2000",
                         "-camera_integration", "2e-4", "-output_times", "1e-3,3e-3"]),
    "thermosonic": (1, ["-options_file", "options/thermosonic.opts", "-source_duration", "2e-4",
                        "-final_time", "3e-4", "-output_times", "3e-4", "-periodic", "off",
                        "-thermoelastic", "two_way", "-material_damping_heat", "-camera", "false"]),
    "periodic": (1, ["-options_file", "options/thermosonic.opts", "-source_duration", "6e-3", "-final_time", "8e-3",
                     "-output_times", "4e-3,8e-3", "-camera_fps", "2000", "-camera_integration", "2e-4",
                     "-crack_probe", "0.5", "-periodic_tol", "2e-2", "-periodic_fine_periods", "8"]),
    "waves_only": (1, PAPER + ["-heat", "off", "-energy_every", "5", "-crack_state_every", "10", "-crack_probe",
                               "0.5"]),
    "slab3d": (1, ["-options_file", "options/slab3d.opts", "-mesh_h", "0.005", "-mesh_h_crack", "0.001",
                   "-final_time", "3e-5", "-source_duration", "3e-5", "-output_times", "3e-5", "-camera",
                   "-camera_fps", "100000", "-camera_integration", "5e-6", "-crack_state_every", "20"]),
    "mesh_file": (1, ["-mesh_file", "meshes/plate_two_cracks.msh", "-final_time", "2e-5", "-output_times", "2e-5",
                      "-wave_degree", "1"]),
    "modes": (1, ["-specimen_width", "0.05", "-specimen_height", "0.1", "-mesh_h", "0.004", "-crack_center",
                  "0.025,0.05", "-crack_length", "0.02", "-crack_angle", "20", "-modes", "-modes_n", "6",
                  "-modes_target_frequency", "1e5"]),
}


def run(build, root, mpiexec, name):
    ranks, args = SCENES[name]
    out = os.path.join(root, name)
    if name == "contact_app":
        return
    command = ([mpiexec, "-n", str(ranks), "--oversubscribe"] if ranks > 1 else []) + \
              [os.path.join(build, "vibrotherm")] + args + ["-overwrite", "-output_dir", out]
    r = subprocess.run(command, capture_output=True, text=True)
    if r.returncode:
        sys.exit("%s: exit %d: %s" % (name, r.returncode, r.stderr[-2000:]))


def run_contact_app(build, root):
    out = os.path.join(root, "contact_app")
    os.makedirs(out, exist_ok=True)
    for law in ("mmd", "coulomb", "clapping", "linear"):
        r = subprocess.run([os.path.join(build, "vibrotherm-contact"), "-crack_law", law, "-history_a_amplitude",
                            "2e-9", "-history_b_amplitude", "3e-9", "-history_cycles", "3", "-o",
                            os.path.join(out, law + ".csv")], capture_output=True, text=True)
        if r.returncode:
            sys.exit("contact app %s: %s" % (law, r.stderr))


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    build, root = argv[1], argv[2]
    mpiexec = argv[3] if len(argv) > 3 else "mpiexec"
    names = argv[4:] or list(SCENES) + ["contact_app"]
    for name in names:
        print("reference scene", name, flush=True)
        if name == "contact_app":
            run_contact_app(build, root)
        else:
            run(build, root, mpiexec, name)


if __name__ == "__main__":
    main(sys.argv)
