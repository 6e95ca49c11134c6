// Run control: which physics run, how they are coupled, what is recorded.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/coupling/observe/recording_options.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::coupling {

enum class PhysicsChoice { All, Wave, Heat };  ///< -physics all|wave|heat
enum class HeatChoice { Auto, On, Off };       ///< -heat auto|on|off
/// -thermoelastic off|one_way|two_way: one_way heats from tr(ε̇) of the waves; two_way also
/// puts the thermal stress −βθI back into the wave equation (thermoelastic damping).
enum class ThermoelasticChoice { Off, OneWay, TwoWay };

/// The run's options; the recording ones are the base the recorder reads.
struct DriverOptions : RecordingOptions {
  int dimension = 2;                  ///< 3 for a 3D box (-specimen_depth > 0; set before the options are read)
  PhysicsChoice physics = PhysicsChoice::All;
  HeatChoice heat = HeatChoice::Auto;  ///< auto: only when the crack can dissipate
  ThermoelasticChoice thermoelastic = ThermoelasticChoice::Off;  ///< -thermoelastic off|one_way|two_way
  double heat_crack_power = 0.0;      ///< -heat_crack_power [W/m²] (-physics heat)
  double final_time = -1.0;           ///< -final_time [s] (default: the source duration)
  double couple_dt = -1.0;            ///< -couple_dt [s] (default: 1/8 of the source period)
  PetscInt heat_substeps = 3;         ///< -heat_substeps: heat steps per coupling interval (each with its own friction energy)
  bool near_field = true;             ///< -heat_near_field: probes near a crack add the recent friction heat exactly
  PetscInt near_field_steps = 8;      ///< -heat_near_field_steps: the window K of that correction [heat steps]
  double quiet_fraction = 1e-2;       ///< -wave_quiet_fraction
  double max_steps = 2e8;             ///< -max_steps: a run whose wave steps would exceed it is refused at setup
  double checkpoint_every_s = 600.0;  ///< -checkpoint_every_s: wall seconds between checkpoints (0: only on signals)
};
/// The run-control and recording options, declared (option_spec.hpp).
const std::vector<OptionSpec<DriverOptions>>& DriverOptionSpecs();
/// Reads and checks them. Collective.
PetscErrorCode ReadDriverOptions(MPI_Comm comm, DriverOptions* options, OptionValues* values = nullptr);

/// The heat exchange interval: -couple_dt, or 1/8 of the source period.
double CouplingInterval(const DriverOptions& options, double source_frequency);

}  // namespace vibrotherm::coupling
