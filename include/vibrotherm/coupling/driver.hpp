// The run loop: which physics run, for how long, and what is recorded.
// Today: elastic waves (issue 4); the crack interface and heat plug in here.
//
// Setup() reads and checks every option and builds the solvers; only then does
// the application create the output directory, so bad input leaves no output.
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

struct DriverOptions {
  double final_time = -1.0;           ///< -final_time [s] (default: the source duration)
  PetscInt energy_every = 10;         ///< -energy_every: steps between energy.csv rows
  PetscInt probe_every = 1;           ///< -probe_every: steps between probe rows
  std::vector<double> probe_points;   ///< -probe_points x1,y1,x2,y2,...
  std::vector<double> crack_probes;   ///< -crack_probe s1,s2,...: fractions along a crack (0.5: centre)
  PetscInt crack_probe_crack = 1;     ///< -crack_probe_crack: which crack (1-based)
  PetscInt crack_state_every = 20;    ///< -crack_state_every: steps between crack_state.csv records (0: none)
};
PetscErrorCode ReadDriverOptions(MPI_Comm comm, DriverOptions* options);

class Simulation {
 public:
  /// Reads the options and builds the wave solver on the specimen's wave mesh.
  PetscErrorCode Setup(const mesh::Specimen& specimen, io::RunSummary* summary);
  /// Runs to the final time, writing probes.csv and energy.csv into dir.
  PetscErrorCode Run(const std::string& dir, io::RunSummary* summary);

 private:
  DriverOptions options_;
  double final_time_ = 0.0;
  wave::ElasticMaterial material_;
  wave::Excitation excitation_;
  wave::WaveOptions wave_options_;
  std::unique_ptr<wave::WaveSolver> wave_;
  std::unique_ptr<interface::CrackInterface> crack_;  ///< only when a crack transmits tractions
  PetscLogStage steps_stage_ = -1;
};

}  // namespace vibrotherm::coupling
