// What the periodic continuation needs of a run, and nothing more: the waves it
// suspends and resumes, the heat it replays a recorded period into, the scene's
// few numbers, and the run's observers its heat steps notify. The run's components
// (coupling/run: WaveComponent, HeatComponent, RunObservers) implement these, so the
// continuation sits below the run and never calls up into it.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/coupling/continuation/periodic_options.hpp"
#include "vibrotherm/coupling/exchange/periodic_replay.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/io/progress.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

/// The waves a continuation suspends: their state kept in memory, what grows in it, and back.
class ContinuedWaves {
 public:
  virtual ~ContinuedWaves() = default;
  virtual wave::WaveSolver& solver() = 0;
  virtual const wave::WaveSolver& solver() const = 0;
  /// The crack contact, or null.
  virtual interface::CrackInterface* crack() = 0;
  virtual const interface::CrackInterface* crack() const = 0;
  /// The state kept in memory ...
  virtual PetscErrorCode Snapshot(const mesh::Specimen& specimen, store::Checkpoint* snapshot) const = 0;
  /// ... what grows over time in it (this rank's: the solver's accounts, then the crack's) ...
  virtual std::vector<double> Accumulated() const = 0;
  /// ... and the stored state again, jumped ahead by increments of what grows.
  virtual PetscErrorCode ResumeFrom(const store::Checkpoint& snapshot, const mesh::Specimen& specimen,
                                    const std::vector<double>& increments) = 0;
};

/// The heat a continuation drives with a recorded period instead of the waves.
class ContinuedHeat {
 public:
  virtual ~ContinuedHeat() = default;
  virtual heat::HeatSolver& solver() = 0;
  virtual const heat::HeatSolver& solver() const = 0;
  /// Whether every source can replay a recorded period.
  virtual bool replayable() const = 0;
  /// The sources record what they deposit from t on (a heat step's end), until StopRecording ...
  virtual PetscErrorCode StartRecording(double t) = 0;
  virtual PetscErrorCode StopRecording() = 0;
  /// ... and replay it (phase-locked or averaged) or take the live physics again (off).
  virtual PetscErrorCode Replay(ReplayMode mode) = 0;
  /// One heat step to t (sample_probes = false: the caller samples them, after shifting the field).
  virtual PetscErrorCode StepTo(double t, bool sample_probes = true) = 0;
  /// One heat step to t with the sources' averaged load, exchanging and recording nothing.
  virtual PetscErrorCode StepAveraged(double t) = 0;
  virtual PetscErrorCode SampleProbes() = 0;
  /// The crack probes' near field paused over the heat ladder, restarted after it.
  virtual void PauseNearField() = 0;
  virtual void RestartNearField() = 0;
  /// The solver alone into an in-memory snapshot, and back.
  virtual PetscErrorCode SolverSnapshot(const mesh::Specimen& specimen, store::Checkpoint* snapshot) const = 0;
  virtual PetscErrorCode RestoreSolver(const store::Checkpoint& snapshot, const mesh::Specimen& specimen) = 0;
};

/// The run's observers, as the continuation's heat steps reach them (coupling/run/run_observers.hpp).
class ContinuationObserver {
 public:
  virtual ~ContinuationObserver() = default;
  /// After a heat step at t without waves; interval: the wave columns of energy.csv when a coupling
  /// interval ends here (null within one).
  virtual PetscErrorCode HeatStepContinued(double t, const io::EnergyRow* interval) = 0;
  /// Between the heat ladder's steps: a checkpoint when due; *stop when a signal stops the run.
  virtual PetscErrorCode BetweenSteps(bool* stop) = 0;
  /// Where a heat step after t must stop next (an output time or a camera window boundary; else end).
  virtual double NextHeatStop(double t, double end) const = 0;
  virtual io::Progress& progress() = 0;
};

/// The scene's numbers a continuation works with.
struct ContinuationScene {
  PeriodicOptions periodic;
  const wave::SourceTimeFunction* signal = nullptr;
  double final_time = 0.0;
  double couple_dt = 0.0;           ///< the coupling interval
  PetscInt heat_substeps = 1;       ///< heat steps per coupling interval
  double waves_expected_end = 0.0;  ///< where the waves are expected to be quiet
  const wave::Excitation* excitation = nullptr;  ///< the source (signal is its time function)
};

}  // namespace vibrotherm::coupling
