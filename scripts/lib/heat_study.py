"""The temperature part of scripts/convergence: the crack-centre rise of the full
paper scene (1 ms of waves, diffusion to 1 s) at the output times, and its
saw-tooth at every wave step of the source periods before 0.1 and 0.2 ms (a run
to 0.2 ms with -crack_state_every 1 -probe_every 1; crack_sawtooth.py), against

  * the continuum: the line-source convolution of the friction power each run
    exchanged (crack_heat.h5, scripts/lib/line_source.py) with the images that
    hold the specimen's edges at T0 — an independent reference for every run;
  * for the saw-tooth, the continuum of the friction energy at every wave step
    (crack_state.csv): the worst sample and the mean of each period, relative
    to the period's mean rise;
  * heat-mesh refinement with the wave side fixed (first layer, length along the
    crack and far size × 2, √2, 1, 1/√2) and heat steps per coupling interval;
  * wave-mesh refinement with the heat side at its default (the friction power
    itself changes: self-convergence against the finest wave mesh).
"""
import math
import os
import sys

import numpy as np

import crack_sawtooth
import line_source
import package  # noqa: F401  (scripts/vibrotherm of this checkout)
import vibrotherm as vt

TIMES = [1e-4, 2e-4, 5e-4, 1e-3, 1e-2, 1.0]
PERIOD_ENDS, PERIOD = (1e-4, 2e-4), 1e-5  # the saw-tooth's periods (paper scene: 100 kHz)


def paper_heat_sizes(paper_option):
    """Defaults of the heat mesh in paper.opts (heat_mesh.hpp): first layer, along, far."""
    alpha = float(paper_option("heat_conductivity")) / (float(paper_option("material_density")) *
                                                       float(paper_option("heat_capacity")))
    couple_dt = 1.0 / (8.0 * float(paper_option("source_frequency")))
    substeps = 3
    return alpha, {"h_crack": 0.5 * math.sqrt(alpha * couple_dt / substeps),
                   "h_along": 0.5 * float(paper_option("mesh_h_crack")), "h": float(paper_option("mesh_h"))}


def settings(paper_option):
    """(name, options) of every run of the study."""
    _, sizes = paper_heat_sizes(paper_option)
    out = []
    for scale in (2.0, math.sqrt(2.0), 1.0, 1.0 / math.sqrt(2.0), 0.5):
        opts = ["-heat_mesh_h_crack", "%.4g" % (sizes["h_crack"] * scale),
                "-heat_mesh_h_along", "%.4g" % (sizes["h_along"] * scale), "-heat_mesh_h", "%.4g" % (sizes["h"] * scale)]
        out.append(("heat_h%.3f" % scale, "heat mesh", scale, opts))
    for substeps in (1, 2, 6):
        out.append(("heat_substeps%d" % substeps, "heat steps", substeps, ["-heat_substeps", str(substeps)]))
    out.append(("heat_q2", "heat degree 2", 2, ["-heat_degree", "2"]))
    for scale in (math.sqrt(2.0), 1.0 / math.sqrt(2.0), 0.5):
        opts = ["-mesh_h", "%.6g" % (float(paper_option("mesh_h")) * scale),
                "-mesh_h_crack", "%.6g" % (float(paper_option("mesh_h_crack")) * scale)]
        out.append(("wave_h%.3f" % scale, "wave mesh", scale, opts))
    return out


def run_one(ranks, out, extra, reuse, sawtooth=False):
    """The full scene (output times), or (sawtooth) 0.2 ms recorded at every wave step; its summary."""
    if not (reuse and os.path.exists(os.path.join(out, "summary.json"))):
        record = ({"final_time": "%.6g" % (max(PERIOD_ENDS) * 1.00005), "output_times": "%g" % max(PERIOD_ENDS),
                   "crack_state_every": 1, "probe_every": 1} if sawtooth else
                  {"output_times": TIMES, "crack_state_every": 0})
        try:
            vt.run_scene(os.path.join(vt.ROOT, "options", "paper.opts"), dict(record, **vt.launch.option_dict(extra)),
                         out, ranks=ranks, overwrite=True)
        except vt.RunFailed as failed:
            sys.exit("scripts/convergence: %s failed:\n%s" % (out, failed.stderr[-3000:]))
    return vt.load(out).summary


def measure(out, summary, alpha, rho_c, width, height):
    """Crack-centre rise at every output time, its continuum value and the heat side's wall time."""
    centre = [k for k, v in summary["probe_labels"].items() if v.endswith("xi = 0.500000")][0]
    record = line_source.CrackHeat(os.path.join(out, "crack_heat.h5"))
    point = record.vertices[np.argmin(np.abs(record.vertices[:, 1] - 0.5)), 2:4]
    rows = []
    for row in summary["output_temperature_rise"]:
        continuum = line_source.temperature_rise(record, point, row["t"], alpha, rho_c, width, height)
        rows.append({"t": row["t"], "rise": row[centre], "continuum": continuum})
    stages = summary["stages"]
    heat = stages.get("heat_steps", 0.0) + stages.get("heat_setup", 0.0)
    peak = summary.get("field_max_temperature_rise", {})
    return {"rows": rows, "wall": summary["wall_time_s"], "heat_wall": heat, "dofs_heat": summary["dofs_heat"],
            "dofs_wave": summary["dofs_wave"], "steps_heat": summary["steps_heat"],
            "field_peak": peak.get("value", float("nan")) if isinstance(peak, dict) else float(peak)}


def measure_sawtooth(out, alpha, rho_c):
    """The crack centre's saw-tooth in the periods before 0.1 and 0.2 ms (crack_sawtooth.period_errors);
    the run's crack_state.csv (hundreds of MB) is deleted once read."""
    periods = crack_sawtooth.period_errors(out, 0.5, PERIOD_ENDS, PERIOD, alpha, rho_c)
    if os.path.exists(os.path.join(out, "crack_state.csv")):
        os.remove(os.path.join(out, "crack_state.csv"))
    return periods


def table(results, reference):
    """Markdown: errors vs the continuum (and vs the finest wave mesh for wave rows) at each time."""
    head = "| setting | heat dofs | heat steps | heat wall [s] | run wall [s] | " + " | ".join(
        "%g ms" % (t * 1e3) for t in TIMES) + " | " + " | ".join(
        "saw-tooth %g ms: worst, mean" % (t * 1e3) for t in PERIOD_ENDS) + " |\n|" + "---|" * (
        5 + len(TIMES) + len(PERIOD_ENDS)) + "\n"
    lines = []
    for name, kind, value, m in results:
        errs = []
        for t in TIMES:
            row = min(m["rows"], key=lambda r: abs(r["t"] - t))
            if kind == "wave mesh":
                ref_row = min(reference["rows"], key=lambda r: abs(r["t"] - t))
                errs.append("%+.2f %%" % (100 * (row["rise"] / ref_row["rise"] - 1)))
            else:
                errs.append("%+.2f %%" % (100 * (row["rise"] / row["continuum"] - 1)))
        for p in m.get("sawtooth", []):
            errs.append("%.2f %%, %+.2f %%" % (100 * p["worst"], 100 * p["mean_error"]))
        lines.append("| %s | %d | %d | %.2f | %.1f | %s |" % (name, m["dofs_heat"], m["steps_heat"], m["heat_wall"],
                                                             m["wall"], " | ".join(errs)))
    return head + "\n".join(lines) + "\n"
