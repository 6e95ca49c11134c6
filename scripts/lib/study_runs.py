"""Runs of one scene for a study: each run in its own directory, its overrides recorded,
a finished run reused when asked again with the same overrides (an interrupted study
resumes), several at once on the machine's cores.

    runner = Runner(options_file, output_dir, ranks=1, jobs=2)
    runs = runner.map([("f12454_a1e-08", {"source_frequency": 12454, "source_amplitude": 1e-8}), ...])
    run.summary  # summary.json as a dict;  run.dir, run.overrides

A failed run raises RunFailed with vibrotherm's own error line.
"""
import json
import os
import subprocess
import threading
import time
from concurrent.futures import ThreadPoolExecutor

from project import BUILD_DIR, ROOT, mpi_env


class RunFailed(RuntimeError):
    """A run that did not end complete: its directory and the line that says why."""


def error_line(path):
    """The line of a run's stderr that says what went wrong: vibrotherm's own, else PETSc's, else the first."""
    try:
        with open(path, errors="replace") as f:
            lines = [line.strip() for line in f if line.strip()]
    except OSError:
        return ""
    for line in lines:
        if line.startswith("vibrotherm") and "error" in line:
            return line
    for line in lines:
        if "PETSC ERROR:" in line and "Error Message" not in line and line.split("PETSC ERROR:", 1)[1].strip(" -"):
            return line
    return lines[0] if lines else ""


class Run:
    def __init__(self, name, directory, overrides, summary):
        self.name, self.dir, self.overrides, self.summary = name, directory, overrides, summary

    def __repr__(self):
        return "Run(%s)" % self.name


def words(overrides):
    """{"source_frequency": 1e4, "camera": None} -> ["-source_frequency", "10000.0", "-camera"]."""
    result = []
    for name, value in overrides.items():
        result.append("-" + name)
        if value is not None:
            result.append(value if isinstance(value, str) else repr(value))
    return result


class Runner:
    def __init__(self, options_file, output_dir, ranks=1, jobs=1, log=print, executable=None):
        self.options_file = os.path.abspath(options_file)
        self.output_dir = output_dir
        self.ranks, self.jobs, self.log = ranks, jobs, log
        self.executable = executable or os.path.join(BUILD_DIR, "vibrotherm")
        self.env = mpi_env()
        self.seconds = 0.0  # wall time of the runs made (not reused)
        self.made = 0
        self._lock = threading.Lock()
        self._slots = threading.Semaphore(jobs)  # at most `jobs` runs at once, however they are asked for

    def command(self, overrides, directory, extra=()):
        return (["mpiexec", "-n", str(self.ranks), self.executable, "-options_file", self.options_file] +
                words(overrides) + list(extra) + ["-output_dir", directory, "-overwrite"])

    def run(self, name, overrides):
        """One run (or the finished one already there with the same overrides)."""
        directory = os.path.join(self.output_dir, name)
        record = os.path.join(directory, "overrides.json")
        summary_path = os.path.join(directory, "summary.json")
        if os.path.exists(record) and os.path.exists(summary_path):
            with open(record) as f, open(summary_path, errors="replace") as g:
                old, summary = json.load(f), json.load(g)
            if old == {k: v for k, v in overrides.items()} and summary.get("complete"):
                return Run(name, directory, overrides, summary)
        os.makedirs(directory, exist_ok=True)
        with self._slots:
            began = time.time()
            with open(os.path.join(directory, "stdout.txt"), "w") as out, \
                    open(os.path.join(directory, "stderr.txt"), "w") as err:
                code = subprocess.run(self.command(overrides, directory), cwd=ROOT, env=self.env, stdout=out,
                                      stderr=err).returncode
            seconds = time.time() - began
        with self._lock:
            self.seconds += seconds
            self.made += 1
        if code != 0 or not os.path.exists(summary_path):
            raise RunFailed("%s (exit %d): %s" % (directory, code, error_line(os.path.join(directory, "stderr.txt"))))
        with open(summary_path, errors="replace") as f:
            summary = json.load(f)
        with open(record, "w") as f:
            json.dump(overrides, f, indent=1)
        self.log("  %s: %.0f s" % (name, seconds))
        return Run(name, directory, overrides, summary)

    def map(self, named_overrides):
        """Runs (name, overrides) pairs, `jobs` at a time; the runs in the same order."""
        with ThreadPoolExecutor(max_workers=self.jobs) as pool:
            return list(pool.map(lambda pair: self.run(*pair), named_overrides))
