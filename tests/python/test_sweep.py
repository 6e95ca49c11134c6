#!/usr/bin/python3
"""Requirement (issue 43 item 9): scripts/sweep keeps what finished, tells honest ETAs, and
takes values holding commas.
  * --vary "crack_center=0.024,0.05;0.026,0.05" is two cases, each run given its whole point
    (summary.json's -crack_center), sweep.csv's crack_center column holding it;
  * a sweep stopped by SIGTERM while its second case runs exits 143 with sweep.csv holding
    the finished case, the running case checkpointed (resumable) and not left running;
    --resume with the same arguments reuses the finished case, continues the stopped one
    (-restart: its summary says restarted_from) and runs the rest: three ok rows;
  * the ETA after a case that became periodic (continued) is a range that says so, whose
    upper end is at least half what a case that never becomes periodic then takes (a single
    figure from the continued case's time is what the sweep gave before);
  * an option varied twice or an empty value: one line, exit 2.

usage: test_sweep.py VIBROTHERM SOURCE_DIR"""
import csv
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import time

exe, src = sys.argv[1:3]
sys.path.insert(0, os.path.join(src, "tests", "scene"))
from checks import Checks  # noqa: E402

check = Checks("sweep")
sweep = os.path.join(src, "scripts", "sweep")
env = dict(os.environ, VIBROTHERM_BUILD_DIR=os.path.dirname(os.path.abspath(exe)))
coarse = ["--set", "mesh_h=0.004", "--set", "mesh_h_crack=0.001", "--set", "wave_degree=1"]


def table(out):
    path = os.path.join(out, "sweep.csv")
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def seconds(text):
    number, unit = text.split()
    return float(number) * {"s": 1, "min": 60, "h": 3600}[unit]


with tempfile.TemporaryDirectory() as tmp:
    # --- values holding commas ----------------------------------------------------------------------
    points = os.path.join(tmp, "points")
    r = subprocess.run(["/usr/bin/python3", sweep, "--no-build", "--output", points] + coarse +
                       ["--set", "final_time=1e-5", "--vary", "crack_center=0.024,0.05;0.026,0.05"],
                       capture_output=True, text=True, env=env)
    rows = table(points)
    check(r.returncode == 0 and [row["crack_center"] for row in rows] == ["0.024,0.05", "0.026,0.05"],
          "--vary with ';': exit %d, rows %s, %s" % (r.returncode, [row.get("crack_center") for row in rows],
                                                     r.stderr[-500:]))
    for k, expected in enumerate([(0.024, 0.05), (0.026, 0.05)]):
        case = os.path.join(points, "case_%d" % k)
        if os.path.exists(os.path.join(case, "summary.json")):
            given = summary(case)["option_values"]["-crack_center"]["value"]
            check(tuple(float(v) for v in given.split(",")) == expected, "case_%d ran with -crack_center %s, not %s"
                  % (k, given, expected))
        else:
            check.fail("case_%d wrote no summary.json" % k)
    for bad, words in ((["--vary", "source_amplitude=1e-7", "--vary", "source_amplitude=2e-7"], "twice"),
                       (["--vary", "source_amplitude=1e-7,,2e-7"], "empty")):
        r = subprocess.run(["/usr/bin/python3", sweep, "--no-build", "--output", os.path.join(tmp, "bad")] + bad,
                           capture_output=True, text=True, env=env)
        lines = [line for line in r.stderr.splitlines() if line.strip()]
        check(r.returncode == 2 and len(lines) == 1 and words in lines[0] and "--vary" in lines[0],
              "%s: exit %d, %r" % (" ".join(bad), r.returncode, r.stderr[-300:]))

    # --- stopped half way, then resumed ----------------------------------------------------------------
    stopped = os.path.join(tmp, "stopped")
    args = ["/usr/bin/python3", sweep, "--no-build", "--output", stopped] + coarse + [
        "--set", "checkpoint_every_s=0", "--set", "crack_state_every=0", "--case=-final_time 1e-5",
        "--case=-final_time 5e-3 -source_duration 5e-3", "--case=-final_time 2e-5"]
    # (case 1's source on for all its 5 ms: with the scene's 1 ms its waves went quiet and the case
    # could end within the 1 s wait below, before the SIGTERM.)
    p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    running = os.path.join(stopped, "case_1", "energy.csv.partial")
    deadline = time.time() + 300
    while not os.path.exists(running) and time.time() < deadline and p.poll() is None:
        time.sleep(0.05)
    time.sleep(1.0)
    p.send_signal(signal.SIGTERM)
    out, err = p.communicate(timeout=300)
    rows = table(stopped)
    check(p.returncode == 128 + signal.SIGTERM, "a sweep stopped by SIGTERM: exit %s (%s)" % (p.returncode, err[-400:]))
    check([row["case"] for row in rows] == ["0"] and rows[0]["status"] == "ok",
          "sweep.csv of a stopped sweep: %s" % [(row["case"], row["status"]) for row in rows])
    case_1 = os.path.join(stopped, "case_1")
    check(os.path.exists(os.path.join(case_1, "checkpoint.h5")) and not os.path.exists(os.path.join(case_1,
                                                                                                 "vibrotherm.lock")),
          "the running case checkpointed and stopped: %s" % sorted(os.listdir(case_1)))
    check("case_1" in err and "--resume" in err, "the stopped sweep says what to do: %r" % err[-400:])
    r = subprocess.run(args + ["--resume"], capture_output=True, text=True, env=env)
    rows = table(stopped)
    check(r.returncode == 0 and [row["status"] for row in rows] == ["ok"] * 3,
          "--resume: exit %d, %s, %s" % (r.returncode, [row["status"] for row in rows], r.stderr[-500:]))
    check("reused" in r.stdout and summary(case_1).get("restarted_from"),
          "--resume reuses case_0 and continues case_1: %r" % r.stdout[-600:])

    # --- an honest ETA ------------------------------------------------------------------------------------
    periodic = os.path.join(tmp, "periodic")
    r = subprocess.run(["/usr/bin/python3", sweep, "--no-build", "--output", periodic] + coarse + [
        "--set", "crack_a0=2e-8", "--set", "source_amplitude=1.6e-8", "--set", "crack_state_every=0",
        "--set", "source_duration=4e-3", "--set", "final_time=4e-3", "--case=-periodic_tol 3e-4",
        "--case=-periodic_tol 1e-12"], capture_output=True, text=True, env=env)
    lines = [line for line in r.stdout.splitlines() if line.startswith("case ")]
    check(r.returncode == 0 and len(lines) == 2, "periodic sweep: exit %d, %r" % (r.returncode, r.stdout[-600:]))
    if len(lines) == 2:
        eta = re.search(r"ETA (\S+ \S+) to (\S+ \S+) \((.*)\)", lines[0])
        took = re.search(r": ok in (\S+) s", lines[1])
        check(eta is not None and "became periodic" in eta.group(3),
              "the ETA after a continued case is a range saying why: %r" % lines[0])
        if eta and took:
            check(seconds(eta.group(2)) >= 0.5 * float(took.group(1)),
                  "the ETA's upper end %s against the never periodic case's %s s" % (eta.group(2), took.group(1)))
        s = [summary(os.path.join(periodic, "case_%d" % k)) for k in (0, 1)]
        check(s[0]["derived"]["periodic_periods_continued"] > 0 == s[1]["derived"]["periodic_periods_continued"],
              "case 0 continued, case 1 never periodic: %s" % [x["derived"]["periodic_periods_continued"] for x in s])
check.finish()
