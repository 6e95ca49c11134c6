"""The part of a crack probe's motion that is not a harmonic of the source (issue 41): a
crack-face mode that friction pumps shows there long before it moves the friction."""
import numpy as np


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
