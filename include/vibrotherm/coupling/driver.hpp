// The run loop: which physics run, for how long, and how they exchange.
//
//   waves (+ crack interface) ──every -couple_dt──► heat: the friction energy
//   each contact cell dissipated in the interval, divided by the interval, is a
//   point source at the cell for the heat TS, which then advances to the wave
//   time (the energy transferred is exactly the energy dissipated).
//   After the source, once the waves are quiet (-wave_quiet_fraction), the wave
//   solver and the interface are destroyed and the heat TS runs alone with
//   adaptive steps to -final_time.
// Only what the scene needs is built: no crack (or -crack_law open) → no
// interface; no possible dissipation → no heat TS (unless -heat on);
// -physics heat → no wave TS (prescribed -heat_crack_power on the cracks).
//
// Setup() reads and checks every option and builds the solvers; only then does
// the application create the output directory, so bad input leaves no output.
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/coupling/driver_options.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

class Recorder;

class Simulation {
 public:
  Simulation();
  ~Simulation();
  /// Reads the options and builds the solvers the scene needs.
  PetscErrorCode Setup(const mesh::Specimen& specimen, io::RunSummary* summary);
  /// Runs to the final time, writing the outputs into dir.
  PetscErrorCode Run(const std::string& dir, io::RunSummary* summary);

 private:
  PetscErrorCode SetupWaves(const mesh::Specimen& specimen, io::RunSummary* summary);
  PetscErrorCode SetupHeat(const mesh::Specimen& specimen, io::RunSummary* summary);
  /// Waves (and heat, coupled) until the final time or until the waves are quiet.
  PetscErrorCode RunWaves(Recorder& recorder, io::RunSummary* summary);
  /// Friction energy of the last interval → heat sources; heat TS to the wave time.
  PetscErrorCode Exchange(double interval);
  /// Whether the waves are over: source ended and, for a whole period, the mechanical energy
  /// left below -wave_quiet_fraction of the energy dissipated (of its peak without dissipation).
  PetscErrorCode WavesQuiet(const io::EnergyRow& energy_now, bool* quiet);
  PetscErrorCode StopWaves(Recorder& recorder, io::RunSummary* summary);
  /// The heat TS alone (adaptive steps) to the final time.
  PetscErrorCode RunHeatAlone(Recorder& recorder, io::RunSummary* summary);

  DriverOptions options_;
  double final_time_ = 0.0;
  wave::ElasticMaterial material_;
  wave::Excitation excitation_;
  wave::WaveOptions wave_options_;
  std::unique_ptr<wave::WaveSolver> wave_;
  std::unique_ptr<interface::CrackInterface> crack_;  ///< only when a crack transmits tractions
  std::unique_ptr<heat::HeatSolver> heat_;           ///< only when something can heat
  std::vector<double> crack_probe_xy_;               ///< crack probe points (heat mesh geometry)
  std::vector<double> cell_weights_;                 ///< tributary length of every contact cell (gathered)
  std::vector<int> cell_counts_, cell_displs_;       ///< Allgatherv layout of the contact cells
  std::vector<double> cell_energy_;                  ///< w·W per contact cell at the last exchange [J/m]
  io::EnergyRow final_wave_energy_;                  ///< wave columns when the waves stopped
  /// Quiet detection: mechanical energy (kinetic + strain + interface) at recent exchanges.
  struct Sample {
    double t, energy;
  };
  std::vector<Sample> recent_;
  double peak_mechanical_ = 0.0, mechanical_left_ = 0.0;
  PetscLogStage wave_stage_ = -1, heat_stage_ = -1;
  double heat_seconds_ = 0.0;
};

}  // namespace vibrotherm::coupling
