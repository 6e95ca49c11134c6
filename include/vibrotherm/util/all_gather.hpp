// Every rank's share of a list of doubles, concatenated in rank order on every
// rank: the one MPI_Allgather + MPI_Allgatherv of the code.
#pragma once

#include <petscsys.h>

#include <vector>

namespace vibrotherm::util {

/// all = mine of rank 0, then rank 1, ... on every rank. Collective.
PetscErrorCode AllGather(MPI_Comm comm, const std::vector<double>& mine, std::vector<double>* all);

}  // namespace vibrotherm::util
