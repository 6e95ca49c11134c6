#!/usr/bin/python3
"""Requirement (issue 25, item 7): refactorings do not change the paper scene's results.
A short run of the paper scene (0.1 ms, Q2, MMD, heat, field outputs) is reduced to a
stored reference in tests/data/reference_paper/ (energy.csv whole; every 10th probe
row; crack_state.csv at its last time; the result keys of summary.json; the field
outputs' datasets at the last time as per-dataset sums and extrema). A run of today's
binary is reduced the same way and compared with scripts/compare_outputs: every number
within 1e-9 of its column's scale (on the machine the reference was made on the files
are byte-identical, which the test reports; another CPU may round BLAS differently).

usage: test_reference_outputs.py VIBROTHERM REPO [--store]
(--store rewrites the reference: only for a change that is meant to change results,
said in the commit.)"""
import json
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import Checks, outputs

SCENE = ["-options_file", "options/paper.opts", "-final_time", "1e-4", "-source_duration", "1e-4",
         "-output_times", "5e-5,1e-4"]
RESULT_KEYS = ["dofs_wave", "dofs_heat", "contact_cells", "steps_wave", "steps_heat", "max_budget_error",
               "dissipated_energy", "heat_deposited", "heat_content", "probe_max_temperature_rise",
               "field_max_temperature_rise", "field_max_temperature_rise_at", "mesh"]


def reduce_run(run, out):
    """The reference's files from a run directory."""
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(run, "energy.csv")) as f, open(os.path.join(out, "energy.csv"), "w") as g:
        g.write(f.read())
    with open(os.path.join(run, "probes.csv")) as f, open(os.path.join(out, "probes.csv"), "w") as g:
        lines = f.read().splitlines(True)
        g.writelines(lines[:1] + lines[1::10])
    with open(os.path.join(run, "crack_state.csv")) as f, open(os.path.join(out, "crack_state.csv"), "w") as g:
        lines = f.read().splitlines(True)
        last = lines[-1].split(",")[0]
        g.writelines(lines[:1] + [l for l in lines[1:] if l.split(",")[0] == last])
    summary = outputs(run).summary
    json.dump({k: summary[k] for k in RESULT_KEYS}, open(os.path.join(out, "summary.json"), "w"), indent=1)
    with outputs(run).h5("fields.h5") as f, open(os.path.join(out, "fields.csv"), "w") as g:
        g.write("dataset,index,sum,min,max\n")
        names = []
        f.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        for i, n in enumerate(sorted(names)):
            x = np.asarray(f[n][()], float)
            g.write("%s,%d,%.17g,%.17g,%.17g\n" % (n.replace(",", ";"), i, x.sum(), x.min(), x.max()))


def main(argv):
    exe, repo = argv[1], argv[2]
    reference = os.path.join(repo, "tests/data/reference_paper")
    check = Checks("reference outputs")
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run")
        r = subprocess.run([exe] + SCENE + ["-output_dir", run], capture_output=True, text=True, cwd=repo)
        check(r.returncode == 0, "paper scene: %s" % r.stderr[-1500:])
        if r.returncode:
            check.finish()
        if "--store" in argv:
            reduce_run(run, reference)
            print("stored", reference)
            return 0
        reduced = os.path.join(tmp, "reduced")
        reduce_run(run, reduced)
        compare = os.path.join(repo, "scripts/compare_outputs")
        exact = subprocess.run([compare, reference, reduced], capture_output=True, text=True)
        print("byte-identical to the reference:", "yes" if exact.returncode == 0 else "no\n" + exact.stdout[-2000:])
        close = subprocess.run([compare, reference, reduced, "--rtol", "1e-9"], capture_output=True, text=True)
        print(close.stdout[-3000:])
        check(close.returncode == 0, "results differ from tests/data/reference_paper beyond 1e-9 (above)")
    check.finish()


if __name__ == "__main__":
    sys.exit(main(sys.argv))
