"""scripts/convergence --study periodic: what the periodic continuation costs in accuracy
and saves in time (issue 24). The paper scene and options/thermosonic.opts with
DURATION of excitation (default 20 ms) and a camera at 1000 fps, run fully resolved
(-periodic_min_continued 1e9: the same quantized wave step, no continuation) and with
the continuation at each -periodic_tol; against the resolved run: dissipated energy,
heat content, the crack-centre temperature at every period end both record (largest
error against its peak), the camera's peak pixel, and the wall-time ratio.
Writes DIR/periodic.{csv,md} and DIR/periodic_work_precision.png."""
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import package  # noqa: E402,F401  (scripts/vibrotherm of this checkout)
import periodic_compare  # noqa: E402
import vibrotherm as vt  # noqa: E402

TOLERANCES = [1e-2, 3e-3, 1e-3, 3e-4]
SCENES = {"paper": ("paper.opts", 1e-5), "thermosonic": ("thermosonic.opts", 1.0 / 62080.43257)}
ERRORS = [("dissipated", "dissipated energy"), ("heat_content", "heat content"),
          ("crack_probe", "crack-centre temperature at period ends"), ("camera_peak", "camera peak pixel")]


def scene_options(scene, duration):
    opts, _ = SCENES[scene]
    return ["-options_file", os.path.join(vt.ROOT, "options", opts), "-source_duration", repr(duration),
            "-final_time", repr(duration * 1.05), "-output_times", repr(duration), "-camera", "-camera_fps", "1000",
            "-camera_netd", "0.02", "-probe_every", "20", "-crack_state_every", "0", "-checkpoint_every_s", "0"]


def run_one(ranks, out, options, reuse):
    if reuse and os.path.exists(os.path.join(out, "summary.json")):
        return
    print("run:", " ".join(options), flush=True)
    vt.run_scene(None, vt.launch.option_dict(options), out, ranks=ranks, overwrite=True)


def study(ranks, output, duration, reuse):
    rows = []
    for scene, (_, period) in SCENES.items():
        base = scene_options(scene, duration)
        ref = os.path.join(output, "periodic", scene, "resolved")
        run_one(ranks, ref, base + ["-periodic_min_continued", "1000000000"], reuse)
        for tol in TOLERANCES:
            out = os.path.join(output, "periodic", scene, "tol_%g" % tol)
            run_one(ranks, out, base + ["-periodic_tol", repr(tol)], reuse)
            c = periodic_compare.compare(out, ref, crack_probe=5, period=period)
            c.update(scene=scene, tol=tol)
            rows.append(c)
    write_tables(rows, output, duration)
    plot(rows, output, duration)
    return rows


def write_tables(rows, output, duration):
    fields = ["scene", "tol", "reached_at", "continued", "wall", "wall_reference", "wall_ratio", "dissipated",
              "heat_content", "crack_probe", "crack_probe_period_ends", "camera_peak"]
    with open(os.path.join(output, "periodic.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(output, "periodic.md"), "w") as f:
        f.write("%g ms of excitation, each continued run against the fully resolved one\n\n" % (duration * 1e3))
        f.write("| scene | -periodic_tol | periodic at [ms] | periods continued | wall [s] | resolved [s] | speed-up "
                "| dissipated | heat content | crack centre, period ends | camera peak |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| %s | %g | %.3g | %d | %.1f | %.1f | %.1f× | %+.2f %% | %+.2f %% | %.2f %% (%d ends) | %+.2f %% |\n" % (
                r["scene"], r["tol"], r["reached_at"] * 1e3, r["continued"], r["wall"], r["wall_reference"],
                r["wall_ratio"], 100 * r["dissipated"], 100 * r["heat_content"], 100 * r["crack_probe"],
                r["crack_probe_period_ends"], 100 * r.get("camera_peak", float("nan"))))
    print(open(os.path.join(output, "periodic.md")).read())


def plot(rows, output, duration):
    fig, axes = plt.subplots(1, len(ERRORS), figsize=(18, 4.8))
    for ax, (key, title) in zip(axes, ERRORS):
        for k, scene in enumerate(SCENES):
            curve = [r for r in rows if r["scene"] == scene and key in r]
            if not curve:
                continue
            ax.loglog([r["wall"] for r in curve], [max(abs(r[key]), 1e-7) for r in curve], "o-", color="C%d" % k,
                      label="%s (continued)" % scene)
            for r in curve:
                ax.annotate("%g" % r["tol"], (r["wall"], max(abs(r[key]), 1e-7)), fontsize=7, xytext=(3, 3),
                            textcoords="offset points")
            ax.axvline(curve[0]["wall_reference"], color="C%d" % k, ls=":", lw=1)
        ax.axhline(5e-3 if key in ("dissipated", "heat_content") else 1e-2, color="r", ls="--", lw=0.8)
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("wall time [s] (dotted: fully resolved)")
        ax.set_ylabel("relative error vs fully resolved")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8)
    fig.suptitle("Periodic continuation, %g ms of excitation: error against cost over -periodic_tol (labels); "
                 "red: the issue's targets" % (duration * 1e3))
    fig.tight_layout()
    path = os.path.join(output, "periodic_work_precision.png")
    fig.savefig(path, dpi=120)
    print("wrote", path)
