// Initial approach a0 along the cracks (PHYSICS.md §3.1): -crack_a0 VALUE
// (uniform), plus either -crack_a0_profile elliptic -crack_a0_max VALUE
// (a0_max √(1 − (2ξ − 1)²)) or -crack_a0_profile file -crack_a0_file F (CSV
// xi,a0, linear in ξ), ξ ∈ [0, 1] along the crack from its end with the smaller x.
#pragma once

#include <petscsys.h>

#include <utility>
#include <vector>

namespace vibrotherm::interface {

struct ApproachProfile {
  double uniform = 0.0, max = 0.0;
  bool elliptic = false;
  std::vector<std::pair<double, double>> table;  ///< (ξ, a0), increasing ξ
  double at(double xi) const;
};
PetscErrorCode ReadApproachProfile(MPI_Comm comm, ApproachProfile* profile);

}  // namespace vibrotherm::interface
