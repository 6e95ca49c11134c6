// Run serial work (gmsh, file parsing) on rank 0 and make its failure collective.
#pragma once

#include <petscsys.h>

#include <exception>
#include <string>

namespace vibrotherm {

/// Calls task() on rank 0 of comm; if it throws, every rank returns a
/// PETSC_ERR_USER_INPUT error with the exception's message.
template <class Task>
PetscErrorCode RunOnRoot(MPI_Comm comm, Task&& task) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string error;
  if (rank == 0) {
    try {
      task();
    } catch (const std::exception& e) {
      error = e.what();
      if (error.empty()) error = "unknown error";
    } catch (const std::string& e) {  // gmsh throws strings
      error = "gmsh: " + e;
    } catch (...) {
      error = "unknown error";
    }
  }
  int length = static_cast<int>(error.size());
  PetscCallMPI(MPI_Bcast(&length, 1, MPI_INT, 0, comm));
  error.resize(length);
  PetscCallMPI(MPI_Bcast(error.data(), length, MPI_CHAR, 0, comm));
  PetscCheck(length == 0, comm, PETSC_ERR_USER_INPUT, "%s", error.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm
