// When a run writes a checkpoint and when it stops for a restart: every
// -checkpoint_every_s wall seconds while the waves run, and at once when
// SIGTERM, SIGINT or SIGUSR1 arrives (what batch schedulers send before a time
// limit; Ctrl-C), after which the run stops; under Open MPI's mpiexec also when
// a SIGCONT arrives, the warning mpiexec sends a rank before its SIGTERM
// (util/stop_signals.hpp). The signal may reach the ranks at different moments:
// they agree with one reduction per coupling interval.
#pragma once

#include <petscsys.h>

#include <string>

namespace vibrotherm::coupling {

class CheckpointSchedule {
 public:
  /// The run steps from now on (signals are remembered, not fatal); every_s = 0:
  /// checkpoints only on a signal.
  PetscErrorCode Start(MPI_Comm comm, double every_s);
  /// Between coupling intervals: *write when a checkpoint is due, *signal ≠ 0
  /// when a stop signal arrived on any rank (the run stops). Collective.
  PetscErrorCode Poll(bool* write, int* signal);
  /// Whether the last Poll's checkpoint is due to mpiexec's SIGCONT warning only.
  bool warned() const { return warned_; }
  /// A checkpoint at simulated time t was written into dir: the wall clock starts
  /// again, and a stop at once resumes from it.
  void Written(double t, const std::string& dir);
  /// The log event of writing one ("Checkpoint").
  PetscLogEvent event() const { return event_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  double every_s_ = 0.0, last_ = 0.0;
  bool warned_ = false, continued_ = false;  ///< the last Poll: only / also for a SIGCONT
  PetscLogEvent event_ = 0;
};

}  // namespace vibrotherm::coupling
