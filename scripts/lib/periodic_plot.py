"""periodic.png: a run with periodic continuation over its whole time (issue 24).

(a) the crack's friction power averaged over each source period (from energy.csv's
    dissipated energy) against time: build-up, the simulated periods, the continued
    stretches (shaded, from summary.json "periodic"), the ring-down; log time;
(b) the temperature rise over seconds: the crack centre (a crack probe, 2D) or the hottest
    point probe (3D has no crack probes), the specimen's hottest point at each output time
    (fields.h5) and the camera's peak pixel per frame, with the NETD and the detection threshold.
Skipped for a run without continuation."""
import matplotlib.pyplot as plt
import numpy as np

import package  # noqa: F401  (scripts/vibrotherm of this checkout)
from vibrotherm import MissingOutput as Skip


def friction_power(run):
    """(t, power [W/m]) averaged between consecutive energy.csv rows at least a source period apart."""
    e = run.table("energy.csv")
    period = run.period
    t, W = e["t"], e["dissipated"]
    times, power, last = [], [], 0
    for i in range(1, len(t)):
        if t[i] - t[last] >= period * (1 - 1e-6):
            times.append(0.5 * (t[i] + t[last]))
            power.append((W[i] - W[last]) / (t[i] - t[last]))
            last = i
    return np.array(times), np.array(power)


def camera_peaks(run):
    """(window centres, peak noise-free pixel of each frame), or None without a camera."""
    if not run.has("camera.h5"):
        return None
    clean = run.camera()["clean"]
    return clean["time"].values, clean.max(dim=("y", "x")).values


def hottest_probe(run, probes):
    """(t, rise, label) of the crack centre's probe (2D), else of the point probe that rose most."""
    T0 = run.number("heat_T0", 293.15)
    crack = [index for index, xi in run.crack_probes().values() if abs(xi - 0.5) < 1e-9]
    if crack:
        index, label = crack[0], "crack centre"
    else:
        rises = {int(k): v for k, v in run.summary.get("probe_max_temperature_rise", {}).items()}
        if not rises or max(rises.values()) <= 0:
            return None
        index = max(rises, key=rises.get)
        label = "hottest probe, %s" % run.probe_labels.get(index, index)
    rows = (probes["probe"] == index) & np.isfinite(probes["temperature"])
    return probes["t"][rows], probes["temperature"][rows] - T0, label


def field_peaks(run):
    """(output times, the specimen's largest temperature rise at each) from fields.h5, or None."""
    try:
        rise = run.field("heat", "temperature_rise")
    except Skip:
        return None
    return rise["time"].values, rise.max(dim=rise.dims[1]).values


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
    a.set_ylabel("friction power [%s]" % ("W" if run.dimension == 3 else "W/m"))
    a.set_title("(a) the crack's friction: build-up, continuation (%d periods not simulated), ring-down"
                % sum(s["periods_continued"] for s in segments), fontsize=10)
    a.legend(fontsize=8)
    a.grid(True, which="both", alpha=0.3)
    probe = hottest_probe(run, run.table("probes.csv"))
    if probe is not None:
        t, rise, label = probe
        b.loglog(t[rise > 0], rise[rise > 0], color="C3", lw=1, label=label)
    fields = field_peaks(run)
    if fields is not None:
        t, peak = fields
        b.loglog(t[peak > 0], peak[peak > 0], "s", ms=5, color="C4", label="hottest point of the specimen (fields.h5)")
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
