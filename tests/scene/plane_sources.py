"""Carslaw & Jaeger's continuous plane sources in an infinite aluminium body: the temperature
rise on the axis of a crack heated with Q [W/m^2] from t = 0, at distance z from its plane
(shared by test_heat_crack_shapes_3d.py and test_surface_cracks_3d.py)."""
import math

K, RHO_C = 237.0, 2700 * 900.0
ALPHA = K / RHO_C


def ierfc(x):
    return math.exp(-x * x) / math.sqrt(math.pi) - x * math.erfc(x)


def disc(Q, z, t, a):
    """A disc of radius a: θ = Q √(αt)/k [ierfc(z/2√(αt)) − ierfc(√(z² + a²)/2√(αt))]."""
    r = math.sqrt(ALPHA * t)
    return Q * r / K * (ierfc(z / (2 * r)) - ierfc(math.sqrt(z * z + a * a) / (2 * r)))


def rectangle(Q, z, t, length, width, n=4000):
    """An L x W rectangle: θ = Q/(ρc) ∫0^t erf(L/4√(ατ)) erf(W/4√(ατ)) e^{−z²/4ατ} / √(4πατ) dτ;
    s = u² removes the 1/√τ singularity; Simpson in u."""
    b = math.sqrt(t)
    h = b / n

    def g(u):
        if u == 0:
            return 0.0 if z > 0 else 1.0 / math.sqrt(4 * math.pi * ALPHA)
        s = 4 * math.sqrt(ALPHA) * u
        return (math.erf(length / s) * math.erf(width / s) * math.exp(-z * z / (4 * ALPHA * u * u)) /
                math.sqrt(4 * math.pi * ALPHA))

    total = g(0) + g(b) + sum((4 if i % 2 else 2) * g(i * h) for i in range(1, n))
    return Q / RHO_C * 2 * total * h / 3
