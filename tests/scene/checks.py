"""Shared by the scene tests: count checks, report failures, print the closing line; run a scene."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "lib"))
import package  # noqa: E402,F401  (the vibrotherm package of this checkout)
import vibrotherm  # noqa: E402


def outputs(*directory):
    """A run's outputs (its directory, or the parts of its path), read through the vibrotherm
    package, the one library that reads them: .summary, .rows("probes.csv"), .h5("fields.h5"),
    .energy(), ..."""
    return vibrotherm.Run(os.path.join(*directory))


class Checks:
    def __init__(self, name):
        self.name, self.count, self.failures = name, 0, []

    def __call__(self, ok, what):
        self.count += 1
        if not ok:
            self.failures.append(what)
            print("FAILED:", what, file=sys.stderr)

    def fail(self, what):
        self(False, what)

    def finish(self):
        print("%s: %d passed, %d failed" % (self.name, self.count - len(self.failures), len(self.failures)))
        sys.exit(1 if self.failures else 0)


def program_runner(exe):
    """run(args): exe with args, its output captured (subprocess.CompletedProcess)."""
    return lambda args: subprocess.run([exe] + args, capture_output=True, text=True)


def one_line_error(check, label, code, err, *words):
    """A refused input: exit 2 and stderr one line `vibrotherm: error: ...` holding every word."""
    lines = [l for l in err.splitlines() if l.strip()]
    check(code == 2 and len(lines) == 1 and lines[0].startswith("vibrotherm: error:"),
          "%s: one line, exit 2 (exit %d: %s)" % (label, code, err[-400:]))
    for word in words:
        check(bool(lines) and word in lines[0], "%s: the line names %s: %s" % (label, word, lines))


def refused(check, exe, base, extra, out, *words):
    """Runs vibrotherm with base + extra into out: refused in one line holding every word
    (one_line_error), nothing written."""
    r = subprocess.run([exe] + base + extra + ["-output_dir", out], capture_output=True, text=True)
    one_line_error(check, " ".join(extra), r.returncode, r.stderr, *words)
    check(not os.path.exists(out), "%s: nothing written" % " ".join(extra))


def run_scene(check, exe, args, out, mpiexec=None, ranks=1):
    """Runs vibrotherm with args into out (through mpiexec on `ranks` ranks when > 1); a
    failed run is a failed check naming out. True when it ran."""
    cmd = ([mpiexec, "-n", str(ranks), "--oversubscribe"] if ranks > 1 else []) + [exe] + args + ["-output_dir", out]
    r = subprocess.run(cmd, capture_output=True, text=True)
    check(r.returncode == 0, "%s: %s" % (out, r.stderr[-1500:]))
    return r.returncode == 0
