"""A sweep: one scene run over a list of option overrides, the cases side by side.

    table = sweep("options/paper.opts", [{"source_amplitude": a} for a in (5e-8, 1e-7)], "results/amp",
                  common={"final_time": 2e-4}, ranks=1, jobs=2)

Case k runs in OUTPUT/case_<k>/ (its stdout.txt, stderr.txt and case.json: the options it
was given); OUTPUT/sweep.csv gets one row per finished case, rewritten (atomically) as each
case ends, so a sweep stopped half way keeps the table of what finished. Ctrl-C (or SIGTERM
turned into KeyboardInterrupt by scripts/sweep) stops the running cases with SIGUSR1 (each
checkpoints: resume=True continues them with -restart) and raises SweepInterrupted.

The ETA is honest about what it knows: from the finished cases' wall times, as a range
when they differ or when a case was continued periodically (a case that never becomes
periodic costs what the fully resolved run costs: that case's time scaled up by the periods
it did not simulate), "unknown" before any case has finished."""
import csv
import itertools
import json
import os
import signal
import subprocess
import threading
import time
from concurrent.futures import FIRST_COMPLETED, ThreadPoolExecutor, wait

from . import launch, project
from .run_dir import Run

# Before "overrides", one column per option the sweep sets or varies; after it, the cells of
# summary.json (empty when a run did not write the key). Column names are a contract.
COLUMNS = ["case", "overrides", "status", "error", "wall_time_s", "physics_ran", "dofs_wave", "contact_cells",
           "steps_wave", "steps_heat", "dissipated_energy", "max_budget_error", "crack_centre_max_rise",
           "field_max_temperature_rise", "camera_peak_snr", "wave_end_time"]
SUMMARY_KEYS = ("wall_time_s", "dofs_wave", "contact_cells", "steps_wave", "steps_heat", "dissipated_energy",
                "max_budget_error", "field_max_temperature_rise", "camera_peak_snr")


class SweepInterrupted(KeyboardInterrupt):
    """The sweep was stopped: .finished (rows written to sweep.csv), .interrupted (cases stopped
    mid-run, resumable), .not_started."""

    def __init__(self, finished, interrupted, not_started):
        super().__init__("sweep stopped: %d case(s) finished, %d interrupted, %d not started"
                         % (len(finished), len(interrupted), len(not_started)))
        self.finished, self.interrupted, self.not_started = finished, interrupted, not_started


def grid(axes):
    """Every combination of the axes {option: [values]} as a list of override dicts (the last
    axis varies fastest)."""
    names = list(axes)
    return [dict(zip(names, values)) for values in itertools.product(*(axes[n] for n in names))]


def _cell(value):
    """An option's sweep.csv cell: its value as given to vibrotherm, "1" for a flag."""
    return "1" if value is True or value is None else launch.option_value(value)


def _words(options):
    return " ".join(launch.option_words(options))


def summary_row(k, options, status, out, stderr_text=""):
    """The sweep.csv row of case k (its overrides as a dict, its status, its directory)."""
    row = {"case": k, "overrides": _words(options), "status": status}
    if status != "ok":
        row["error"] = launch.error_line(stderr_text)
    path = os.path.join(out, "summary.json")
    if status == "ok" and os.path.exists(path):
        s = Run(out).summary
        for key in SUMMARY_KEYS:
            value = s.get(key, "")
            row[key] = json.dumps(value, separators=(",", ":")) if isinstance(value, (dict, list)) else value
        row["physics_ran"] = "+".join(s.get("physics_ran", []))
        centre = [int(i) for i, label in s.get("probe_labels", {}).items() if "xi = 0.5" in label]
        if centre:
            row["crack_centre_max_rise"] = s.get("probe_max_temperature_rise", {}).get(str(centre[0]), "")
        row["wave_end_time"] = s.get("physics_time", {}).get("wave", ["", ""])[1]
    return row


def resolved_cost(summary):
    """(wall seconds, the same case's estimated wall seconds had it never been continued): the
    wave stages scaled by the wave time it ran over the wave time it simulated, the heat steps
    grown by one per heat_dt of the time continued."""
    wall = float(summary.get("wall_time_s", 0.0))
    segments = summary.get("periodic", []) or []
    span = summary.get("physics_time", {}).get("wave", [0.0, 0.0])
    skipped = sum(max(0.0, s.get("resumed", 0.0) - s.get("suspended", 0.0)) for s in segments)
    simulated = (span[1] - span[0]) - skipped
    if skipped <= 0 or simulated <= 0:
        return wall, wall
    stages = summary.get("stages", {})
    waves = (stages.get("wave_steps", 0.0) + stages.get("contact", 0.0)) * ((span[1] - span[0]) / simulated - 1.0)
    # Resolved, the heat takes a step every heat_dt where the continuation took a few of a ladder.
    heat_dt, heat_steps = summary.get("derived", {}).get("heat_dt", 0.0), summary.get("steps_heat", 0)
    heat = stages.get("heat_steps", 0.0) * skipped / heat_dt / heat_steps if heat_dt > 0 and heat_steps > 0 else 0.0
    return wall, wall + waves + heat


def _duration(seconds):
    if seconds < 120:
        return "%.0f s" % seconds
    if seconds < 7200:
        return "%.0f min" % (seconds / 60)
    return "%.1f h" % (seconds / 3600)


def eta(costs, running_elapsed, waiting, jobs):
    """The ETA text of a sweep: costs = [(wall, resolved wall, case name)] of the finished ok
    cases, running_elapsed = seconds each running case has run, waiting = cases not started."""
    if not costs:
        return "ETA unknown (no case finished yet)" if running_elapsed or waiting else "ETA 0 s"
    low = min(c[0] for c in costs)
    high = max(max(c[0], c[1]) for c in costs)
    left_low = sum(max(0.0, low - e) for e in running_elapsed) + waiting * low
    left_high = sum(max(0.0, high - e) for e in running_elapsed) + waiting * high
    lanes = max(1, min(jobs, len(running_elapsed) + waiting))
    if left_high == 0:
        return "ETA 0 s"
    continued = [c for c in costs if c[1] > c[0] * 1.01]
    if not continued and high <= 1.5 * low:
        return "ETA %s" % _duration(left_high / lanes)
    why = ("%s became periodic; a case that does not costs up to %s" % (continued[0][2], _duration(continued[0][1]))
           if continued else "finished cases took %s to %s" % (_duration(low), _duration(high)))
    return "ETA %s to %s (%s)" % (_duration(left_low / lanes), _duration(left_high / lanes), why)


def write_table(path, rows, option_columns):
    """sweep.csv: a column per option, then COLUMNS; written as .partial and renamed."""
    with open(path + ".partial", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=["case"] + option_columns + COLUMNS[1:], restval="")
        writer.writeheader()
        writer.writerows(rows)
    os.replace(path + ".partial", path)


class _Sweep:
    """The state of a sweep under way: which cases run, which finished, the table so far."""

    def __init__(self, options_file, cases, output_dir, common, ranks, jobs, program, resume, overwrite, report):
        self.options_file, self.cases, self.output_dir = options_file, cases, os.path.abspath(output_dir)
        self.common, self.ranks, self.jobs, self.program = common, ranks, jobs, program
        self.resume, self.overwrite, self.report = resume, overwrite, report
        self.lock, self.stopping = threading.Lock(), threading.Event()
        self.live, self.started, self.rows, self.costs, self.interrupted = {}, {}, {}, [], []
        self.option_columns = []
        for options in [common] + cases:
            self.option_columns += [n.lstrip("-") for n in options if n.lstrip("-") not in self.option_columns]
        self.option_columns = [n for n in self.option_columns if n not in COLUMNS]
        self.table = os.path.join(self.output_dir, "sweep.csv")

    def case_dir(self, k):
        return os.path.join(self.output_dir, "case_%d" % k)

    def _command(self, k, out):
        options = dict(self.common, **self.cases[k])
        record = os.path.join(out, "case.json")
        if self.resume and os.path.exists(record):
            with open(record) as f:
                before = json.load(f)
            if before != launch.option_words(options):
                raise ValueError("case_%d: --resume with other options than its first run (%s, now %s)" % (
                    k, " ".join(before), _words(options)))
            if os.path.exists(os.path.join(out, "checkpoint.h5")):
                options["restart"] = out
        if self.overwrite and "restart" not in options:
            options["overwrite"] = True
        with open(record, "w") as f:
            json.dump(launch.option_words(dict(self.common, **self.cases[k])), f)
        return launch.command(self.options_file, options, out, self.ranks, self.program)

    def _finished_before(self, k, out):
        """A complete run of this case from an earlier, interrupted sweep (resume=True)."""
        try:
            with open(os.path.join(out, "case.json")) as f:
                same = json.load(f) == launch.option_words(dict(self.common, **self.cases[k]))
            return same and Run(out).complete and not os.path.exists(os.path.join(out, "checkpoint.h5"))
        except (OSError, ValueError):
            return False

    def run_case(self, k):
        if self.stopping.is_set():
            return
        out = self.case_dir(k)
        os.makedirs(out, exist_ok=True)
        began = time.time()
        if self.resume and self._finished_before(k, out):
            code, note = 0, " (finished before: reused)"
        else:
            note = ""
            with open(os.path.join(out, "stdout.txt"), "a" if self.resume else "w") as so, \
                    open(os.path.join(out, "stderr.txt"), "w") as se:
                with self.lock:
                    if self.stopping.is_set():
                        return
                    # Its own session: a Ctrl-C reaches the sweep only, which stops each case once.
                    process = subprocess.Popen(self._command(k, out), cwd=project.ROOT, env=project.mpi_env(),
                                               stdout=so, stderr=se, start_new_session=True)
                    self.live[k], self.started[k] = process, began
                code = process.wait()
            with self.lock:
                del self.live[k], self.started[k]
            if self.stopping.is_set() and code != 0:
                self.interrupted.append(k)
                return
        status = "ok" if code == 0 else "failed (exit %d)" % code
        with open(os.path.join(out, "stderr.txt"), errors="replace") as f:
            row = summary_row(k, self.cases[k], status, out, f.read())
        row.update({n.lstrip("-"): _cell(v) for n, v in dict(self.common, **self.cases[k]).items()})
        with self.lock:
            self.rows[k] = row
            now = time.time()
            if status == "ok" and not note:  # the time it took here (start-up included), scaled as resolved_cost
                wall, resolved = resolved_cost(Run(out).summary)
                self.costs.append((now - began, now - began + resolved - wall, "case_%d" % k))
            write_table(self.table, [self.rows[i] for i in sorted(self.rows)], self.option_columns)
            waiting = len(self.cases) - len(self.rows) - len(self.live)
            progress = eta(self.costs, [now - t for t in self.started.values()], waiting, self.jobs)
            self.report("case %d/%d (case_%d) [%s]: %s in %.1f s%s%s; %d/%d done, %s" % (
                k + 1, len(self.cases), k, _words(self.cases[k]) or "base", status, now - began, note,
                ": " + row["error"] if row.get("error") else "", len(self.rows), len(self.cases), progress))

    def stop(self):
        """Stops every running case with SIGUSR1 (checkpoint, exit 138) and starts no other."""
        with self.lock:
            self.stopping.set()
            for process in self.live.values():
                try:
                    process.send_signal(signal.SIGUSR1)  # mpiexec forwards SIGUSR1 to every rank
                except ProcessLookupError:
                    pass


def sweep(options_file, cases, output_dir, common=None, ranks=1, jobs=1, program=None, resume=False, overwrite=False,
          report=print):
    """Runs every case (a list of override dicts; [] or [{}]: the scene as it is) with `common`
    given to all, `jobs` at a time on `ranks` ranks each, and returns sweep.csv as a pandas
    DataFrame (attrs["runs"] = {case: its directory}). resume=True reuses the complete runs of
    an earlier sweep into the same directory (same options) and continues the interrupted ones
    with -restart; overwrite=True gives every case -overwrite (an earlier run in its directory is
    replaced). Progress lines go to `report`. A failed case is a row with its status and
    error line; the others go on."""
    import pandas as pd

    cases = [dict(c) for c in cases] or [{}]
    state = _Sweep(options_file, cases, output_dir, dict(common or {}), ranks, jobs,
                   program or project.executable(), resume, overwrite, report)
    os.makedirs(state.output_dir, exist_ok=True)
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        futures = [pool.submit(state.run_case, k) for k in range(len(cases))]
        try:
            pending = set(futures)
            while pending:  # short waits: the main thread stays interruptible
                done, pending = wait(pending, timeout=0.5, return_when=FIRST_COMPLETED)
                for future in done:
                    future.result()
        except KeyboardInterrupt:
            state.stop()
            wait(futures)
            finished = sorted(state.rows)
            write_table(state.table, [state.rows[i] for i in finished], state.option_columns)
            not_started = [k for k in range(len(cases)) if k not in state.rows and k not in state.interrupted]
            raise SweepInterrupted(finished, sorted(state.interrupted), not_started) from None
        except BaseException:
            state.stop()
            raise
    frame = pd.read_csv(state.table)
    frame.attrs["runs"] = {k: state.case_dir(k) for k in range(len(cases))}
    return frame
