"""Power laws in the drive amplitude A, fitted on runs at one frequency (numpy only).

A pre-closed rough crack dissipates ∝ A^p: p = 3 in Mindlin's partial slip, falling
towards 1 in gross slip; material damping heat ∝ A^2 (linear waves). The heat equation
is linear, so the defect's own rise on the camera, and its SNR, grow like the friction
power: SNR(A) = SNR_i (A/A_i)^p; its contrast against the damping background like
A^(p−q), q the damping power's exponent. The detection threshold is the smallest A
with SNR >= s* and contrast >= c*.
"""
import math

import numpy as np


class PowerLaw:
    """y = c A^p fitted by least squares in log-log (one point: p given)."""

    def __init__(self, amplitudes, values, default_exponent=2.0):
        pairs = [(a, y) for a, y in zip(amplitudes, values) if a > 0 and y is not None and y > 0 and math.isfinite(y)]
        self.points = len(pairs)
        if not pairs:
            self.exponent, self.log_c = float("nan"), float("nan")
            return
        x = np.log([a for a, _ in pairs])
        y = np.log([v for _, v in pairs])
        if len(pairs) == 1 or np.ptp(x) < 1e-9:
            self.exponent = default_exponent
            self.log_c = float(np.mean(y - default_exponent * x))
        else:
            self.exponent, self.log_c = (float(v) for v in np.polyfit(x, y, 1))

    def __call__(self, amplitude):
        return math.exp(self.log_c + self.exponent * math.log(amplitude))

    def inverse(self, value):
        """The amplitude where the law reaches value."""
        return math.exp((math.log(value) - self.log_c) / self.exponent)


def threshold_amplitude(points, detect_snr, detect_contrast):
    """The predicted detection threshold from runs at one frequency.

    points: dicts with amplitude, friction_power, damping_power, snr, contrast (None: no
    background). Returns (amplitude, law) or (None, law) when no amplitude detects (the
    contrast falls with the drive and is already too low where the SNR suffices).
    """
    friction = PowerLaw([p["amplitude"] for p in points], [p["friction_power"] for p in points], 3.0)
    damping = PowerLaw([p["amplitude"] for p in points], [p["damping_power"] for p in points], 2.0)
    law = {"p": friction.exponent, "q": damping.exponent if damping.points else None, "points": friction.points}
    seen = [p for p in points if p["snr"] and p["snr"] > 0]
    if not seen or not math.isfinite(friction.exponent) or friction.exponent <= 0:
        return None, law
    # Anchored at the run nearest the threshold in SNR: the law's slope, the run's level.
    anchor = min(seen, key=lambda p: abs(math.log(p["snr"] / detect_snr)))
    p = friction.exponent
    needed = anchor["amplitude"] * (detect_snr / anchor["snr"]) ** (1.0 / p)
    contrast = anchor.get("contrast")
    if contrast is None or not math.isfinite(contrast) or detect_contrast <= 0:
        return needed, law
    slope = p - (damping.exponent if damping.points else 2.0)
    at_needed = contrast * (needed / anchor["amplitude"]) ** slope
    if at_needed >= detect_contrast:
        return needed, law
    if slope <= 0:
        return None, law
    return anchor["amplitude"] * (detect_contrast / contrast) ** (1.0 / slope), law
