#!/usr/bin/python3
"""Requirement (issue 16): every option the programs declare, given a bad value,
is one line on stderr naming the option, exit code 2 and nothing written -- or the
value is a documented valid one (ALLOWED below) and the run ends normally with
finite outputs.

The options come from the programs themselves: `vibrotherm -help` and
`vibrotherm-contact -help`, so an option added tomorrow is tested tomorrow. Each
(option, value) pair runs one short scene (a 2 cm square with one crack, coarse
mesh, 2 microseconds: well under a second). A run fails when it exits 1, prints
more than one stderr line or a PETSc traceback, does not name the option, writes
anything before its error, takes more than TIMEOUT seconds, or exits 0 for a value
that is not in ALLOWED or with NaN/inf in summary.json, energy.csv or probes.csv
(there in the columns that always apply; vibrotherm-contact: in its CSV).

Values: nan, inf, -inf, -1, 0, abc and the empty string. In CI (the default) every
option gets nan, -1 and abc, and one of the other four values in turn (option i
gets EXTRA[i % 4]), which keeps the suite under about four minutes on two busy
cores; --full tries every value on every option.

usage: test_generated_bad_input.py VIBROTHERM VIBROTHERM_CONTACT [--full]
           [--only REGEX] [--values v1,v2,...] [--timeout SECONDS]"""
import argparse, concurrent.futures, csv, json, os, re, subprocess, sys, tempfile, time

VALUES = ["nan", "inf", "-inf", "-1", "0", "abc", ""]
CORE = ["nan", "-1", "abc"]
EXTRA = ["inf", "0", "", "-inf"]

# vibrotherm -help also lists PETSc's own options. Tested here: the options
# vibrotherm declares itself, i.e. the sections after the "vibrotherm:" header
# (PetscInitialize's generic options and PetscDevice sections come before it).
# Skipped even there, should a solver object print its options one day: the
# prefixes vibrotherm hands to PETSc objects (their values are PETSc's to check,
# and CheckScene refuses the few vibrotherm sets itself) and PETSc's generic ones.
PETSC_PREFIXES = ("-wave_ts_", "-wave_snes_", "-wave_ksp_", "-wave_pc_", "-heat_ts_", "-heat_snes_", "-heat_ksp_",
                  "-heat_pc_", "-heat_free_", "-heat_redundant_", "-modes_eps_", "-modes_st_", "-modes_ksp_",
                  "-modes_pc_", "-modes_mat_", "-petscpartitioner_", "-mat_", "-vec_", "-log", "-malloc",
                  "-options_", "-info", "-device_", "-root_device_context_", "-default_device_type")
# Not values of a scene: -help prints and exits, -version likewise; -options_file is
# a file of options (test_first_hour and test_bad_input cover it).
NOT_TESTED = {"-help", "-h", "-version", "-options_file"}

# The scene every vibrotherm case runs: small, one crack, a few wave steps.
SCENE = ["-specimen_width", "0.02", "-specimen_height", "0.02", "-mesh_h", "0.004", "-mesh_h_crack", "0.002",
         "-crack_center", "0.01,0.01", "-crack_length", "0.006", "-crack_angle", "20", "-final_time", "2e-6",
         "-wave_degree", "1"]
# Options read only in some scenes: the case adds what makes the option count, so
# an ignored value cannot pass for a checked one.
CONTEXT = {
    "-modes_n": ["-modes"], "-modes_target_frequency": ["-modes"], "-modes_defect_radius": ["-modes"],
    "-contact_table_file": ["-contact_normal_law", "table"],
    "-crack_a0_file": ["-crack_a0_profile", "file"],
    "-crack_a0_max": ["-crack_a0_profile", "elliptic"],
    "-heat_crack_power": ["-physics", "heat"],
    "-material_expansion": ["-thermoelastic", "one_way"],
    "-heat_T_ext": ["-heat_bc", "convective"], "-heat_h": ["-heat_bc", "convective"],
    "-crack_probe_crack": ["-crack_probe", "0.5"],
}
# vibrotherm-contact: a short built-in history written to a file.
CONTACT_SCENE = ["-history_cycles", "1", "-history_steps_per_cycle", "20"]
CONTACT_CONTEXT = {"-contact_table_file": ["-contact_normal_law", "table"],
                   # A second tangential component needs a law that takes two (not mmd, the default).
                   **{"-history_b2_" + f: ["-crack_law", "coulomb"] for f in ("amplitude", "offset", "phase", "rate")}}

ANY_NAME = set(VALUES) - {""}
# Documented valid values: (option) -> values that must run (exit 0, finite outputs).
ALLOWED = {
    # Angles in degrees: any finite angle is a direction.
    "-crack_angle": {"-1", "0"},
    # Initial approach: "> 0: pre-closed, < 0: gap" -- any sign.
    "-crack_a0": {"-1", "0"}, "-crack_a0_max": {"-1", "0"},
    # A signed amplitude (the phase); 0 drives nothing (refused, issue 43).
    "-source_amplitude": {"-1"},
    # ">= 0" in -help: friction-free, adiabatic edges, no crack power, no dissipation-quiet test.
    "-contact_mu": {"0"}, "-heat_h": {"0"}, "-heat_crack_power": {"0"}, "-wave_quiet_fraction": {"0"},
    "-modes_defect_radius": {"0"},
    # "default: cfl x stability limit" / "0: none" / no refinement / a crack end.
    "-wave_dt": {"0"}, "-crack_state_every": {"0"}, "-dm_refine": {"0"}, "-crack_probe": {"0"},
    # Output times: t = 0 is the initial state.
    "-output_times": {"0"},
    # Poisson ratio in (-1, 0.5): 0 is valid.
    "-material_nu": {"0"},
    # "0: no damping" (-help).
    "-material_loss_factor": {"0"},
    # No thermoelastic coupling (-help: "(-thermoelastic)"; the heat reader wants >= 0).
    "-material_expansion": {"0"},
    # "0: a 2D plane-strain specimen" (-help).
    "-specimen_depth": {"0"},
    # Abrupt switch-on; uniform element size.
    "-source_ramp_cycles": {"0"}, "-mesh_grading": {"0"}, "-heat_mesh_grading": {"0"},
    # A mirror band of half-width 0 is none (-mesh_crack_mirror off).
    "-mesh_crack_mirror": {"0"},
    # Booleans: 0 is false; a bare flag ("") is true.
    "-mesh_only": {"0", ""}, "-modes": {"0", ""}, "-allow_unknown": {"0", ""}, "-heat_lumped_mass": {"0", ""},
    "-heat_near_field": {"0", ""},
    # The camera switch and -force are booleans; any integer seeds the noise; 0 fps: no camera.
    "-camera": {"0", ""}, "-force": {"0", ""}, "-camera_seed": {"-1", "0"}, "-camera_fps": {"0"},
    "-debug": {"0", ""}, "-overwrite": {"0", ""},
    # 0: checkpoints only when a signal stops the run.
    "-checkpoint_every_s": {"0"},
    # 0: the waves run again only where the source changes; the drift is reported only.
    "-periodic_refresh": {"0"}, "-periodic_drift_tol": {"0"},
    # A directory name is any name; so is the name of a state file to write.
    "-output_dir": ANY_NAME, "-periodic_save_state": ANY_NAME,
}
CONTACT_ALLOWED = {
    "-contact_a0": {"-1", "0"}, "-contact_mu": {"0"}, "-material_nu": {"0"},
    # History sinusoids: any amplitude, offset, phase or drift; no ramp.
    **{"-history_%s_%s" % (x, f): {"-1", "0"} for x in ("a", "b", "b2") for f in ("amplitude", "offset", "phase", "rate")},
    "-history_ramp_cycles": {"0"},
    # Output file: any name.
    "-o": ANY_NAME,
}


def declared_options(exe, after_header):
    """Option names of the help of exe, after the line after_header (None: all)."""
    r = subprocess.run([exe, "-help"], capture_output=True, text=True, timeout=60)
    if r.returncode != 0:
        sys.exit("%s -help: exit %d\n%s" % (exe, r.returncode, r.stderr))
    lines = r.stdout.splitlines()
    if after_header is not None:
        lines = lines[lines.index(after_header) + 1:]
    names = []
    for line in lines:
        m = re.match(r"\s+(-[A-Za-z][A-Za-z0-9_]*)(?=[\s:<]|$)", line)
        if m and m.group(1) not in names and m.group(1) not in NOT_TESTED and not m.group(1).startswith(PETSC_PREFIXES):
            names.append(m.group(1))
    return names


def non_finite(text):
    return re.search(r"(?<![A-Za-z_])-?(nan|inf|infinity)(?![A-Za-z_])", text, re.IGNORECASE) is not None


# probes.csv writes nan where a column does not apply (a point probe's crack columns,
# a crack probe's velocity, the temperature when no heat runs): only these always apply.
CSV_COLUMNS = {"probes.csv": {"t", "probe", "x", "y", "ux", "uy"}}


def refuse_constant(name):
    raise ValueError("holds " + name)


def output_problem(files):
    """Why the outputs of a normal run are not acceptable ('' when they are)."""
    present = [f for f in files if os.path.exists(f)]
    if not present:
        return "no output written"
    for f in present:
        if f.endswith(".json"):
            try:
                with open(f) as fh:
                    json.load(fh, parse_constant=refuse_constant)
            except ValueError as e:
                return "%s: %s" % (os.path.basename(f), e)
        elif f.endswith(".csv"):
            columns = CSV_COLUMNS.get(os.path.basename(f))
            with open(f) as fh:
                for row in csv.DictReader(fh):
                    for k, v in row.items():
                        if (columns is None or k in columns) and non_finite(v or ""):
                            return "%s holds %s = %s" % (os.path.basename(f), k, v)
    return ""


def names_option(line, option):
    return re.search(re.escape(option) + r"(?![A-Za-z0-9_])", line) is not None


def verdict(option, value, code, stderr, out_path, allowed, out_files, elapsed):
    """'' for a pass, else why the case failed."""
    lines = [l for l in stderr.splitlines() if l.strip()]
    if code is None:
        return "no answer after %.0f s" % elapsed
    if code == 0:
        if value not in allowed.get(option, ()):
            return "exit 0: accepted, but not a documented valid value"
        return output_problem(out_files)
    first = (lines[0] if lines else "(nothing on stderr)")[:200]
    if code != 2:
        return "exit %d: %s" % (code, first)
    if len(lines) != 1:
        return "exit 2 with %d stderr lines: %s" % (len(lines), " | ".join(l[:100] for l in lines[:3]))
    if not names_option(lines[0], option):
        return "exit 2 without naming %s: %s" % (option, first)
    if os.path.exists(out_path):
        return "exit 2 but %s was written" % out_path
    return ""


def make_case(program, exe, scene, context, option, value, cwd):
    """The command of one case, the path that must not exist after an error, and
    the files to check after a normal run."""
    if program == "vibrotherm":
        out = os.path.join(cwd, (value or "none") if option == "-output_dir" else "out")
        cmd = [exe] + scene + context.get(option, []) + ([] if option == "-output_dir" else ["-output_dir", out])
        files = [os.path.join(out, f) for f in ("summary.json", "energy.csv", "probes.csv")]
    else:
        out = os.path.join(cwd, (value or "none") if option == "-o" else "cell.csv")
        cmd = [exe] + scene + context.get(option, []) + ([] if option == "-o" else ["-o", out])
        files = [out]
    return cmd + [option, value], out, files


def run_case(case, env, timeout):
    """'' when the case passes, else why not; and the seconds it took."""
    program, option, value, cmd, cwd, out, files, allowed = case
    t = time.time()
    try:
        r = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
        code, stderr = r.returncode, r.stderr
    except subprocess.TimeoutExpired:
        code, stderr = None, ""
    elapsed = time.time() - t
    why = verdict(option, value, code, stderr, out, allowed, files, elapsed)
    stray = [f for f in os.listdir(cwd) if os.path.join(cwd, f) != out]
    if not why and stray:  # nothing outside the output directory either
        why = "wrote %s" % ", ".join(stray)
    return why, elapsed


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("vibrotherm")
    p.add_argument("contact")
    p.add_argument("--full", action="store_true", help="every value on every option")
    p.add_argument("--only", default="", help="options matching this regular expression only")
    p.add_argument("--values", default=None, help="comma-separated values instead of the defaults")
    p.add_argument("--timeout", type=float, default=20.0)
    p.add_argument("--jobs", type=int, default=1, help="cases run at once")
    args = p.parse_args()
    env = dict(os.environ)
    # A singleton MPI process without an mpirun daemon: starts ~0.25 s faster.
    env.setdefault("OMPI_MCA_ess_singleton_isolated", "1")
    vibrotherm, contact = os.path.abspath(args.vibrotherm), os.path.abspath(args.contact)
    programs = [("vibrotherm", vibrotherm, declared_options(vibrotherm, "vibrotherm:"), SCENE, CONTEXT, ALLOWED),
                ("vibrotherm-contact", contact, declared_options(contact, None), CONTACT_SCENE, CONTACT_CONTEXT,
                 CONTACT_ALLOWED)]
    start = time.time()
    stale = []  # allow-list entries of options -help no longer lists: a rename must not leave them behind
    if not args.only:
        stale = [(program[0], o) for program in programs for o in program[5] if o not in program[2]]
        for program, o in stale:
            print("FAIL %s: %s is in the allow-list but -help does not list it" % (program, o))
    with tempfile.TemporaryDirectory() as tmp:
        cases = []
        for program, exe, options, scene, context, allowed in programs:
            options = [o for o in options if re.search(args.only, o)]
            for i, option in enumerate(options):
                if args.values is not None:
                    values = args.values.split(",")
                elif args.full:
                    values = VALUES
                else:
                    values = CORE + [EXTRA[i % len(EXTRA)]]
                for value in values:
                    cwd = os.path.join(tmp, "case%d" % len(cases))
                    os.makedirs(cwd)
                    cmd, out, files = make_case(program, exe, scene, context, option, value, cwd)
                    cases.append((program, option, value, cmd, cwd, out, files, allowed))
        failed, slowest = len(stale), (0.0, "")
        with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
            for case, (why, elapsed) in zip(cases, pool.map(lambda c: run_case(c, env, args.timeout), cases)):
                program, option, value = case[:3]
                slowest = max(slowest, (elapsed, "%s %s %r" % (program, option, value)))
                if why:
                    failed += 1
                    print("FAIL %s %s %r: %s" % (program, option, value, why), flush=True)
    print("generated bad input: %d options, %d cases, %d failed, %.0f s (slowest %.1f s: %s)"
          % (len({c[:2] for c in cases}), len(cases), failed, time.time() - start, slowest[0], slowest[1]))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
