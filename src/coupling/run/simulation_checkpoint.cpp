// Checkpoints of a run: when (checkpoint_schedule.hpp), what (every component,
// the recorder, the wave-stop rule's memory) and how a restart resumes.
#include <cmath>

#include "vibrotherm/coupling/run/run_observers.hpp"
#include "vibrotherm/coupling/continuation/periodic_continuation.hpp"
#include "vibrotherm/coupling/run/simulation.hpp"
#include "vibrotherm/util/stop_signals.hpp"

namespace vibrotherm::coupling {

PetscErrorCode Simulation::CanCheckpoint(bool* can) const {
  PetscFunctionBeginUser;
  *can = false;
  if (!waves_) PetscFunctionReturn(0);  // the heat alone is not checkpointed
  MPI_Comm comm = PetscObjectComm((PetscObject)waves_->solver().space().dm());
  const char* why = nullptr;
  if (waves_->solver().step().implicit()) why = "the implicit wave TS (alpha2)";
  if (!why) *can = true;
  else if (scene_->run.checkpoint_every_s > 0.0 || control_.restart)
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: no checkpoints in this run: %s is not checkpointed; a signal stops "
                                "the run without one\n", why));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::CheckpointIfDue(Recorder& recorder, bool quiet) {
  PetscFunctionBeginUser;
  bool due;
  int signal;
  PetscCall(schedule_.Poll(&due, &signal));
  // Always where the waves stop (the checkpoint says so): a stop while the heat
  // runs alone resumes from there, repeating only that phase.
  const bool stopping_waves = quiet && heat_ && !interrupted_by_;
  MPI_Comm comm = PetscObjectComm((PetscObject)waves_->solver().space().dm());
  if ((due || stopping_waves) && checkpoints_) {
    if (schedule_.warned())
      PetscCall(PetscPrintf(comm, "vibrotherm: SIGCONT at t = %.6g s: a checkpoint, in case a stop follows (Open MPI's "
                                  "mpiexec sends it before SIGTERM)\n", waves_->solver().time()));
    PetscCall(PetscLogEventBegin(schedule_.event(), 0, 0, 0, 0));
    PetscCall(WriteCheckpoint(recorder, quiet));
    PetscCall(PetscLogEventEnd(schedule_.event(), 0, 0, 0, 0));
    schedule_.Written(waves_->solver().time(), dir_);
    if (stopping_waves) heat_alone_from_ = waves_->solver().time();
  }
  if (!signal) PetscFunctionReturn(0);
  interrupted_by_ = signal;
  if (checkpoints_) {
    PetscCall(PetscPrintf(comm, "vibrotherm: %s at t = %.6g s: stopping; -restart %s resumes from its checkpoint at t = "
                                "%.6g s\n", stop_signals::Name(signal), waves_->solver().time(), dir_.c_str(),
                          waves_->solver().time()));
    stop_signals::Stopping();
  }
  else
    PetscCall(PetscPrintf(comm, "vibrotherm: %s at t = %.6g s: stopping without a checkpoint (this scene has none)\n",
                          stop_signals::Name(signal), waves_->solver().time()));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::WriteCheckpoint(Recorder& recorder, bool waves_quiet) const {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)waves_->solver().space().dm());
  store::Checkpoint checkpoint(comm);
  checkpoint.PutText("run/fingerprint", control_.fingerprint);
  // The waves went quiet in the interval just ended: a restart stops them at once.
  if (waves_quiet) checkpoint.PutShared("run/waves_quiet", {1.0});
  PetscCall(waves_->Save(checkpoint, *specimen_));
  if (heat_) PetscCall(heat_->Save(checkpoint, *specimen_));
  PetscCall(recorder.Save(checkpoint));
  if (periodic_) PetscCall(periodic_->Save(checkpoint));
  std::vector<double> quiet = {peak_mechanical_, mechanical_left_};
  for (const Sample& s : recent_) quiet.insert(quiet.end(), {s.t, s.energy, s.dissipated, s.damped, s.radiated});
  checkpoint.PutShared("run/quiet_rule", quiet);
  checkpoint.PutShared("run/response_strain", strain_->state());
  PetscCall(checkpoint.Write(dir_ + "/checkpoint.h5"));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Resume(const store::Checkpoint& checkpoint, RunObservers& observers) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen_->wave);
  PetscCheck(waves_ && checkpoints_, comm, PETSC_ERR_USER_INPUT, "-restart: this scene is not checkpointed");
  PetscCall(waves_->Restore(checkpoint, *specimen_));
  PetscCheck(heat_ != nullptr || !checkpoint.Has("heat/clock"), comm, PETSC_ERR_USER_INPUT,
             "-restart: the checkpoint has a heat solver, this scene has none");
  if (heat_) PetscCall(heat_->Restore(checkpoint, *specimen_));
  PetscCall(observers.Restore(checkpoint));
  if (periodic_) PetscCall(periodic_->Restore(checkpoint));
  std::vector<double> quiet;
  PetscCall(checkpoint.GetShared("run/quiet_rule", &quiet));
  peak_mechanical_ = quiet.at(0);
  mechanical_left_ = quiet.at(1);
  recent_.clear();
  for (std::size_t i = 2; i + 4 < quiet.size(); i += 5)
    recent_.push_back({quiet[i], quiet[i + 1], quiet[i + 2], quiet[i + 3], quiet[i + 4]});
  waves_quiet_at_restart_ = checkpoint.Has("run/waves_quiet");
  if (checkpoint.Has("run/response_strain")) {  // older checkpoints: the peak since the restart
    std::vector<double> strain;
    PetscCall(checkpoint.GetShared("run/response_strain", &strain, 2));
    strain_->Restore(strain);
  }
  PetscCall(PetscPrintf(comm, "Restarted from the checkpoint at t = %.6g s (wave step %" PetscInt_FMT ")\n",
                        waves_->solver().time(), waves_->solver().steps()));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
