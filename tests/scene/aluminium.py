"""The default material's constants (the code's aluminium: -material_* and -heat_* defaults)
and the thermoelastic quantities the closed forms need, for the thermoelastic tests."""
import math

E, nu, rho, cp, T0, alpha_L = 70e9, 0.33, 2700.0, 900.0, 293.15, 23e-6
lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
beta = (3 * lam + 2 * G) * alpha_L  # thermal stress per kelvin
c_P = math.sqrt((lam + 2 * G) / rho)  # isothermal P speed
c_P_adiabatic = math.sqrt((lam + 2 * G + beta ** 2 * T0 / (rho * cp)) / rho)
