"""The units of the CSV outputs' columns (README "Outputs and units"; the files carry none).

Energies are per metre of depth in 2D (J/m) and whole in 3D (J): energy_unit(dimension).
A column not listed here (a newer output) has no entry: loaders pass it through without
a unit rather than guess one."""

STATES = ["loss", "slide", "partial", "stick"]  # crack contact states, in the order of fields.h5's contact_state

ENERGY_COLUMNS = ("work_source", "kinetic", "strain", "radiated", "interface_stored", "dissipated", "heat_deposited",
                  "heat_content", "heat_boundary_loss", "integrator_correction", "heat_friction",
                  "heat_thermoelastic", "work_thermal", "damped", "heat_damping")

_POINT = {"t": "s", "x": "m", "y": "m", "z": "m"}
_CRACK = {"a": "m", "b": "m", "b0": "m", "b2": "m", "N": "Pa", "T": "Pa", "T2": "Pa",
          "power": "W/m^2", "W": "J/m^2"}
_COUNTERS = {"probe": "", "crack": "", "mode": "", "multiple": "", "state": ""}  # labels and counts: no unit

_TABLES = {
    "probes.csv": dict(_POINT, ux="m", uy="m", uz="m", vx="m/s", vy="m/s", vz="m/s", temperature="K", **_CRACK),
    "crack_state.csv": dict(_POINT, xi="1", s1="m", s2="m", **_CRACK),
    # relative changes against 1..4 periods back
    "periodic.csv": {"t": "s", "change": "1", "state": "1", "memory": "1", "cells": "1", "energies": "1"},
    "modes.csv": {"frequency": "Hz", "participation": "1", "error": "1"},
}


def energy_unit(dimension):
    return "J" if dimension == 3 else "J/m"


def column_units(name, columns, dimension=2):
    """{column: unit} of the CSV output `name` ("energy.csv", ...) for the columns it has;
    "" for labels and counts (probe, crack, state, ...); columns without a known unit are left out."""
    if name.endswith(".partial"):
        name = name[:-len(".partial")]
    table = dict(_TABLES.get(name, {}))
    if name == "energy.csv":
        table = dict({c: energy_unit(dimension) for c in ENERGY_COLUMNS}, t="s", budget_error="1")
    if name == "source_power.csv":
        power = "W" if dimension == 3 else "W/m"
        table = dict({c: power for c in ("input_power", "friction_power", "damping_power", "radiated_power")},
                     t_start="s", t_end="s", periods="1", frequency="Hz", efficiency="1")  # amplitude: m or Pa
    table.update({c: u for c, u in _COUNTERS.items() if c not in table})
    return {c: table[c] for c in columns if c in table}
