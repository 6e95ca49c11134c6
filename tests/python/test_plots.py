#!/usr/bin/python3
"""Requirement (issue 43 item 10): the plots show what the run did.
  * a run continued periodically (a pre-closed crack, 4 ms of 100 kHz): traction_loop.png's
    loop and its "same cycles" panel cover two whole periods the run recorded (the last
    simulated ones: the middle of the excitation was continued, not recorded), not "less
    than one excitation period";
  * a run with material damping (-material_damping_heat, thermoelastic heating):
    energy_budget.png draws the damped energy and names damping in its budget, and the heat
    panel draws every heat source;
  * a 3D run (options/block3d_small.opts, a 6 x 4 mm crack, with a camera on the front face):
    crack_maps.png spans the crack's 6 x 4 mm edge (drawn), not only its contact cells'
    5 x 3 mm; camera.png draws the crack's outline projected on the filmed face (its corners
    at the crack's (x, y) corners), names the face, and its colour bars carry no exponent
    (offset text) to collide with a title; the 3D traction loop takes the cell of largest
    W (its slip, tens of pm, not ~1e-12 nm);
  * a 3D -modes run: modes.png says which face the shapes are drawn on;
  * a free specimen's -modes run (README "Which excitation makes my defect visible?": its
    rigid-body modes have no strain energy, participation nan): modes.png is drawn, with the
    modes of largest participation;
  * a 3D run with a periodic continuation (its summary's segments given to the short run):
    periodic.png has a temperature curve though 3D has no crack probes.

usage: test_plots.py VIBROTHERM SOURCE_DIR"""
import importlib.machinery
import importlib.util
import json
import os
import shutil
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import package_test  # noqa: E402

test = package_test.setup("plots")
vt, check, program, src = test.vt, test.check, test.program, test.src
paper, block, coarse = test.paper, test.block, test.coarse
loader = importlib.machinery.SourceFileLoader("plot_script", os.path.join(src, "scripts", "plot"))
plot = importlib.util.module_from_spec(importlib.util.spec_from_loader("plot_script", loader))
loader.exec_module(plot)
import camera_plot  # noqa: E402  (scripts/lib, on the path once the plot script is loaded)
import crack_map_plot  # noqa: E402
import periodic_plot  # noqa: E402


def texts(fig):
    return " ".join([ax.get_title() for ax in fig.axes] + [t.get_text() for ax in fig.axes for t in ax.texts] +
                    ([fig._suptitle.get_text()] if fig._suptitle else []))


def labels(ax):
    return [line.get_label() for line in ax.get_lines()]


def continued_run(tmp):
    run = vt.run_scene(paper, dict(coarse, crack_a0=2e-8, source_amplitude=1.6e-8, crack_state_every=0,
                                   source_duration=4e-3, final_time=4e-3), os.path.join(tmp, "continued"),
                       program=program)
    check(run.value("derived.periodic_periods_continued") > 100, "the scene was continued: %s"
          % run.value("derived.periodic_periods_continued"))
    fig = plot.plot_traction_loop(run)
    loop, same = fig.axes[0], fig.axes[1]
    check("no whole excitation period" not in texts(fig) and "less than one" not in texts(fig),
          "continued run: traction loop without its cycles: %r" % texts(fig))
    t = same.get_lines()[0].get_xdata() if same.get_lines() else np.array([])
    check(len(t) > 10 and t.max() - t.min() > 1.8, "the 'same cycles' panel spans %.3g periods"
          % (np.ptp(t) if len(t) else 0))
    check(any("cycles from t = 3.9" in label for label in labels(loop)), "the loop's cycles: %s" % labels(loop))


def damped_run(tmp):
    run = vt.run_scene(paper, dict(coarse, final_time=2e-4, material_loss_factor=1e-2, material_damping_heat=True,
                                   thermoelastic="one_way"), os.path.join(tmp, "damped"), program=program)
    fig = plot.plot_energy_budget(run)
    waves, heat = fig.axes[0], fig.axes[1]
    check("dissipated by material damping" in labels(waves) and "damping" in waves.get_title(),
          "energy_budget.png without the damping: %s / %r" % (labels(waves), waves.get_title()))
    check({"deposited from crack friction", "deposited from material damping",
           "deposited thermoelastic (reversible)"} <= set(labels(heat)), "heat sources: %s" % labels(heat))


def crack_maps_3d(box):
    fig = crack_map_plot.figure(box)
    for ax in fig.axes:
        if ax.get_xlabel().startswith("s1"):
            dashed = [line for line in ax.get_lines() if line.get_linestyle() == "--"]
            check(len(dashed) == 1, "crack_maps.png: the crack's edge is not drawn")
            if dashed:
                x, y = dashed[0].get_xdata(), dashed[0].get_ydata()
                check(abs(np.ptp(x) - 6) < 1e-6 and abs(np.ptp(y) - 4) < 1e-6,
                      "the edge drawn is %.4g x %.4g mm, the crack 6 x 4" % (np.ptp(x), np.ptp(y)))
            low, high = ax.get_xlim()
            check(low <= -3 and high >= 3, "crack_maps.png shows s1 from %g to %g mm" % (low, high))


def camera_3d(box):
    fig = camera_plot.figure(box)
    fig.canvas.draw()
    outline = [line for line in fig.axes[0].get_lines() if line.get_linestyle() == "--"]
    corners = box.crack_outlines()[0][1][:4, :2] * 1e3
    if outline:
        drawn = np.column_stack([outline[0].get_xdata(), outline[0].get_ydata()])[:4]
        check(np.allclose(drawn, corners, atol=1e-9), "camera.png's crack outline %s, the crack's corners %s"
              % (drawn.tolist(), corners.tolist()))
    else:
        check.fail("camera.png draws no crack")
    check("front face" in texts(fig), "camera.png does not name the face: %r" % texts(fig))
    offsets = [ax.yaxis.get_offset_text().get_text() for ax in fig.axes] + \
              [ax.xaxis.get_offset_text().get_text() for ax in fig.axes]
    check(not any(offsets), "camera.png has axis exponents: %s" % offsets)


def traction_loop_3d(box):
    t, b, T, N, where = plot.centre_series(box)[1]
    check("largest W" in where and np.ptp(b) > 1e-11, "3D traction loop: %s, slip range %.3g m" % (where, np.ptp(b)))


def periodic_3d(tmp, box):
    """A 3D run with a periodic continuation (its summary's segments given to the short run)."""
    shutil.copytree(box.directory, os.path.join(tmp, "box_periodic"))
    with open(os.path.join(tmp, "box_periodic", "summary.json")) as f:
        summary = json.load(f)
    summary["periodic"] = [{"detected": 1e-5, "suspended": 1.1e-5, "resumed": 1.5e-5, "period_multiple": 1,
                            "periods_continued": 1, "change": 1e-4, "friction_drift": 0, "drift_projected": 0}]
    with open(os.path.join(tmp, "box_periodic", "summary.json"), "w") as f:
        json.dump(summary, f)
    fig = periodic_plot.figure(vt.load(os.path.join(tmp, "box_periodic")))
    curves = [line for line in fig.axes[1].get_lines() if line.get_label().startswith(("hottest", "camera"))]
    check(len(curves) >= 2, "3D periodic.png's temperature panel: %s" % labels(fig.axes[1]))


def modes_3d(tmp):
    run = vt.run_scene(block, {"mesh_h": 0.004, "mesh_h_crack": 0.002, "modes": True, "modes_n": 3},
                       os.path.join(tmp, "modes3d"), program=program)
    fig = plot.plot_modes(run)
    shapes = [ax for ax in fig.axes if ax.get_title().startswith("mode ")]
    check(len(shapes) == 3 and all("front face" in ax.get_title() for ax in shapes)
          and "front face z = 10 mm" in fig._suptitle.get_text(),
          "3D modes.png: %s, %r" % ([ax.get_title() for ax in shapes], fig._suptitle and fig._suptitle.get_text()))


def modes_free(tmp):
    free = dict(coarse, modes=True, modes_n=5, modes_target_frequency=1000, edge_top="free", edge_bottom="free",
                edge_left="free", edge_right="free")
    run = vt.run_scene(paper, free, os.path.join(tmp, "modes_free"), program=program)
    participation = run.table("modes.csv")["participation"]
    check(np.isnan(participation).any(), "a free specimen's rigid-body modes: participation %s" % participation)
    fig = plot.plot_modes(run)
    shapes = [ax for ax in fig.axes if ax.get_title().startswith("mode ")]
    check(len(shapes) == 3 and all("participation nan" not in ax.get_title() for ax in shapes),
          "free specimen's modes.png: %s" % [ax.get_title() for ax in shapes])


def guarded(function, *args):
    """A plot that raises is a failed check (the others still run)."""
    try:
        function(*args)
    except Exception as error:  # noqa: BLE001
        check.fail("%s: %s: %s" % (function.__name__, type(error).__name__, error))


with tempfile.TemporaryDirectory() as tmp:
    guarded(continued_run, tmp)
    guarded(damped_run, tmp)
    box = vt.run_scene(block, {"output_times": 2e-5, "camera": True, "camera_fps": 1e5, "camera_integration": 5e-6,
                               "camera_pixel": 2.5e-4}, os.path.join(tmp, "box"), program=program)
    for function in (crack_maps_3d, camera_3d, traction_loop_3d):
        guarded(function, box)
    guarded(periodic_3d, tmp, box)
    guarded(modes_3d, tmp)
    guarded(modes_free, tmp)
check.finish()
