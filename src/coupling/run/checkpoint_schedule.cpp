#include "vibrotherm/coupling/run/checkpoint_schedule.hpp"

#include "vibrotherm/util/stop_signals.hpp"

namespace vibrotherm::coupling {

PetscErrorCode CheckpointSchedule::Start(MPI_Comm comm, double every_s) {
  PetscFunctionBeginUser;
  comm_ = comm;
  every_s_ = every_s;
  PetscClassId id;
  PetscCall(PetscClassIdRegister("vibrotherm run", &id));
  PetscCall(PetscLogEventRegister("Checkpoint", id, &event_));
  last_ = MPI_Wtime();
  stop_signals::TakeContinue();  // a SIGCONT during the setup warned of nothing to save
  stop_signals::EnterRun();
  PetscFunctionReturn(0);
}

PetscErrorCode CheckpointSchedule::Poll(bool* write, int* signal) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  // Rank 0's clock decides the periodic ones: all ranks write together.
  int local[3] = {stop_signals::Received(), rank == 0 && every_s_ > 0.0 && MPI_Wtime() - last_ >= every_s_ ? 1 : 0,
                  stop_signals::TakeContinue() ? 1 : 0};
  int global[3];
  PetscCallMPI(MPI_Allreduce(local, global, 3, MPI_INT, MPI_MAX, comm_));
  *signal = global[0];
  *write = global[0] != 0 || global[1] != 0 || global[2] != 0;
  continued_ = global[2] != 0;
  warned_ = continued_ && global[0] == 0 && global[1] == 0;
  PetscFunctionReturn(0);
}

void CheckpointSchedule::Written(double t, const std::string& dir) {
  last_ = MPI_Wtime();
  stop_signals::CheckpointWritten(t, dir, continued_);
}

}  // namespace vibrotherm::coupling
