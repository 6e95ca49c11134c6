"""camera.png: what the IR camera saw (camera.h5 of a -camera run).

    draw(run, out_png)      draws, or prints "skipped camera.png: <why>"
    figure(run)             the figure, or raises vibrotherm.MissingOutput (scripts/plot's list)

run: a vibrotherm.Run or a run directory. Left: the best frame (largest noise-free pixel)
without noise; middle: the same frame as the camera reads it (with NETD noise); right: the
peak SNR of every frame (its largest noise-free pixel over the NETD) against time, with the
detection threshold. The cracks are drawn dashed on both frames: 2D their lines (mesh.h5),
3D their outlines projected on the filmed face. Temperatures in the unit that needs no
exponent on the colour bars (K, mK, µK or nK).
"""
import os

import numpy as np

import package  # noqa: F401  (scripts/vibrotherm of this checkout)
from vibrotherm import MissingOutput as Skip
from vibrotherm import Run
from vibrotherm.crack_geometry import project

CRACK_COLOUR = "cyan"


PREFIXES = {0: "K", -3: "mK", -6: "µK", -9: "nK", -12: "pK", -15: "fK", -18: "aK"}


def temperature_unit(peak):
    """(scale, unit) for temperatures up to `peak` [K]: values from 1 to 1000 on the bars (K for
    1 K and more), so that no exponent sits above a colour bar."""
    if not np.isfinite(peak) or peak <= 0:
        return 1.0, "K"
    exponent = min(0, 3 * int(np.floor(np.log10(peak) / 3)))
    return 10.0 ** -exponent, PREFIXES.get(exponent, "1e%d K" % exponent)


def _hot_box(values, extent):
    """[x0, x1, y0, y1] around the pixels above 5 % of the peak, padded (None when they fill it)."""
    rows, cols = np.nonzero(values > 0.05 * values.max())
    if len(rows) == 0:
        return None
    ny, nx = values.shape
    px, py = (extent[1] - extent[0]) / nx, (extent[3] - extent[2]) / ny
    x0, x1 = extent[0] + cols.min() * px, extent[0] + (cols.max() + 1) * px
    y0, y1 = extent[2] + rows.min() * py, extent[2] + (rows.max() + 1) * py
    pad = 0.5 * max(x1 - x0, y1 - y0)
    box = [max(extent[0], x0 - pad), min(extent[1], x1 + pad), max(extent[2], y0 - pad), min(extent[3], y1 + pad)]
    whole = (box[1] - box[0]) * (box[3] - box[2]) > 0.5 * (extent[1] - extent[0]) * (extent[3] - extent[2])
    return None if whole else box


def crack_lines(run, face):
    """[(name, (n × 2) points in the frame's axes [mm])] of the cracks the run can place."""
    lines = []
    for name, points in run.crack_outlines():
        flat = project(points, face) if points.shape[1] == 3 else points
        lines.append((name, flat * 1e3))
    return lines


def _draw_cracks(ax, lines, label=True):
    for name, points in lines:
        ax.plot(points[:, 0], points[:, 1], color=CRACK_COLOUR, lw=1.0, ls="--")
        if label:
            ax.annotate(name, points[np.argmax(points[:, 1])], xytext=(3, 3), textcoords="offset points",
                        color=CRACK_COLOUR, fontsize=7, fontweight="bold")


def _image(ax, fig, values, extent, title, cmap, unit, vmin=None, vmax=None, box=None, axes=("x", "y")):
    im = ax.imshow(values, origin="lower", extent=extent, cmap=cmap, vmin=vmin, vmax=vmax, interpolation="nearest")
    if box:
        ax.set_xlim(box[0], box[1])
        ax.set_ylim(box[2], box[3])
        title += " (zoom)"
    else:
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("%s [mm]" % axes[0])
    ax.set_ylabel("%s [mm]" % axes[1])
    bar = fig.colorbar(im, ax=ax, shrink=0.85, label="temperature rise [%s]" % unit)
    bar.formatter.set_useOffset(False)
    bar.update_ticks()


def _snr_panel(ax, times, peaks, netd, threshold, best):
    snr = peaks / netd if netd > 0 else np.full_like(peaks, np.inf)
    log_time = len(times) > 1 and times[-1] > 100 * times[0]
    scale, unit = (1.0, "s") if log_time or times[-1] >= 1 else (1e3, "ms")  # no exponent under the axis
    t = times * scale
    ax.plot(t, snr, "o-", ms=3, color="#d62728", label="peak SNR of the frame")
    ax.axhline(threshold, color="k", ls="--", lw=1, label="detectable from SNR %g" % threshold)
    ax.plot(t[best], snr[best], "k*", ms=10, label="best frame")
    if log_time:
        ax.set_xscale("log")
    if np.all(snr > 0):  # from far below to far above the threshold: log
        ax.set_yscale("log")
    ax.set_xlabel("time (window centre) [%s]" % unit)
    ax.set_ylabel("peak rise / NETD")
    ax.set_title("SNR vs time (NETD %g mK)" % (netd * 1e3), fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="best")


def draw(run, out_png):
    """Draws camera.png from the run's camera.h5, or prints why it skips."""
    import matplotlib.pyplot as plt

    try:
        fig = figure(run)
    except Skip as why:
        print("skipped %s: %s" % (os.path.basename(out_png), why))
        return
    fig.savefig(out_png, dpi=130)
    plt.close(fig)
    print("wrote", out_png)


def figure(run):
    """The camera figure of a run; raises Skip when the run has no camera frames."""
    run = run if isinstance(run, Run) else Run(run)
    if not run.has("camera.h5"):
        raise Skip("no camera.h5 (run with -camera)")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    camera = run.camera()
    if camera.sizes.get("time", 0) == 0:
        raise Skip("camera.h5 has no frame")
    clean_frames = camera["clean"].values
    peaks = clean_frames.reshape(len(clean_frames), -1).max(axis=1)
    best = int(np.argmax(peaks))
    clean, noisy = clean_frames[best], camera["frame"].values[best]
    netd, window = float(camera.attrs["netd"]), np.asarray(camera.attrs["window"], float) * 1e3
    extent = [window[0], window[2], window[1], window[3]]
    face = run.option("camera_face", "front") if run.dimension == 3 else None
    axes_names = {"top": ("x", "z"), "bottom": ("x", "z"), "left": ("z", "y"), "right": ("z", "y")}.get(face, ("x", "y"))
    threshold = float(run.value("camera.detect_snr", 5.0))
    lines = crack_lines(run, face)
    aspect = (window[3] - window[1]) / (window[2] - window[0])
    fig, axes = plt.subplots(1, 3, figsize=(16, max(5.0, min(8.5, 4.5 * aspect))),
                             gridspec_kw={"width_ratios": [1, 1, 1.3]})
    when = "[%.4g, %.4g] s" % (float(camera["window_start"][best]), float(camera["window_end"][best]))
    scale, unit = temperature_unit(max(peaks[best], -float(np.min(clean))))
    # A frame that also cools (thermoelastic heating) on a diverging scale centred on 0.
    lowest = float(np.min(clean))
    if lowest < -1e-3 * peaks[best]:
        span = max(peaks[best], -lowest, 1e-300) * scale
        cmap, vmin, vmax = "RdBu_r", -span, span
    else:
        cmap, vmin, vmax = "inferno", 0.0, max(peaks[best] * scale, 1e-300)
    where = " on the %s face" % face if face else ""
    _image(axes[0], fig, clean * scale, extent, "best frame %d, %s, no noise\npeak %.3g %s; dashed: the crack"
           % (best, when, peaks[best] * scale, unit), cmap, unit, vmin=vmin, vmax=vmax,
           box=_hot_box(clean, extent), axes=axes_names)
    _draw_cracks(axes[0], lines)
    # Scaled as the camera's display would be: the noise band (±2 NETD) or the signal, whichever is larger.
    noise_scale, noise_unit = temperature_unit(max(peaks[best], 2 * netd))
    _image(axes[1], fig, noisy * noise_scale, extent, "as the camera reads it (NETD %g mK)\nSNR %.3g: %s" % (
        netd * 1e3, peaks[best] / netd if netd > 0 else np.inf,
        "detectable" if netd == 0 or peaks[best] / netd >= threshold else "not detectable"),
        "inferno", noise_unit, vmin=-2 * netd * noise_scale, vmax=max(peaks[best], 2 * netd, 1e-300) * noise_scale,
        axes=axes_names)
    _draw_cracks(axes[1], lines, label=False)
    _snr_panel(axes[2], camera["time"].values, peaks, netd, threshold, best)
    fig.suptitle("IR camera%s: %d frames at %g fps, integration %g ms, pixel %g mm" % (
        where, len(peaks), float(camera.attrs["fps"]), float(camera.attrs["integration"]) * 1e3,
        float(camera.attrs["pixel"]) * 1e3), fontsize=10)
    fig.tight_layout()
    return fig
