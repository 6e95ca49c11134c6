#include "vibrotherm/coupling/run/checkpoint_schedule.hpp"

namespace vibrotherm::coupling {
namespace {

constexpr int kSignals[3] = {SIGTERM, SIGINT, SIGUSR1};

// The one process-wide variable of vibrotherm: a signal handler can reach
// nothing else (async-signal-safe code may only set a volatile sig_atomic_t).
volatile std::sig_atomic_t g_signal_received = 0;

extern "C" void RememberSignal(int signal) { g_signal_received = signal; }

}  // namespace

const char* SignalName(int signal) {
  switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGUSR1: return "SIGUSR1";
    default: return "a signal";
  }
}

PetscErrorCode CheckpointSchedule::Start(MPI_Comm comm, double every_s) {
  PetscFunctionBeginUser;
  comm_ = comm;
  every_s_ = every_s;
  PetscClassId id;
  PetscCall(PetscClassIdRegister("vibrotherm run", &id));
  PetscCall(PetscLogEventRegister("Checkpoint", id, &event_));
  last_ = MPI_Wtime();
  g_signal_received = 0;
  struct sigaction action = {};
  action.sa_handler = RememberSignal;
  sigemptyset(&action.sa_mask);
  for (int i = 0; i < 3; ++i)
    PetscCheck(sigaction(kSignals[i], &action, &previous_[i]) == 0, comm, PETSC_ERR_SYS, "cannot catch %s",
               SignalName(kSignals[i]));
  installed_ = true;
  PetscFunctionReturn(0);
}

CheckpointSchedule::~CheckpointSchedule() {
  if (!installed_) return;
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous_[i], nullptr);
}

PetscErrorCode CheckpointSchedule::Poll(bool* write, int* signal) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  // Rank 0's clock decides the periodic ones: all ranks write together.
  int local[2] = {static_cast<int>(g_signal_received),
                  rank == 0 && every_s_ > 0.0 && MPI_Wtime() - last_ >= every_s_ ? 1 : 0};
  int global[2];
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_INT, MPI_MAX, comm_));
  *signal = global[0];
  *write = global[0] != 0 || global[1] != 0;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
