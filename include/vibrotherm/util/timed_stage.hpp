// A PETSc log stage that also measures its wall time for summary.json:
//   TimedStage stage; PetscCall(stage.Begin("Heat setup")); ...;
//   PetscCall(stage.End(&summary->stages["heat_setup"]));
#pragma once

#include <petscsys.h>

namespace vibrotherm {

class TimedStage {
 public:
  /// Registers the stage (PETSc returns the same stage for the same name) and pushes it.
  PetscErrorCode Begin(const char* name) {
    PetscFunctionBeginUser;
    PetscLogStage stage;
    PetscCall(PetscLogStageRegister(name, &stage));
    start_ = MPI_Wtime();
    PetscCall(PetscLogStagePush(stage));
    PetscFunctionReturn(0);
  }
  /// Pops the stage; *seconds = its wall time.
  PetscErrorCode End(double* seconds) {
    PetscFunctionBeginUser;
    PetscCall(PetscLogStagePop());
    *seconds = MPI_Wtime() - start_;
    PetscFunctionReturn(0);
  }

 private:
  double start_ = 0.0;
};

}  // namespace vibrotherm
