"""The crack temperature's saw-tooth of a run against the continuum of its friction
energy at every wave step: a run written with -crack_state_every 1 -probe_every 1
(crack_state.csv: each cell's cumulative friction energy at every wave step;
probes.csv: the crack probes' temperature at every wave step) compared, at every
wave step of given source periods, with line_source.rise_series of the
wave-step record (exact in space and time for that energy, no mesh)."""
import json
import os

import numpy as np

import line_source


def period_errors(out, xi, ends, period, alpha, rho_c, T0=293.15, record=None):
    """For the crack probe at fraction xi of crack 1: per period (end − period, end] a dict with
    the samples, the continuum's mean rise, the run's mean error and its worst sample's error
    (both relative to the continuum's mean rise), and the saw-tooth's range over its mean."""
    summary = json.load(open(os.path.join(out, "summary.json")))
    if record is None:
        record = line_source.wave_step_record(os.path.join(out, "crack_state.csv"), os.path.join(out, "crack_heat.h5"))
    rows = np.genfromtxt(os.path.join(out, "probes.csv"), delimiter=",", names=True, usecols=(0, 1, 8))
    label = "crack 1 at xi = %f" % xi
    probe = [int(k) for k, v in summary["probe_labels"].items() if v == label][0]
    mine = rows[rows["probe"] == probe]
    crack = record.vertices[record.vertices[:, 0] == 0]
    point = (np.interp(xi, crack[:, 1], crack[:, 2]), np.interp(xi, crack[:, 1], crack[:, 3]))
    t = record.t_end
    inside = [(t > end - period + 1e-12) & (t <= end + 1e-12) for end in ends]
    samples = np.nonzero(np.any(inside, axis=0))[0]
    ref = line_source.rise_series(record, point, samples, alpha, rho_c)
    at = np.minimum(np.searchsorted(mine["t"], t[samples] - 1e-11), len(mine) - 1)
    if not np.all(np.abs(mine["t"][at] - t[samples]) < 1e-11):
        raise ValueError("%s: probes.csv lacks rows at the wave steps (-probe_every 1)" % out)
    run = mine["temperature"][at] - T0
    result = []
    for end, mask in zip(ends, inside):
        sel = mask[samples]
        mean = np.mean(ref[sel])
        result.append({"end": end, "samples": int(sel.sum()), "mean": mean,
                       "mean_error": np.mean(run[sel]) / mean - 1,
                       "worst": np.max(np.abs(run[sel] - ref[sel])) / mean,
                       "range": (ref[sel].min() / mean, ref[sel].max() / mean),
                       "t": t[samples][sel], "run": run[sel], "reference": ref[sel]})
    return result


def record_energy(record):
    """The energy [J/m] a (wave-step) record holds: Σ over intervals of ∫ q ds Δt."""
    weights = np.zeros(record.density.shape[1])  # each cell's ∫ φ ds
    for e in record.elements:
        shares = ((5, 0.5), (6, 0.5)) if int(e[4]) == 1 else ((5, 1 / 6), (6, 1 / 6), (7, 4 / 6))
        for k, w in shares:
            if e[k] >= 0:  # a buried tip carries no cell
                weights[int(e[k])] += w * e[3]
    return float(np.sum(record.density @ weights * (record.t_end - record.t_start)))
