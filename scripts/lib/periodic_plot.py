"""periodic.png: a run with periodic continuation over its whole time (issue 24).

(a) the crack's friction power averaged over each source period (from energy.csv's
    dissipated energy) against time: build-up, the simulated periods, the continued
    stretches (shaded, from summary.json "periodic"), the ring-down; log time;
(b) the temperature rise over seconds: the crack centre (probe) and the camera's
    peak pixel per frame, with the NETD and the detection threshold.
Skipped for a run without continuation."""
import os

import matplotlib.pyplot as plt
import numpy as np

import package  # noqa: F401  (scripts/vibrotherm of this checkout)
from vibrotherm import MissingOutput as Skip


def friction_power(run):
    """(t, power [W/m]) averaged between consecutive energy.csv rows at least a source period apart."""
    e = run.table("energy.csv")
    period = 1.0 / float(run.summary["option_values"]["-source_frequency"]["value"])
    t, W = e["t"], e["dissipated"]
    times, power, last = [], [], 0
    for i in range(1, len(t)):
        if t[i] - t[last] >= period * (1 - 1e-6):
            times.append(0.5 * (t[i] + t[last]))
            power.append((W[i] - W[last]) / (t[i] - t[last]))
            last = i
    return np.array(times), np.array(power)


def camera_peaks(run):
    path = run.path("camera.h5")
    if not os.path.exists(path):
        return None
    import h5py
    with h5py.File(path, "r") as f:
        times = np.array(f["camera/time"])[:, 0]  # (centre, start, end) of each frame's window
        peaks = np.array([np.max(f["camera/clean_%d" % k]) for k in range(len(times))])
    return times, peaks


def figure(run):
    segments = run.summary.get("periodic", [])
    if not segments:
        raise Skip("no periodic continuation in this run")
    fig, (a, b) = plt.subplots(1, 2, figsize=(14, 5))
    t, p = friction_power(run)
    keep = p > 0
    a.loglog(t[keep], p[keep], ".-", ms=3, lw=0.8, color="C3", label="friction power, per period")
    for k, s in enumerate(segments):
        a.axvspan(s["suspended"], s["resumed"], color="C0", alpha=0.12, label="continued" if k == 0 else None)
        a.axvline(s["detected"], color="C2", ls=":", lw=1, label="found periodic" if k == 0 else None)
    a.set_xlabel("t [s]")
    a.set_ylabel("friction power [W/m]")
    a.set_title("(a) the crack's friction: build-up, continuation (%d periods not simulated), ring-down"
                % sum(s["periods_continued"] for s in segments), fontsize=10)
    a.legend(fontsize=8)
    a.grid(True, which="both", alpha=0.3)
    probes = run.table("probes.csv")
    crack = [index for index, xi in run.crack_probes().values() if abs(xi - 0.5) < 1e-9]
    T0 = 293.15
    if crack:
        rows = (probes["probe"] == crack[0]) & np.isfinite(probes["temperature"])
        rise = probes["temperature"][rows] - T0
        b.loglog(probes["t"][rows][rise > 0], rise[rise > 0], color="C3", lw=1, label="crack centre")
    camera = camera_peaks(run)
    if camera is not None:
        ct, peak = camera
        b.loglog(ct[peak > 0], peak[peak > 0], "o", ms=3, color="C1", label="camera: peak pixel per frame")
        c = run.summary.get("camera", {})
        if c.get("netd"):
            b.axhline(c["netd"], color="k", ls="--", lw=1, label="NETD %.3g K" % c["netd"])
            b.axhline(c["netd"] * c.get("detect_snr", 1), color="r", ls=":", lw=1,
                      label="detection: SNR %g" % c.get("detect_snr", 1))
    for s in segments:
        b.axvspan(s["suspended"], s["resumed"], color="C0", alpha=0.12)
    verdict = ""
    if "camera_peak_snr" in run.summary:
        verdict = ": peak SNR %.3g, %s" % (run.summary["camera_peak_snr"],
                                          "detectable" if run.summary.get("camera_detectable") else "not detectable")
    b.set_xlabel("t [s]")
    b.set_ylabel("temperature rise [K]")
    b.set_title("(b) temperature over the test%s" % verdict, fontsize=10)
    b.legend(fontsize=8)
    b.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    return fig
