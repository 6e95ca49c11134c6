#include "vibrotherm/util/all_gather.hpp"

namespace vibrotherm::util {

PetscErrorCode AllGather(MPI_Comm comm, const std::vector<double>& mine, std::vector<double>* all) {
  PetscFunctionBeginUser;
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  all->resize(displs.back() + counts.back());
  PetscCallMPI(MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all->data(), counts.data(), displs.data(), MPI_DOUBLE,
                              comm));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::util
