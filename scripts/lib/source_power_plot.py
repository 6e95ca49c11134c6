"""source_power.png (scripts/plot): what the source put in and where it went, per source period.

A sweep (-source_sweep) is read the way Rahammer et al. read local defect resonances off a
frequency sweep: the crack's friction power against the instantaneous frequency, its peaks
at the defect's resonances. Any other source: the powers against time (build-up, steady
state, ring-down after the switch-off), and the thermosonic efficiency (friction / input)."""
import numpy as np

from vibrotherm import MissingOutput as Skip


def figure(run):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if not run.has("source_power.csv"):
        raise Skip("no source_power.csv (a run without a source, or from before it existed)")
    table = run.source_power()
    if len(table) == 0:
        raise Skip("source_power.csv has no whole source period")
    unit = table.attrs["units"].get("input_power", "W/m")
    sweep = table["frequency"].nunique() > 1  # a sweep's rows carry its instantaneous frequency
    middle = 0.5 * (table["t_start"] + table["t_end"]).to_numpy()
    scale, t_unit = (1e6, "µs") if middle.max() < 1e-4 else (1e3, "ms")
    x = table["frequency"].to_numpy() / 1e3 if sweep else scale * middle
    label = "instantaneous drive frequency [kHz]" if sweep else "t [%s] (the middle of each source period)" % t_unit
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    for column, name, style in (("input_power", "put in by the source", "C0-"),
                                ("friction_power", "the crack's friction (its heat)", "C3-"),
                                ("damping_power", "material damping", "C2--"),
                                ("radiated_power", "radiated through absorbing edges", "C7:")):
        values = table[column].to_numpy()
        if np.any(values != 0):
            top.plot(x, values, style, lw=1, label=name)
    positive = table[["input_power", "friction_power"]].to_numpy()
    positive = positive[positive > 0]
    if positive.size and positive.max() > 100 * positive.min():  # the friction far below the input: both seen
        top.set_yscale("log")
    top.set_ylabel("mean power per period [%s]" % unit)
    top.legend(fontsize=8)
    top.grid(alpha=0.3)
    if sweep:  # the heating's peak: the crack's friction, or the damping where nothing rubs (an open crack)
        heating = "friction_power" if table["friction_power"].max() > 0 else "damping_power"
        values = table[heating].to_numpy()
        k = int(np.argmax(values))
        top.axvline(x[k], color="C3", lw=0.8, alpha=0.6)
        top.annotate("%s peaks at %.4g kHz" % ("friction" if heating == "friction_power" else "damping", x[k]),
                     (x[k], values[k]), textcoords="offset points", xytext=(-6, 8), ha="right", fontsize=8, color="C3")
        # A sweep's input swings through negative periods: the friction's share of the losses instead.
        losses = (table["friction_power"] + table["damping_power"] + table["radiated_power"]).to_numpy()
        share = np.divide(table["friction_power"].to_numpy(), losses, out=np.full(len(losses), np.nan),
                          where=losses > 0)
        bottom.plot(x, 100 * share, "k-", lw=1)
        bottom.set_ylabel("friction's share of the losses [%]")
    else:
        bottom.plot(x, 100 * table["efficiency"].to_numpy(), "k-", lw=1)
        bottom.set_ylabel("thermosonic efficiency [%]\n(friction / input)")
    bottom.set_xlabel(label)
    bottom.grid(alpha=0.3)
    f = table["frequency"].to_numpy()
    what = "a sweep %.6g to %.6g Hz" % (f[0], f[-1]) if sweep else "%.6g Hz" % f[0]
    fig.suptitle("Source power per period (%s)%s" % (what, "" if sweep else
                                                       "; no efficiency where nothing is put in (ring-down)"),
                 fontsize=10)
    fig.tight_layout()
    return fig
