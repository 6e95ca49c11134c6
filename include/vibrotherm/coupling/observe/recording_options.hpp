// What a run records and how often (read with the driver's options, ReadDriverOptions).
#pragma once

#include <petscsys.h>

#include <vector>

namespace vibrotherm::coupling {

struct RecordingOptions {
  std::vector<double> output_times;  ///< -output_times t1,t2,... (fields.h5)
  PetscInt energy_every = 10;        ///< -energy_every: steps between energy.csv rows (waves without heat)
  PetscInt probe_every = 1;          ///< -probe_every: steps between probe rows
  std::vector<double> probe_points;  ///< -probe_points x1,y1,x2,y2,...
  std::vector<double> crack_probes;  ///< -crack_probe s1,s2,...: fractions along a crack (0.5: centre)
  PetscInt crack_probe_crack = 1;    ///< -crack_probe_crack: which crack (1-based)
  PetscInt crack_state_every = 20;   ///< -crack_state_every: steps between crack_state.csv records (0: none)
};

}  // namespace vibrotherm::coupling
