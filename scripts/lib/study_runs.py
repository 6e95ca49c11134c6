"""Runs of one scene for a study: each run in its own directory, its overrides recorded,
a finished run reused when asked again with the same overrides (an interrupted study
resumes), several at once on the machine's cores.

    runner = Runner(options_file, output_dir, ranks=1, jobs=2)
    runs = runner.map([("f12454_a1e-08", {"source_frequency": 12454, "source_amplitude": 1e-8}), ...])
    run.summary  # summary.json as a dict;  run.dir, run.overrides

A failed run raises RunFailed with vibrotherm's own error line.
"""
import contextlib
import heapq
import itertools
import json
import os
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import package  # noqa: F401  (scripts/vibrotherm on the path)
import vibrotherm as vt


class RunFailed(RuntimeError):
    """A run that did not end complete: its directory and the line that says why."""


def read_options(path):
    """-name value pairs of an options file (and the files it includes), the last one winning."""
    values = {}
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if not line.startswith("-"):
                continue
            parts = line.split(None, 1)
            name, value = parts[0][1:], parts[1].strip() if len(parts) > 1 else ""
            if name == "options_file":
                include = value
                for base in (os.path.dirname(path), os.getcwd()):
                    if os.path.exists(os.path.join(base, include)):
                        values.update(read_options(os.path.join(base, include)))
                        break
                continue
            values[name] = value
    return values


class Run:
    def __init__(self, name, directory, overrides, summary):
        self.name, self.dir, self.overrides, self.summary = name, directory, overrides, summary

    def __repr__(self):
        return "Run(%s)" % self.name


class Slots:
    """At most `jobs` holders at once; waiters are let in by priority (lowest first), then in the
    order they came: a study puts the runs of its slowest searches first (the longest jobs first)."""

    def __init__(self, jobs):
        self._free, self._waiting, self._count = jobs, [], itertools.count()
        self._cond = threading.Condition()

    @contextlib.contextmanager
    def held(self, priority=0.0):
        with self._cond:
            ticket = (priority, next(self._count))
            heapq.heappush(self._waiting, ticket)
            self._cond.wait_for(lambda: self._free > 0 and self._waiting[0] == ticket)
            heapq.heappop(self._waiting)
            self._free -= 1
            self._cond.notify_all()
        try:
            yield
        finally:
            with self._cond:
                self._free += 1
                self._cond.notify_all()


class Runner:
    def __init__(self, options_file, output_dir, ranks=1, jobs=1, log=print, executable=None):
        self.options_file = os.path.abspath(options_file)
        self.output_dir = output_dir
        self.ranks, self.jobs, self.log = ranks, jobs, log
        self.executable = executable
        self.scene = read_options(self.options_file)  # a run is reused only for the same scene and overrides
        self.seconds = 0.0  # wall time of the runs made (not reused)
        self.made = 0
        self._lock = threading.Lock()
        self._slots = Slots(jobs)  # at most `jobs` runs at once, however they are asked for
        self._wanted = 0  # runs running or waiting for a slot

    def portable(self, overrides):
        """The overrides as recorded: paths into the study's directory relative to it ($STUDY/...), so that
        a study moved elsewhere still finds its runs."""
        prefix = os.path.abspath(self.output_dir) + os.sep
        return {k: "$STUDY/" + v[len(prefix):] if isinstance(v, str) and v.startswith(prefix) else v
                for k, v in dict(overrides).items()}

    def finished(self, name, overrides):
        """The run of that name already finished with the same scene and overrides, or None."""
        directory = os.path.join(self.output_dir, name)
        record, scene = os.path.join(directory, "overrides.json"), os.path.join(directory, "scene.json")
        summary_path = os.path.join(directory, "summary.json")
        if all(os.path.exists(p) for p in (record, scene, summary_path)):
            with open(record) as f, open(scene) as g, open(summary_path, errors="replace") as h:
                old, old_scene, summary = json.load(f), json.load(g), json.load(h)
            if old == self.portable(overrides) and old_scene == self.scene and summary.get("complete"):
                return Run(name, directory, overrides, summary)
        return None

    def run(self, name, overrides, priority=0.0):
        """One run (or the finished one already there with the same overrides); waiting for a slot, runs of
        lower priority go first."""
        done = self.finished(name, overrides)
        if done:
            return done
        directory = os.path.join(self.output_dir, name)
        record, scene = os.path.join(directory, "overrides.json"), os.path.join(directory, "scene.json")
        with self._lock:
            self._wanted += 1
        try:
            with self._slots.held(priority):
                began = time.time()
                try:
                    summary = vt.run_scene(self.options_file, overrides, directory, ranks=self.ranks, overwrite=True,
                                           program=self.executable).summary
                except vt.RunFailed as failed:
                    raise RunFailed("%s (exit %d): %s" % (directory, failed.returncode, failed.error)) from None
                seconds = time.time() - began
        finally:
            with self._lock:
                self._wanted -= 1
        with self._lock:
            self.seconds += seconds
            self.made += 1
        with open(record, "w") as f:
            json.dump(self.portable(overrides), f, indent=1)
        with open(scene, "w") as f:
            json.dump(self.scene, f, indent=1)
        self.log("  %s: %.0f s" % (name, seconds))
        return Run(name, directory, overrides, summary)

    def idle_slots(self):
        """Run slots nobody runs in or waits for now (a study may fill them with a second guess)."""
        with self._lock:
            return max(0, self.jobs - self._wanted)

    def map(self, named_overrides, priority=0.0):
        """Runs (name, overrides) pairs, `jobs` at a time; the runs in the same order."""
        with ThreadPoolExecutor(max_workers=self.jobs) as pool:
            return list(pool.map(lambda pair: self.run(*pair, priority=priority), named_overrides))
