"""How a crack's motion changes over a long excitation (issue 41): its friction per source
period and that friction's trend, and the part of a crack probe's motion that is not a
harmonic of the source (a crack-face mode that friction pumps shows there long before it
moves the friction)."""
import os

import numpy as np

from run_data import read_csv


def friction_per_period(out, periods, period):
    """F_k, k = 0..periods-1: the crack's friction energy per source period [J/m], from the run's
    energy.csv (the dissipated energy interpolated at the period ends, differenced)."""
    e = read_csv(os.path.join(out, "energy.csv"))
    return np.diff(np.interp(period * np.arange(periods + 1), e["t"], e["dissipated"]))


def trend(F, k0, k1):
    """The least-squares line through F_k over periods k0..k1-1: its change over 100 periods,
    relative to the mean of F there."""
    return 100 * np.polyfit(np.arange(k0, k1), F[k0:k1], 1)[0] / F[k0:k1].mean()


def non_harmonic(t, a, period, k0, k1, split=1e6):
    """Over source periods k0..k1 of samples a(t) (uniform once the wave step is constant;
    a crack probe every -probe_every steps): the RMS of what is not a harmonic of 1/period
    below and above `split` Hz, and the frequency of its largest line [Hz]. Hann window;
    every line within 2.5 bins of a harmonic removed."""
    inside = (t >= k0 * period) & (t < k1 * period)
    t, a = t[inside], a[inside]
    A = np.abs(np.fft.rfft((a - a.mean()) * np.hanning(len(a)))) * 4 / len(a)
    f = np.fft.rfftfreq(len(a), np.median(np.diff(t)))
    A[np.abs(f - np.round(f * period) / period) < 2.5 / ((k1 - k0) * period)] = 0.0
    return np.sqrt(0.5 * np.sum(A[f < split] ** 2)), np.sqrt(0.5 * np.sum(A[f >= split] ** 2)), f[np.argmax(A)]
