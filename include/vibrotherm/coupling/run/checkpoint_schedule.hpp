// When a run writes a checkpoint and when it stops for a restart: every
// -checkpoint_every_s wall seconds while the waves run, and at once when
// SIGTERM, SIGINT or SIGUSR1 arrives (what batch schedulers send before a time
// limit; Ctrl-C), after which the run stops. The signal may reach the ranks at
// different moments: they agree with one reduction per coupling interval.
#pragma once

#include <petscsys.h>

#include <csignal>

namespace vibrotherm::coupling {

class CheckpointSchedule {
 public:
  CheckpointSchedule() = default;
  CheckpointSchedule(const CheckpointSchedule&) = delete;
  CheckpointSchedule& operator=(const CheckpointSchedule&) = delete;
  ~CheckpointSchedule();  ///< puts the earlier signal handlers back

  /// Catches the signals from now on; every_s = 0: checkpoints only on a signal.
  PetscErrorCode Start(MPI_Comm comm, double every_s);
  /// Between coupling intervals: *write when a checkpoint is due, *signal ≠ 0
  /// when one arrived on any rank (the run stops). Collective.
  PetscErrorCode Poll(bool* write, int* signal);
  /// A checkpoint was written: the wall clock starts again.
  void Written() { last_ = MPI_Wtime(); }
  /// The log event of writing one ("Checkpoint").
  PetscLogEvent event() const { return event_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  double every_s_ = 0.0, last_ = 0.0;
  bool installed_ = false;
  PetscLogEvent event_ = 0;
  struct sigaction previous_[3];
};

/// "SIGTERM", "SIGINT", "SIGUSR1" (or "signal N").
const char* SignalName(int signal);

}  // namespace vibrotherm::coupling
