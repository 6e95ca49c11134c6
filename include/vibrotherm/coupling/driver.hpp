// The run loop: which physics run, for how long, and what is recorded.
// Today: elastic waves (issue 4); the crack interface and heat plug in here.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::coupling {

struct DriverOptions {
  double final_time = -1.0;           ///< -final_time [s] (default: the source duration)
  PetscInt energy_every = 10;         ///< -energy_every: steps between energy.csv rows
  PetscInt probe_every = 1;           ///< -probe_every: steps between probe rows
  std::vector<double> probe_points;   ///< -probe_points x1,y1,x2,y2,...
};
PetscErrorCode ReadDriverOptions(MPI_Comm comm, DriverOptions* options);

/// Runs the wave solver on the specimen, writes probes.csv and energy.csv to dir
/// and fills the wave part of the summary.
PetscErrorCode RunWaves(const mesh::Specimen& specimen, const std::string& dir, io::RunSummary* summary);

}  // namespace vibrotherm::coupling
