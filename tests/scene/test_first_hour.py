#!/usr/bin/python3
"""Requirement: a user's first hour holds no surprises. -help and --help list every
module's options (heat, mesh, heat mesh, modes, choices with their values, list options
with real defaults) and exit 0 without touching the disk; -version prints the version
and exits 0; a misspelt option is one line naming it with the nearest known name, exit 2
(-allow_unknown lets it through with a warning); a non-numeric value is one line naming
the option, exit 2; -output_times after the end is a warning; a run into a directory
holding an earlier run's outputs removes them first.
Issue 27: the default wave elements are Q2 (-help shows <2>); -help lists the PETSc
solvers' main options (-wave_ts_type, -petscpartitioner_type); a misspelt option is
refused before meshing; a misspelt PETSc solver option (-wave_ts_rk_typ) and a bad value
of one PETSc reads (-heat_free_ts_adapt_type) are refused before any step, one line,
exit 2, nothing written; the README's -mesh_file example with paper.opts runs, with a
note naming the options the file makes irrelevant; meshing is announced before it starts.

usage: test_first_hour.py VIBROTHERM SOURCE_DIR"""
import os, subprocess, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks

exe, src = sys.argv[1:3]
check = Checks("first hour")
paper = ["-options_file", os.path.join(src, "options", "paper.opts")]
small = ["-mesh_h", "0.004", "-mesh_h_crack", "0.001"]


def run(args, cwd):
    return subprocess.run([exe] + args, cwd=cwd, capture_output=True, text=True)


with tempfile.TemporaryDirectory() as tmp:
    for flag in ("-help", "--help"):
        empty = os.path.join(tmp, "empty" + flag)
        os.makedirs(empty)
        r = run([flag], empty)
        check(r.returncode == 0, "%s: exit %d" % (flag, r.returncode))
        check(os.listdir(empty) == [], "%s wrote %s" % (flag, os.listdir(empty)))
        for option in ("-heat_degree", "-heat_mesh_h_crack", "-modes_n", "-crack_law", "-edge_top", "-physics",
                       "-heat_substeps", "-max_steps", "-allow_unknown", "-wave_ts_type", "-petscpartitioner_type",
                       "-heat_free_ts_adapt_type", "-overwrite", "-debug"):
            check(option in r.stdout, "%s does not list %s" % (flag, option))
        check("-crack_center <now none" in r.stdout or "-crack_center <none" in r.stdout,
              "-crack_center's default is not 'none'")
        check("(all|wave|heat)" in r.stdout, "-physics does not list its values")
        check("-wave_degree <2" in r.stdout or "-wave_degree <now 2 " in r.stdout, "the default wave degree is not 2 (Q2)")
    r = run(["-version"], tmp)
    check(r.returncode == 0 and "vibrotherm 0." in r.stdout, "-version: exit %d, %r" % (r.returncode, r.stdout[-200:]))

    out = os.path.join(tmp, "typo")
    r = run(paper + small + ["-crak_angle", "45", "-mesh_only", "-output_dir", out], tmp)
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    check(r.returncode == 2 and len(lines) == 1 and "-crak_angle" in lines[0] and "did you mean -crack_angle" in lines[0],
          "misspelt option: exit %d, stderr %r" % (r.returncode, r.stderr[-300:]))
    check(not os.path.exists(out), "misspelt option left %s" % out)
    check("Mesh (" not in r.stdout, "misspelt option: refused only after meshing")

    # PETSc's options: checked against what its solvers read, before any step.
    for extra, words in [(["-wave_ts_type", "rk", "-wave_ts_rk_typ", "4"], ["-wave_ts_rk_typ", "did you mean -wave_ts_rk_type"]),
                         (["-heat_free_ts_adapt_type", "foo"], ["-heat_free_ts_adapt_type", "unknown value 'foo'"])]:
        r = run(paper + small + extra + ["-final_time", "2e-5", "-output_dir", out], tmp)
        lines = [l for l in r.stderr.splitlines() if l.strip()]
        check(r.returncode == 2 and len(lines) == 1 and all(w in lines[0] for w in words),
              "%s: exit %d, stderr %r" % (" ".join(extra), r.returncode, r.stderr[-300:]))
        check(not os.path.exists(out), "%s: wrote %s" % (" ".join(extra), out))

    # Options for a solver this scene does not have (no heat): noted as ignored, the run goes on.
    r = run(paper + small + ["-heat", "off", "-heat_free_ts_adapt_type", "basic", "-final_time", "2e-6",
                             "-output_dir", os.path.join(tmp, "no_heat")], tmp)
    check(r.returncode == 0 and "-heat_free_ts_adapt_type" in r.stdout and "ignored" in r.stdout,
          "a heat option without heat: exit %d, %r" % (r.returncode, (r.stdout + r.stderr)[-300:]))

    # The README's mesh-file example, with paper.opts (written for a generated specimen).
    r = run(paper + ["-mesh_file", os.path.join(src, "meshes", "plate_two_cracks.msh"), "-final_time", "1e-6",
                     "-output_dir", os.path.join(tmp, "mesh_file")], tmp)
    check(r.returncode == 0, "-mesh_file with paper.opts: exit %d, %r" % (r.returncode, r.stderr[-300:]))
    check("-crack_angle" in r.stdout and "ignored" in r.stdout, "-mesh_file: no note on the options it ignores")
    r = run(paper + small + ["-crak_angle", "45", "-allow_unknown", "-mesh_only", "-output_dir", out], tmp)
    check(r.returncode == 0 and "warning" in r.stdout + r.stderr, "-allow_unknown: exit %d" % r.returncode)

    r = run(paper + small + ["-source_frequency", "abc", "-output_dir", out + "2"], tmp)
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    check(r.returncode == 2 and len(lines) == 1 and "-source_frequency: expected a number, got 'abc'" in lines[0],
          "non-numeric value: exit %d, stderr %r" % (r.returncode, r.stderr[-300:]))

    stale = os.path.join(tmp, "stale")
    os.makedirs(stale)
    for name in ("fields.h5", "fields.xmf", "probes.csv", "crack_state.csv", "probes.csv.partial"):
        open(os.path.join(stale, name), "w").write("from an earlier run\n")
    open(os.path.join(stale, "notes.txt"), "w").write("the user's own file\n")
    # Issue 43: an earlier run's outputs are never removed without -overwrite.
    r = run(paper + small + ["-mesh_only", "-output_dir", stale], tmp)
    check(r.returncode == 2 and "-overwrite" in r.stderr and len(os.listdir(stale)) == 6,
          "run into an old directory without -overwrite: refused, nothing removed (%s)" % r.stderr[-300:])
    r = run(paper + small + ["-mesh_only", "-overwrite", "-output_dir", stale], tmp)
    check(r.returncode == 0, "run into an old directory: %s" % r.stderr[-500:])
    left = sorted(os.listdir(stale))
    check(left == ["mesh.h5", "mesh.xmf", "notes.txt", "summary.json", "vibrotherm.log"],
          "left in the old directory: %s" % left)

    r = run(paper + small + ["-final_time", "2e-6", "-output_times", "1e-6,5e-3", "-output_dir",
                             os.path.join(tmp, "late")], tmp)
    check(r.returncode == 0 and "-output_times 0.005 s is after the end of the run" in r.stdout,
          "late output time: exit %d, %r" % (r.returncode, r.stdout[-400:]))
    # Meshing says what it does before it starts (large scenes take minutes).
    before = r.stdout.split("Mesh (generated)")[0]
    check("Meshing with gmsh" in before and "wave cells" in before, "no word before meshing: %r" % before[-300:])
check.finish()
