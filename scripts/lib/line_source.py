"""Temperature of the friction heat a run exchanged (crack_heat.h5), or of the
friction heat at every wave step (crack_state.csv written with -crack_state_every 1:
wave_step_record), computed without any mesh: the line density q(ξ, t) along
each crack (piecewise constant in time over the intervals, Lagrange in ξ over
the wave mesh's crack elements) convolved with the heat kernel of the infinite
plate,

    T(x, t) − T0 = 1/(ρ c_p) ∫∫ q(s, τ) G(x − y(s), t − τ) ds dτ,
    G(r, τ) = exp(−r²/(4 α τ)) / (4 π α τ),

optionally with the images that hold the edges of a W × H rectangle at T0
(method of images). The space integral over each straight element is closed
form (Gaussian moments of a quadratic); the time integral is Gauss–Legendre in
√τ per interval (the kernel on the line behaves as τ^(−1/2)). rise_series gives
the rise at many interval ends at once: where the intervals are equal, the
contribution of each cell is a convolution with the cell's kernel per lag.
"""
import h5py
import numpy as np
from scipy.special import erf

_GAUSS_X, _GAUSS_W = np.polynomial.legendre.leggauss(8)


class CrackHeat:
    """crack_heat.h5: intervals, densities and the wave mesh's crack elements."""

    def __init__(self, path):
        with h5py.File(path, "r") as f:
            self.t_end = f["time"][:, 0]
            self.density = f["density"][:]
            self.elements = f["elements"][:]
            self.vertices = f["vertices"][:]
        self.t_start = np.concatenate([[0.0], self.t_end[:-1]])

    def element_geometry(self):
        """End points (E × 2 × 2) of every element, from the crack vertices."""
        ends = np.zeros((len(self.elements), 2, 2))
        for i, e in enumerate(self.elements):
            v = self.vertices[self.vertices[:, 0] == e[0]]
            for k, xi in enumerate(e[1:3]):
                ends[i, k] = [np.interp(xi, v[:, 1], v[:, 2]), np.interp(xi, v[:, 1], v[:, 3])]
        return ends

    def polynomial_coefficients(self):
        """q(σ) = c0 + c1 σ + c2 σ² on each element (σ ∈ [0, ℓ] from its ξ0 end), per interval: K × E × 3."""
        K, E = len(self.t_end), len(self.elements)
        coef = np.zeros((K, E, 3))
        for i, e in enumerate(self.elements):
            ell, degree = e[3], int(e[4])
            node = [int(n) for n in e[5:8]]
            q = [self.density[:, n] if n >= 0 else np.zeros(K) for n in node]
            if degree == 1:  # q0 (1 − t) + q1 t, t = σ/ℓ
                coef[:, i, 0], coef[:, i, 1] = q[0], (q[1] - q[0]) / ell
            else:  # q0 (1−t)(1−2t) + q1 t(2t−1) + qm 4t(1−t)
                coef[:, i, 0] = q[0]
                coef[:, i, 1] = (-3 * q[0] - q[1] + 4 * q[2]) / ell
                coef[:, i, 2] = (2 * q[0] + 2 * q[1] - 4 * q[2]) / ell**2
        return coef


def _segment_integral(coef, sigma_x, d2, ell, a):
    """∫_0^ℓ (c0 + c1 σ + c2 σ²) exp(−((σ − σx)² + d²)/a) dσ, broadcast over a (..., Q) and elements."""
    sa = np.sqrt(a)
    lo, hi = -sigma_x, ell - sigma_x  # u = σ − σx
    e_lo, e_hi = np.exp(-lo**2 / a), np.exp(-hi**2 / a)
    m0 = 0.5 * np.sqrt(np.pi) * sa * (erf(hi / sa) - erf(lo / sa))
    m1 = -0.5 * a * (e_hi - e_lo)
    m2 = 0.5 * a * (m0 - (hi * e_hi - lo * e_lo))
    c0, c1, c2 = coef[..., 0], coef[..., 1], coef[..., 2]
    # q(u + σx) expanded in powers of u
    b0 = c0 + c1 * sigma_x + c2 * sigma_x**2
    b1 = c1 + 2 * c2 * sigma_x
    return np.exp(-d2 / a) * (b0 * m0 + b1 * m1 + c2 * m2)


def _images(width, height):
    """(sx, ox, sy, oy, sign): x' = sx x + ox, y' = sy y + oy, for the 36 nearest images (or only identity)."""
    if width is None:
        return [(1, 0.0, 1, 0.0, 1.0)]
    out = []
    for m in (-1, 0, 1):
        for n in (-1, 0, 1):
            for sx in (1, -1):
                for sy in (1, -1):
                    out.append((sx, 2 * m * width, sy, 2 * n * height, float(sx * sy)))
    return out


def temperature_rise(record, point, t, alpha, rho_c, width=None, height=None):
    """T − T0 at point (x, y) and time t (after the last interval ending before t; partial interval included)."""
    ends = record.element_geometry()
    coef = record.polynomial_coefficients()
    keep = record.t_start < t
    t0, t1, coef = record.t_start[keep], np.minimum(record.t_end[keep], t), coef[keep]
    # √τ nodes per interval: τ ∈ [t − t1, t − t0]
    r0, r1 = np.sqrt(t - t1), np.sqrt(t - t0)
    s = 0.5 * (r0 + r1)[:, None] + 0.5 * (r1 - r0)[:, None] * _GAUSS_X[None, :]
    w = 0.5 * (r1 - r0)[:, None] * _GAUSS_W[None, :] * 2 * s  # dτ = 2 s ds
    tau = s**2
    a = 4 * alpha * tau  # K × Q
    total = 0.0
    for sx, ox, sy, oy, sign in _images(width, height):
        p0 = np.stack([sx * ends[:, 0, 0] + ox, sy * ends[:, 0, 1] + oy], axis=1)
        p1 = np.stack([sx * ends[:, 1, 0] + ox, sy * ends[:, 1, 1] + oy], axis=1)
        ell = np.linalg.norm(p1 - p0, axis=1)
        tangent = (p1 - p0) / ell[:, None]
        rel = np.asarray(point)[None, :] - p0
        sigma_x = rel @ np.array([1.0, 0.0]) * tangent[:, 0] + rel @ np.array([0.0, 1.0]) * tangent[:, 1]
        d2 = np.maximum(np.sum(rel**2, axis=1) - sigma_x**2, 0.0)
        space = _segment_integral(coef[:, None, :, :], sigma_x[None, None, :], d2[None, None, :],
                                  ell[None, None, :], a[:, :, None])  # K × Q × E
        kernel = space.sum(axis=2) / (4 * np.pi * alpha * tau)
        total += sign * np.sum(w * kernel)
    return total / rho_c


def wave_step_record(crack_state_csv, crack_heat_h5):
    """The friction heat at every wave step: the cumulative W per cell of crack_state.csv
    (-crack_state_every 1) differenced into a density per step, on crack_heat.h5's elements
    (cells matched by ξ)."""
    record = CrackHeat(crack_heat_h5)
    with open(crack_state_csv) as f:
        header = f.readline().strip().split(",")
    columns = tuple(header.index(c) for c in ("t", "crack", "xi", "W"))
    rows = np.loadtxt(crack_state_csv, delimiter=",", skiprows=1, usecols=columns, ndmin=2)
    times = np.unique(rows[:, 0])
    cell_at = {}
    for e in record.elements:
        crack = int(e[0]) + 1  # crack_state.csv numbers cracks from 1
        cell_at[(crack, round(e[1], 6))], cell_at[(crack, round(e[2], 6))] = int(e[5]), int(e[6])
        if e[4] == 2:
            cell_at[(crack, round(0.5 * (e[1] + e[2]), 6))] = int(e[7])
    W = np.zeros((len(times) + 1, record.density.shape[1]))
    cells = [cell_at[(int(c), round(x, 6))] for c, x in rows[:, 1:3]]
    W[np.searchsorted(times, rows[:, 0]) + 1, cells] = rows[:, 3]
    t = np.concatenate([[0.0], times])
    record.t_start, record.t_end = t[:-1], t[1:]
    record.density = np.diff(W, axis=0) / np.diff(t)[:, None]
    return record


def _basis_coefficients(record):
    """φ(σ) = c0 + c1 σ + c2 σ² of each element's nodes (ends, middle): E × 3 × 3."""
    coef = np.zeros((len(record.elements), 3, 3))
    for i, e in enumerate(record.elements):
        ell = e[3]
        if int(e[4]) == 1:
            coef[i, 0], coef[i, 1] = [1, -1 / ell, 0], [0, 1 / ell, 0]
        else:
            coef[i, 0], coef[i, 1] = [1, -3 / ell, 2 / ell**2], [0, -1 / ell, 2 / ell**2]
            coef[i, 2] = [0, 4 / ell, -4 / ell**2]
    return coef


def cell_kernels(record, point, age_lo, age_hi, alpha, rho_c, width=None, height=None, gauss=8):
    """(N × C): the rise at point per unit density [W/m²] held at cell c over the ages [lo, hi]."""
    ends = record.element_geometry()
    basis, nodes = _basis_coefficients(record), record.elements[:, 5:8].astype(int)
    gx, gw = np.polynomial.legendre.leggauss(gauss)
    out = np.zeros((len(age_lo), record.density.shape[1]))
    for sx, ox, sy, oy, sign in _images(width, height):
        p0 = np.stack([sx * ends[:, 0, 0] + ox, sy * ends[:, 0, 1] + oy], axis=1)
        p1 = np.stack([sx * ends[:, 1, 0] + ox, sy * ends[:, 1, 1] + oy], axis=1)
        ell = np.linalg.norm(p1 - p0, axis=1)
        rel = np.asarray(point)[None, :] - p0
        sigma_x = np.sum(rel * (p1 - p0) / ell[:, None], axis=1)
        d2 = np.maximum(np.sum(rel**2, axis=1) - sigma_x**2, 0.0)
        nearest = d2 + np.maximum(np.maximum(-sigma_x, sigma_x - ell), 0.0)**2
        if nearest.min() > 200 * alpha * np.max(age_hi):  # exp(−50): this image's heat has not arrived
            continue
        for lo in range(0, len(age_lo), 2000):
            r0, r1 = np.sqrt(age_lo[lo:lo + 2000]), np.sqrt(age_hi[lo:lo + 2000])
            s = 0.5 * (r0 + r1)[:, None] + 0.5 * (r1 - r0)[:, None] * gx[None, :]
            w = 0.5 * (r1 - r0)[:, None] * gw[None, :] * 2 * s  # dτ = 2 s ds
            a = 4 * alpha * s**2
            for k in range(3):
                space = _segment_integral(basis[None, None, :, k, :], sigma_x[None, None, :], d2[None, None, :],
                                          ell[None, None, :], a[:, :, None])  # N × Q × E
                per_element = sign * np.sum((w / (np.pi * a))[:, :, None] * space, axis=1) / rho_c
                for e in np.nonzero(nodes[:, k] >= 0)[0]:
                    out[lo:lo + 2000, nodes[e, k]] += per_element[:, e]
    return out


def rise_series(record, point, samples, alpha, rho_c, width=None, height=None):
    """T − T0 at point at the ends of the intervals `samples` (indices into record.t_end, all within
    the run of equal intervals that ends with the last sample). Equal intervals: a convolution per cell; the
    intervals before them (older than the samples by far more than their length) are summed
    directly at a tenth of the samples and interpolated (their heat varies slowly)."""
    from scipy.interpolate import CubicSpline
    from scipy.signal import fftconvolve
    samples = np.asarray(samples)
    dt = (record.t_end - record.t_start)[:samples.max() + 1]  # later intervals do not heat the samples
    step = np.median(dt[-min(len(dt), 1000):])
    first = len(dt)
    while first > 0 and abs(dt[first - 1] / step - 1) < 1e-3:
        first -= 1
    if samples.min() < first:
        raise ValueError("rise_series: samples before the last run of equal intervals")
    lags = np.arange(len(dt) - first)
    kernel = cell_kernels(record, point, lags * step, (lags + 1) * step, alpha, rho_c, width, height)
    q = record.density[first:len(dt)] * (dt[first:, None] / step)  # each interval's energy over the common step
    rise = np.zeros(len(dt))
    for c in range(q.shape[1]):
        rise[first:] += fftconvolve(q[:, c], kernel[:, c])[:len(q)]
    if first > 0:
        every = samples[::10] if samples[-1] in samples[::10] else np.append(samples[::10], samples[-1])
        old = [np.sum(cell_kernels(record, point, record.t_end[m] - record.t_end[:first],
                                   record.t_end[m] - record.t_start[:first], alpha, rho_c, width, height, gauss=2) *
                      record.density[:first]) for m in every]
        rise[samples] += CubicSpline(record.t_end[every], old)(record.t_end[samples]) if len(every) > 3 else \
            np.interp(record.t_end[samples], record.t_end[every], old)
    return rise[samples]
