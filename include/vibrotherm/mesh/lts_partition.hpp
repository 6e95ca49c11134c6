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

namespace vibrotherm::mesh {

/// Sets the weights on the serial dm and asks its partitioner to use them, when
/// -wave_lts on is among the options (else nothing). Call before DMPlexDistribute.
PetscErrorCode SetLtsPartitionWeights(DM dm);

}  // namespace vibrotherm::mesh
