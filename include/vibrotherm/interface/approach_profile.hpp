// Initial approach a0 along the cracks (PHYSICS.md §3.1): -crack_a0 VALUE
// (uniform), plus either -crack_a0_profile elliptic -crack_a0_max VALUE
// (a0_max √(1 − (2ξ − 1)²)) or -crack_a0_profile file -crack_a0_file F (CSV
// xi,a0, linear in ξ), ξ ∈ [0, 1] along the crack from its end with the smaller x.
#pragma once

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::interface {

enum class ApproachShape { Uniform, Elliptic, File };  ///< -crack_a0_profile

struct ApproachProfile {
  double uniform = 0.0;  ///< -crack_a0 [m]
  ApproachShape shape = ApproachShape::Uniform;
  double max = 0.0;      ///< -crack_a0_max [m] (Elliptic)
  std::string file;      ///< -crack_a0_file (File)
  std::vector<std::pair<double, double>> table;  ///< (ξ, a0), increasing ξ, from the file
  double at(double xi) const;
};
/// -crack_a0, -crack_a0_profile, -crack_a0_max, -crack_a0_file, declared (option_spec.hpp).
const std::vector<OptionSpec<ApproachProfile>>& ApproachProfileOptionSpecs();
/// Reads them and the file's table. Collective.
PetscErrorCode ReadApproachProfile(MPI_Comm comm, ApproachProfile* profile, OptionValues* values = nullptr);

}  // namespace vibrotherm::interface
