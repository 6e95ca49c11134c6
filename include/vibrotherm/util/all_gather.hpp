// Every rank's share of a list, concatenated in rank order on every rank
// (AllGather) or on rank 0 (GatherToRoot): the code's only variable-count
// gathers (MPI_Allgatherv, MPI_Gatherv).
#pragma once

#include <petscsys.h>

#include <vector>

namespace vibrotherm::util {

/// all = mine of rank 0, then rank 1, ... on every rank. Collective.
PetscErrorCode AllGather(MPI_Comm comm, const std::vector<double>& mine, std::vector<double>* all);
/// all = mine of rank 0, then rank 1, ... on rank 0; empty on the other ranks. Collective.
PetscErrorCode GatherToRoot(MPI_Comm comm, const std::vector<double>& mine, std::vector<double>* all);
PetscErrorCode GatherToRoot(MPI_Comm comm, const std::vector<long long>& mine, std::vector<long long>* all);

}  // namespace vibrotherm::util
