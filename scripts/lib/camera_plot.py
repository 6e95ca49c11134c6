"""camera.png: what the IR camera saw (camera.h5 of a -camera run).

    draw(run_dir, out_png)      draws, or prints "skipped camera.png: <why>"
    figure(run_dir)             the figure, or raises vibrotherm.MissingOutput (scripts/plot's list)

Left: the best frame (largest noise-free pixel) without noise; middle: the same frame as
the camera reads it (with NETD noise); right: the peak SNR of every frame (its largest
noise-free pixel over the NETD) against time, with the detection threshold.
numpy, h5py and matplotlib only.
"""
import json
import os

import numpy as np

import package  # noqa: F401  (scripts/vibrotherm of this checkout)
from vibrotherm import MissingOutput as Skip


def _read(run_dir):
    """Frames (clean, noisy), their window times, the pixel grid and the camera's attributes."""
    import h5py

    with h5py.File(os.path.join(run_dir, "camera.h5"), "r") as f:
        g = f["camera"]
        times = g["time"][:]
        attrs = {k: np.asarray(v) for k, v in g.attrs.items()}
        peaks = np.array([g["clean_%d" % k][:].max() for k in range(len(times))])
        best = int(np.argmax(peaks)) if len(peaks) else 0
        clean = g["clean_%d" % best][:] if len(peaks) else None
        noisy = g["frame_%d" % best][:] if len(peaks) else None
    return times, peaks, best, clean, noisy, attrs


def _detect_snr(run_dir):
    try:
        with open(os.path.join(run_dir, "summary.json")) as f:
            return float(json.load(f).get("camera", {}).get("detect_snr", 5.0))
    except (OSError, ValueError):
        return 5.0


def _hot_box(values, extent):
    """[x0, x1, y0, y1] around the pixels above 5 % of the peak, padded (the whole extent when they fill it)."""
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


def _image(ax, fig, values, extent, title, cmap, vmin=None, vmax=None, box=None):
    im = ax.imshow(values, origin="lower", extent=extent, cmap=cmap, vmin=vmin, vmax=vmax, interpolation="nearest")
    if box:
        ax.set_xlim(box[0], box[1])
        ax.set_ylim(box[2], box[3])
        title += " (zoom)"
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    fig.colorbar(im, ax=ax, shrink=0.85, label="temperature rise [K]")


def _snr_panel(ax, times, peaks, netd, threshold, best):
    snr = peaks / netd if netd > 0 else np.full_like(peaks, np.inf)
    ax.plot(times[:, 0], snr, "o-", ms=3, color="#d62728", label="peak SNR of the frame")
    ax.axhline(threshold, color="k", ls="--", lw=1, label="detectable from SNR %g" % threshold)
    ax.plot(times[best, 0], snr[best], "k*", ms=10, label="best frame")
    if len(times) > 1 and times[-1, 0] > 100 * times[0, 0]:
        ax.set_xscale("log")
    else:
        ax.locator_params(axis="x", nbins=6)
        ax.ticklabel_format(axis="x", style="sci", scilimits=(-2, 3))
    if np.all(snr > 0):  # from far below to far above the threshold: log
        ax.set_yscale("log")
    ax.set_xlabel("time (window centre) [s]")
    ax.set_ylabel("peak rise / NETD")
    ax.set_title("SNR vs time (NETD %g mK)" % (netd * 1e3), fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, loc="best")


def draw(run_dir, out_png):
    """Draws camera.png from run_dir/camera.h5, or prints why it skips."""
    import matplotlib.pyplot as plt

    try:
        fig = figure(run_dir)
    except Skip as why:
        print("skipped %s: %s" % (os.path.basename(out_png), why))
        return
    fig.savefig(out_png, dpi=130)
    plt.close(fig)
    print("wrote", out_png)


def figure(run_dir):
    """The camera figure of run_dir; raises Skip when the run has no camera frames."""
    if not os.path.exists(os.path.join(run_dir, "camera.h5")):
        raise Skip("no camera.h5 (run with -camera)")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    times, peaks, best, clean, noisy, attrs = _read(run_dir)
    if clean is None:
        raise Skip("camera.h5 has no frame")
    netd, window = float(attrs["netd"]), attrs["window"] * 1e3
    extent = [window[0], window[2], window[1], window[3]]
    threshold = _detect_snr(run_dir)
    aspect = (window[3] - window[1]) / (window[2] - window[0])
    fig, axes = plt.subplots(1, 3, figsize=(15, max(4.5, min(8.0, 4.0 * aspect))),
                             gridspec_kw={"width_ratios": [1, 1, 1.4]})
    when = "[%.4g, %.4g] s" % (times[best, 1], times[best, 2])
    # A frame that also cools (thermoelastic heating) on a diverging scale centred on 0.
    lowest = float(np.min(clean))
    if lowest < -1e-3 * peaks[best]:
        span = max(peaks[best], -lowest, 1e-300)
        cmap, vmin, vmax = "RdBu_r", -span, span
    else:
        cmap, vmin, vmax = "inferno", 0.0, max(peaks[best], 1e-300)
    _image(axes[0], fig, clean, extent, "best frame %d, %s, without noise\npeak %.3g K" % (best, when, peaks[best]),
           cmap, vmin=vmin, vmax=vmax, box=_hot_box(clean, extent))
    # Scaled as the camera's display would be: the noise band (±2 NETD) or the signal, whichever is larger.
    _image(axes[1], fig, noisy, extent, "as the camera reads it (NETD %g mK)\nSNR %.3g: %s" % (
        netd * 1e3, peaks[best] / netd if netd > 0 else np.inf,
        "detectable" if netd == 0 or peaks[best] / netd >= threshold else "not detectable"),
        "inferno", vmin=-2 * netd, vmax=max(peaks[best], 2 * netd, 1e-300))
    _snr_panel(axes[2], times, peaks, netd, threshold, best)
    fig.suptitle("IR camera: %d frames at %g fps, integration %g ms, pixel %g mm" % (
        len(times), float(attrs["fps"]), float(attrs["integration"]) * 1e3, float(attrs["pixel"]) * 1e3), fontsize=10)
    fig.tight_layout()
    return fig
