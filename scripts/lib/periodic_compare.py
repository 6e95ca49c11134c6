"""A run with periodic continuation against a fully resolved run of the same scene
(-periodic_min_continued 1e9: the same quantized wave step, no continuation): the
figures issue 24 asks for. Used by tests/scene/test_periodic_continuation.py,
scripts/convergence --study periodic and scripts/bench periodic."""
import os
import signal
import subprocess
import time

import numpy as np

import package  # noqa: F401  (scripts/vibrotherm of this checkout)
import vibrotherm as vt


def summary(out):
    return vt.load(out).summary


def relative(a, b):
    return a / b - 1.0 if b != 0 else (0.0 if a == 0 else float("inf"))


def probe_rows(out, probe):
    p = vt.load(out).probes(probe)
    p = p[p["temperature"].notna()]
    return p["t"].to_numpy(), p["temperature"].to_numpy()


def at_period_ends(out, ref, probe, period, t0, t1):
    """The probe's rise at every period end in [t0, t1] where both runs have a row:
    (times, rise of out, rise of ref)."""
    T0 = summary(ref)["derived"].get("heat_T0", 293.15)
    ta, Ta = probe_rows(out, probe)
    tb, Tb = probe_rows(ref, probe)
    times, a, b = [], [], []
    for t, temperature in zip(ta, Ta):
        k = t / period
        if t < t0 or t > t1 or abs(k - round(k)) > 1e-6:
            continue
        j = np.searchsorted(tb, t)
        for i in (j - 1, j):
            if 0 <= i < len(tb) and abs(tb[i] - t) < 1e-6 * period:
                times.append(t), a.append(temperature - T0), b.append(Tb[i] - T0)
                break
    return np.array(times), np.array(a), np.array(b)


def compare(out, ref, crack_probe, period, t0=0.0, t1=np.inf):
    """Errors of `out` against `ref`: dissipated energy, heat content, crack probe rise at period ends
    (largest over [t0, t1], against the largest rise of the reference), camera peak pixel, wall ratio."""
    s, r = summary(out), summary(ref)
    times, a, b = at_period_ends(out, ref, crack_probe, period, t0, t1)
    result = {
        "dissipated": relative(s["dissipated_energy"], r["dissipated_energy"]),
        "heat_content": relative(s["heat_content"], r["heat_content"]),
        "crack_probe_period_ends": len(times),
        "crack_probe": float(np.max(np.abs(a - b)) / np.max(np.abs(b))) if len(times) else float("nan"),
        "wall_ratio": r["wall_time_s"] / s["wall_time_s"],
        "wall": s["wall_time_s"],
        "wall_reference": r["wall_time_s"],
        "continued": s["derived"].get("periodic_periods_continued", 0),
        "reached_at": s["derived"].get("periodic_reached_at", float("nan")),
    }
    if "camera" in s and "camera" in r and r["camera"].get("peak_rise"):
        result["camera_peak"] = relative(s["camera"]["peak_rise"], r["camera"]["peak_rise"])
    return result


def check_restart_inside_continuation(check, exe, args, tmp):
    """A run stopped by SIGUSR1 inside a continuation's heat ladder (args must make the
    ladder long enough to catch, e.g. camera windows) restarts from its checkpoint and ends
    identical to the run never stopped: energy.csv, probes.csv, periodic.csv, summary figures."""
    whole, stopped = os.path.join(tmp, "whole"), os.path.join(tmp, "stopped")
    r = subprocess.run([exe] + args + ["-overwrite", "-output_dir", whole], capture_output=True, text=True)
    check(r.returncode == 0, "%s: %s" % (whole, r.stderr[-1500:]))
    if r.returncode != 0:
        return
    p = subprocess.Popen([exe] + args + ["-overwrite", "-output_dir", stopped], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True)
    for line in p.stdout:
        if line.startswith("Periodic at"):
            time.sleep(0.3)
            p.send_signal(signal.SIGUSR1)
            break
    p.communicate()
    check(p.returncode == 128 + signal.SIGUSR1, "stopped by SIGUSR1 inside the continuation: exit %s" % p.returncode)
    r = subprocess.run([exe] + args + ["-restart", stopped, "-output_dir", stopped], capture_output=True, text=True)
    check(r.returncode == 0, "restart: %s" % r.stderr[-800:])
    if r.returncode == 0:
        for name in ("energy.csv", "probes.csv", "periodic.csv"):
            same = open(os.path.join(whole, name)).read() == open(os.path.join(stopped, name)).read()
            check(same, "restart inside the continuation: %s differs from the run never stopped" % name)
        a, b = summary(whole), summary(stopped)
        check(a["dissipated_energy"] == b["dissipated_energy"] and a.get("camera") == b.get("camera"),
              "restart: summary figures differ")
