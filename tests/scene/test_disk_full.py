#!/usr/bin/python3
"""Requirement (issue 43, item 7): a full disk is a clear failure, not a riddle.

A run (serial and on 2 ranks) writes into a 400 kB file system (a tmpfs mounted for the
test) that fills while it writes its fields: it exits non-zero with one line "vibrotherm:
error: ..." naming the file it was writing and saying "no space left on device" (before:
"Error in HDF5 call H5Dcreate2() Status -1 (VecView_MPI_HDF5, ...)", neither file nor
reason), leaves no lock, and no file under its final name that is incomplete (every final
HDF5 file opens, every XDMF file parses; no summary.json saying complete). Open MPI's own
line about the failed write ("mca_fbtl_posix_pwritev: ... No space left on device") may
come before it.

Mounting needs root (or CAP_SYS_ADMIN); elsewhere the test is skipped (exit 77, CTest's
SKIP_RETURN_CODE). RLIMIT_FSIZE, the unprivileged alternative, also breaks Open MPI's
start-up (its PMIx shared memory), so it cannot stand in.

usage: test_disk_full.py VIBROTHERM SOURCE_DIR MPIEXEC"""
import json, os, subprocess, sys, tempfile
import xml.etree.ElementTree as ElementTree

import h5py

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks

exe, src, mpiexec = sys.argv[1:4]
check = Checks("disk_full")
SCENE = ["-options_file", os.path.join(src, "options/paper.opts"), "-mesh_h", "0.004", "-mesh_h_crack", "0.001",
         "-final_time", "2e-4", "-output_times", "1e-4,2e-4"]


def whole_files_only(label, out):
    """Nothing under a final name is a half-written file."""
    for name in sorted(os.listdir(out)):
        path = os.path.join(out, name)
        if name.endswith(".h5"):
            try:
                with h5py.File(path, "r") as f:
                    f.visit(lambda n: None)
                ok = True
            except OSError:
                ok = False
            check(ok, "%s: %s is under its final name but does not open" % (label, name))
        elif name.endswith(".xmf"):
            try:
                ElementTree.parse(path)
                ok = True
            except ElementTree.ParseError:
                ok = False
            check(ok, "%s: %s is under its final name but does not parse" % (label, name))
        elif name == "summary.json":
            check(json.load(open(path)).get("complete") is not True, "%s: summary.json says complete" % label)


with tempfile.TemporaryDirectory() as tmp:
    small = os.path.join(tmp, "small")
    os.makedirs(small)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=400k", "tmpfs", small], capture_output=True).returncode:
        print("disk_full: skipped: cannot mount a small file system here (needs root or CAP_SYS_ADMIN)")
        sys.exit(77)
    try:
        for ranks in (1, 2):
            label = "full disk, %d rank%s" % (ranks, "s" if ranks > 1 else "")
            out = os.path.join(small, "run%d" % ranks)
            cmd = ([mpiexec, "-n", "2", "--oversubscribe"] if ranks > 1 else []) + [exe] + SCENE + ["-output_dir", out]
            r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
            errors = [l for l in r.stderr.splitlines() if l.startswith("vibrotherm: error:")]
            check(r.returncode != 0, "%s: exit non-zero (%d)" % (label, r.returncode))
            check(len(errors) == 1 and "no space left on device" in errors[0].lower() and out + "/" in errors[0],
                  "%s: one line naming the file and 'no space left on device' (%s)" % (label, r.stderr[-600:]))
            check(not os.path.exists(os.path.join(out, "vibrotherm.lock")), "%s: no lock left" % label)
            if os.path.isdir(out):
                whole_files_only(label, out)
                subprocess.run(["rm", "-rf", out])  # room for the next run
    finally:
        subprocess.run(["umount", small])
check.finish()
