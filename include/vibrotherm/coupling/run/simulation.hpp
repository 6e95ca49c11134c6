// A simulation run: which physics run, in what order, and how they exchange.
// The order of a run lives here and nowhere else:
//
//   Setup  scene (every option, read once) → waves (+ crack contact, when a crack
//          transmits tractions) → heat (when something can heat: a crack law
//          that dissipates, -heat on, or -physics heat)
//   Run    the observers registered once (run_observers.hpp: probes, energy, crack
//          state, fields, field peak, camera, progress; checkpoints), then the
//          phases in one loop (RunPhases):
//          coupled    per heat step (-couple_dt / -heat_substeps) the waves
//                     advance a whole number of steps, then the heat takes one step
//                     with the energy its sources deposited in it (friction_heat.hpp);
//                     per coupling interval: the records, the periodic detector, the
//                     quiet test, a checkpoint when due;
//          continued  a periodic state found: the continuation (coupling/continuation)
//                     feeds the heat the recorded period, the waves suspended, then
//                     resumes them (back to coupled);
//          stop waves after the source, once the waves are quiet (-wave_quiet_fraction)
//                     or at -final_time: their solver and the interface are freed;
//          heat alone (adaptive) to -final_time, landing on output times and on the
//                     camera's frame windows.
//          Each phase tells the observers of its steps; none writes a record itself.
// Checkpoints (simulation_checkpoint.cpp): between coupling intervals, every
// -checkpoint_every_s and on SIGTERM/SIGINT/SIGUSR1 (the run then stops); a
// restart restores every component and the recorder and goes on as if never
// stopped. One more checkpoint is written where the waves stop: the heat
// running alone is not checkpointed itself, so a signal there stops the run and
// a restart resumes where the waves stopped, repeating that phase (seconds).
// Only what the scene needs is built: no crack (or an open crack law) → no
// interface; nothing that can dissipate → no heat (unless -heat on);
// -physics heat → no waves (prescribed -heat_crack_power on the cracks).
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/coupling/run/checkpoint_schedule.hpp"
#include "vibrotherm/coupling/run/heat_component.hpp"
#include "vibrotherm/coupling/run/model_validity.hpp"
#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/coupling/run/wave_component.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::coupling {

class Recorder;
class RunObservers;
class HeatCamera;
class PeriodicContinuation;

/// How a run starts and what its checkpoints carry.
struct RunControl {
  const store::Checkpoint* restart = nullptr;  ///< continue from this checkpoint (read by the caller)
  std::string fingerprint;                  ///< the options a restart must share with the run it continues
};

class Simulation {
 public:
  Simulation();
  ~Simulation();
  /// Builds what the scene needs; all input is checked here, before any output.
  /// restarting: the state will come from a checkpoint (the harmonic start is not solved).
  PetscErrorCode Setup(const mesh::Specimen& specimen, const Scene& scene, io::RunSummary* summary,
                       bool restarting = false);
  /// Runs to the final time (or until a signal stops it), writing the outputs into dir.
  PetscErrorCode Run(const std::string& dir, io::RunSummary* summary, const RunControl& control);
  /// The signal that stopped the run (0: it ran to its end).
  int interrupted_by() const { return interrupted_by_; }

 private:
  /// The IR camera when the scene asks for one (-camera) and heat runs.
  PetscErrorCode SetupCamera(const Scene& scene);
  /// The run's phases in one loop: coupled intervals (waves and heat), continued (the periodic
  /// continuation's heat, the waves suspended), the waves stopped, then the heat alone.
  enum class RunPhase { kCoupled, kContinued, kStopWaves, kHeatAlone, kDone };
  PetscErrorCode RunPhases(RunObservers& observers, io::RunSummary* summary);
  /// The waves' phase begins (or goes on after a restart): their step, the progress line, the stage.
  PetscErrorCode StartWaves(RunObservers& observers);
  /// One coupling interval; then a continuation, the quiet test or the waves' end decide what is next.
  PetscErrorCode CoupledInterval(RunObservers& observers, RunPhase* next);
  /// The quiet test and a checkpoint when due, after an interval (or the continuation it started).
  PetscErrorCode AfterCoupledInterval(RunObservers& observers, RunPhase* next);
  /// The periodic continuation's phase: its heat, then the waves resumed.
  PetscErrorCode Continued(RunObservers& observers, RunPhase* next);
  /// The waves are quiet or at the final time: their records closed, their solvers freed.
  PetscErrorCode EndWaves(RunObservers& observers, io::RunSummary* summary, RunPhase* next);
  /// One coupling interval: waves and the heat's substeps of about heat_dt each
  /// (whole wave steps), then the records of the interval.
  PetscErrorCode Interval(RunObservers& observers, double heat_dt, io::EnergyRow* row);
  PetscInt WaveStepsPerHeatStep(double heat_dt) const;
  PetscErrorCode StopWaves(RunObservers& observers, const io::EnergyRow& last, io::RunSummary* summary);
  PetscErrorCode RunHeatAlone(RunObservers& observers, io::RunSummary* summary);
  // Checkpoints (simulation_checkpoint.cpp).
  /// Between coupling intervals: a checkpoint when due; a signal stops the run.
  PetscErrorCode CheckpointIfDue(Recorder& recorder, bool quiet);
  /// waves_quiet: the waves went quiet in the interval just ended (they stop now).
  PetscErrorCode WriteCheckpoint(Recorder& recorder, bool waves_quiet) const;
  /// Every component and the recorder back to the checkpoint's state.
  PetscErrorCode Resume(const store::Checkpoint& checkpoint, RunObservers& observers);
  /// Whether this scene's state can be checkpointed (says why not, once).
  PetscErrorCode CanCheckpoint(bool* can) const;

  const Scene* scene_ = nullptr;
  const mesh::Specimen* specimen_ = nullptr;
  std::string dir_;
  RunControl control_;
  CheckpointSchedule schedule_;
  bool checkpoints_ = false;  ///< this scene's state can be checkpointed
  bool waves_quiet_at_restart_ = false;  ///< the checkpoint restarted from was written as the waves stopped
  double heat_alone_from_ = -1.0;  ///< where a stop in the heat-alone phase resumes (< 0: no checkpoint there)
  int interrupted_by_ = 0;
  // The waves' phase (RunPhases).
  io::EnergyRow row_;          ///< the waves' energy row at the last interval's end
  bool quiet_ = false;         ///< the waves went quiet (they stop)
  double heat_dt_ = 0.0;       ///< the coupled heat step
  double waves_began_ = 0.0;   ///< wall time the waves' phase began
  bool continuation_restarted_ = false;  ///< restarted inside a continuation's ladder
  std::unique_ptr<WaveComponent> waves_;
  std::unique_ptr<HeatComponent> heat_;
  std::unique_ptr<HeatCamera> camera_;  ///< -camera: the IR camera's view of the heat field
  std::unique_ptr<PeriodicContinuation> periodic_;  ///< -periodic: continuation of a periodic state
  std::unique_ptr<ResponseStrain> strain_;            ///< the waves' strain, once per coupling interval
  io::RunSummary* summary_ = nullptr;                 ///< Run's (its warnings)
  /// The wave-stop rule: mechanical energy (kinetic + strain + interface) at recent intervals.
  struct Sample {
    double t, energy;                    ///< energy: the mechanical energy left times friction's share of the losses
    double dissipated, damped, radiated;  ///< the accounts then
  };
  std::vector<Sample> recent_;
  double peak_mechanical_ = 0.0, mechanical_left_ = 0.0;
  PetscErrorCode WavesQuiet(const io::EnergyRow& energy_now, bool* quiet);
  PetscLogStage wave_stage_ = -1, heat_stage_ = -1;
};

}  // namespace vibrotherm::coupling
