"""The LDR study's plots (scripts/study ldr): from study.json and the runs it made.

    heating_spectrum.png  efficiency and the defect's SNR against frequency at the common input
                          power, every mode of the band marked (its defect participation)
    thresholds.png        the detection threshold (input power, drive amplitude) at the best frequencies
    best_camera.png       the best candidate's camera frame at its defect's peak: what the camera
                          sees, and the defect's own share of it, the crack drawn
"""
import math
import os

import numpy as np


def _figure_module():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def heating_spectrum(study, path):
    plt = _figure_module()
    fig, axes = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    c = study["candidates"]
    khz = lambda f: np.asarray(f, dtype=float) / 1e3  # noqa: E731
    for ax in axes:
        for m in study["modes"]:
            ax.axvline(m["frequency"] / 1e3, color="0.8", lw=0.8 + 2.0 * max(0.0, m["participation"] - 0.5), zorder=0)
    panels = (("efficiency", "thermosonic efficiency\n(friction / input power)"),
              ("snr", "defect's peak SNR on the camera\nwithin %g s" % study["duration"]))
    for ax, (key, label) in zip(axes, panels):
        for kind, marker, name in ((True, "o", "mode of the band"), (False, "s", "off resonance")):
            pick = [x for x in c if x["mode"] == kind and (x[key] or 0) > 0]
            ax.plot(khz([x["frequency"] for x in pick]), [x[key] for x in pick], marker, ms=7,
                    mfc="C0" if kind else "white", mec="C0", ls="none", label=name)
        for x in c:  # a candidate the rescaling could not bring to the common power (a clapping onset)
            if x.get("at_common_power") is False and (x[key] or 0) > 0:
                ax.annotate("at %.3g x the power" % (1.0 + x["power_error"]), (x["frequency"] / 1e3, x[key]),
                            textcoords="offset points", xytext=(6, -12), fontsize=7, color="C1")
        ldr = [x for x in c if x.get("ldr") and (x[key] or 0) > 0]
        ax.plot(khz([x["frequency"] for x in ldr]), [x[key] for x in ldr], "*", ms=16, color="C3",
                label="local defect resonance (participation >= 0.8)")
        ax.set_yscale("log")
        ax.set_ylabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[1].axhline(study["detect_snr"], color="k", ls="--", lw=1, label="detectable from SNR %g" % study["detect_snr"])
    axes[0].legend(fontsize=8, loc="best")
    axes[1].legend(fontsize=8, loc="best")
    axes[1].set_xlabel("drive frequency [kHz] (grey lines: the modes, thicker = more defect participation)")
    gain = study.get("ldr_gain")
    fig.suptitle("Heating spectrum at a common input power of %.3g %s%s" % (
        study["common_input_power"], study.get("power_unit", "W/m"),
        "; LDR gain %.3g" % gain if gain else ""), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def thresholds(study, path):
    plt = _figure_module()
    rows = [t for t in study["thresholds"] if t.get("input_power")]
    fig, ax = plt.subplots(figsize=(7, 4))
    if rows:
        f = np.array([t["frequency"] for t in rows]) / 1e3
        power = np.array([t["input_power"] for t in rows])
        ax.bar(f, power, width=0.04 * (f.max() - f.min() + 1.0) + 0.3, color=["C2" if t["verified"] else "C1"
                                                                               for t in rows])
        for x, y, t in zip(f, power, rows):
            ax.annotate("%.3g %s\nA = %.3g m%s" % (y, study.get("power_unit", "W/m"), t["amplitude"],
                                                  "" if t["verified"] else "\n(not verified)"),
                        (x, y), ha="center", va="bottom", fontsize=8)
        ax.set_yscale("log")
        ax.set_ylim(power.min() / 3, power.max() * 5)
    none = [t for t in study["thresholds"] if not t.get("input_power")]
    for t in none:
        ax.axvline(t["frequency"] / 1e3, color="C3", ls=":", label="%.0f Hz: no drive detects" % t["frequency"])
    if none:
        ax.legend(fontsize=8)
    ax.set_xlabel("drive frequency [kHz]")
    ax.set_ylabel("input power to detect within %g s" % study["duration"])
    ax.set_title("Detection threshold (green: verified, 1.25x detects and 0.75x does not)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _crack_lines(summary):
    """The 2D cracks as (x0, y0, x1, y1) [m] from the run's options (3D: their outline on the x-y face)."""
    values = {k.lstrip("-"): v.get("value", "") for k, v in summary.get("option_values", {}).items()}
    try:
        centres = [float(v) for v in values.get("crack_center", "").split(",") if v.strip()]
    except ValueError:
        return []
    dim = 3 if summary.get("dimension") == 3 else 2
    per = lambda key, n, default: ([float(v) for v in values.get(key, "").split(",") if v.strip()] or [default]) * n  # noqa
    n = len(centres) // dim
    lengths, angles = per("crack_length", n, 0.0), per("crack_angle", n, 0.0)
    lines = []
    for k in range(n):
        x, y = centres[dim * k], centres[dim * k + 1]
        half, a = 0.5 * lengths[k], math.radians(angles[k])
        lines.append((x - half * math.cos(a), y - half * math.sin(a), x + half * math.cos(a), y + half * math.sin(a)))
    return lines


def best_camera(study, output_dir, path):
    """The camera frame (and the defect's share) of the candidate with the largest defect SNR."""
    import package  # noqa: F401  (scripts/vibrotherm on the path)
    import vibrotherm as vt
    from ldr_study import detection_rank  # ranked as the study ranks them

    plt = _figure_module()
    best = max(study["candidates"], key=detection_rank)
    run = vt.load(os.path.join(output_dir, best["run"]))
    summary = run.summary
    frame = summary.get("camera", {}).get("defect_peak_frame", 0)
    camera = run.camera()
    clean = camera["clean"].values[frame]
    defect = camera["defect"].values[frame] if "defect" in camera else clean
    x, y = camera["x"].values, camera["y"].values
    p = x[1] - x[0] if len(x) > 1 else 1.0
    extent = [1e3 * (x[0] - p / 2), 1e3 * (x[-1] + p / 2), 1e3 * (y[0] - p / 2), 1e3 * (y[-1] + p / 2)]
    from camera_plot import temperature_unit

    scale, unit = temperature_unit(float(clean.max()))
    fig, axes = plt.subplots(2, 1, figsize=(9, 5.5))
    for ax, values, title in ((axes[0], clean, "what the camera sees (all heat)"),
                              (axes[1], defect, "the defect's own share (its friction heat)")):
        im = ax.imshow(values * scale, origin="lower", extent=extent, cmap="inferno", aspect="auto")
        for x0, y0, x1, y1 in _crack_lines(summary):
            ax.plot([1e3 * x0, 1e3 * x1], [1e3 * y0, 1e3 * y1], color="c", lw=1.5, label="crack")
        ax.set_title(title, fontsize=9)
        ax.set_ylabel("y [mm]")
        fig.colorbar(im, ax=ax, label="rise [%s]" % unit, pad=0.01)
    axes[1].set_xlabel("x [mm]")
    fig.suptitle("Best candidate %.0f Hz at %.3g %s in: frame at t = %.3g s, defect SNR %.3g, %s" % (
        best["frequency"], best["input_power"], study.get("power_unit", "W/m"),
        summary.get("camera", {}).get("defect_peak_time", float("nan")), best["snr"] or 0.0,
        "detectable" if best["detectable"] else "not detectable"), fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def draw_all(study, output_dir, log=print):
    for name, draw in (("heating_spectrum.png", lambda p: heating_spectrum(study, p)),
                       ("thresholds.png", lambda p: thresholds(study, p)),
                       ("best_camera.png", lambda p: best_camera(study, output_dir, p))):
        path = os.path.join(output_dir, name)
        draw(path)
        log("wrote " + path)
