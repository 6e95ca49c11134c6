// Partition weights for clustered local time stepping (-wave_lts on): before the
// serial wave mesh is distributed, each cell gets the weight 2^l of its level l
// (the rate it will step at), estimated from its shortest edge (rate-2 classes
// above the shortest edge of the mesh, capped at -wave_lts_max_levels, SeisSol's
// λ = -wave_lts_wiggle); cohesive cells weigh 1. The weights reach the
// partitioner as a local section's cell dofs (PETSc's vertex weights); the
// "metis" partitioner balances each level on its own (metis_partitioner.hpp), so
// every level's products cost the same on every rank. The wave solver assigns
// its own levels from the cells' spectra later: these only balance the work.
#pragma once

#include <petscdmplex.h>

#include <algorithm>
#include <cmath>

namespace vibrotherm::mesh {

/// What the partition needs of the wave's LTS options (read and checked with them).
struct LtsWeighting {
  bool on = false;          ///< -wave_lts
  PetscInt max_levels = 4;  ///< -wave_lts_max_levels
  double wiggle = 1.0;      ///< -wave_lts_wiggle
};

/// The rate-2 class of a cell whose stable step is `ratio` × the finest one's
/// (after SeisSol's λ = wiggle): doublings above the finest, 0 … max_levels − 1.
/// The one rule of both these weights and the wave solver's levels (lts_levels).
inline PetscInt LtsDoublings(double ratio, double wiggle, PetscInt max_levels) {
  return std::min<PetscInt>(max_levels - 1,
                            std::max<PetscInt>(0, static_cast<PetscInt>(std::floor(std::log2(ratio / wiggle)))));
}

/// Sets the weights on the serial dm and asks its partitioner to use them, when
/// lts.on (else nothing). Call before DMPlexDistribute.
PetscErrorCode SetLtsPartitionWeights(DM dm, const LtsWeighting& lts);

}  // namespace vibrotherm::mesh
