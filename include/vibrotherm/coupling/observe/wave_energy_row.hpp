// The wave and interface columns of energy.csv, read from a wave solver.
#pragma once

#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

/// The wave and interface columns of energy.csv of a wave solver now (collective).
PetscErrorCode WaveEnergyRow(const wave::WaveSolver& solver, io::EnergyRow* row);

}  // namespace vibrotherm::coupling
