#include "vibrotherm/util/all_gather.hpp"

namespace vibrotherm::util {
namespace {

template <class T>
PetscErrorCode GatherToRootAs(MPI_Comm comm, MPI_Datatype type, const std::vector<T>& mine, std::vector<T>* all) {
  PetscFunctionBeginUser;
  PetscMPIInt size, rank;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  all->resize(rank == 0 ? displs.back() + counts.back() : 0);
  PetscCallMPI(MPI_Gatherv(mine.data(), count, type, all->data(), counts.data(), displs.data(), type, 0, comm));
  PetscFunctionReturn(0);
}

}  // namespace

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

PetscErrorCode GatherToRoot(MPI_Comm comm, const std::vector<double>& mine, std::vector<double>* all) {
  PetscFunctionBeginUser;
  PetscCall(GatherToRootAs(comm, MPI_DOUBLE, mine, all));
  PetscFunctionReturn(0);
}

PetscErrorCode GatherToRoot(MPI_Comm comm, const std::vector<long long>& mine, std::vector<long long>* all) {
  PetscFunctionBeginUser;
  PetscCall(GatherToRootAs(comm, MPI_LONG_LONG, mine, all));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::util
