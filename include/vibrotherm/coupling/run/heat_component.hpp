// The heat of a run: the heat TS on the heat mesh with its sources (the
// exchanges that feed it). While the waves run it steps with them, one heat
// step per StepTo; afterwards it runs alone (adaptive) to the final time.
#pragma once

#include <petscsys.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/coupling/continuation/continued_parts.hpp"
#include "vibrotherm/coupling/observe/camera_verdict.hpp"
#include "vibrotherm/coupling/exchange/heat_sources.hpp"
#include "vibrotherm/coupling/observe/probe_temperatures.hpp"
#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/coupling/run/wave_component.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::coupling {

class ThermalStress;

class HeatComponent final : public ContinuedHeat {
 public:
  HeatComponent();
  HeatComponent(const HeatComponent&) = delete;
  HeatComponent& operator=(const HeatComponent&) = delete;
  ~HeatComponent();

  /// Builds the solver (stage "Heat setup"), its sources (friction when `waves`
  /// has a dissipating crack; -heat_crack_power for -physics heat) and the
  /// temperature probes (point probes, then crack probes on the crack line).
  PetscErrorCode Setup(const mesh::Specimen& specimen, const Scene& scene, WaveComponent* waves,
                       io::RunSummary* summary);
  /// What of the heat field is the defect's own (the camera's verdict, heat_camera.hpp): all of it
  /// (only the crack heats), none (nothing heats at the crack), or the partial rise the solver
  /// steps beside θ with the friction heat alone (damping, thermoelastic or film heat as well).
  DefectShare defect_share() const { return defect_share_; }
  heat::HeatSolver& solver() override { return solver_; }
  const heat::HeatSolver& solver() const override { return solver_; }
  /// One heat step to t, loaded with what every source deposited since the last step
  /// (two_way: then the thermal stress on the waves follows the new temperatures).
  /// sample_probes = false: the caller samples the probes itself (SampleProbes), after shifting the field.
  PetscErrorCode StepTo(double t, bool sample_probes = true) override;
  /// The crack probes' near field paused over a continuation's heat ladder, restarted after it.
  void PauseNearField() override { probe_temperatures_.PauseNearField(); }
  void RestartNearField() override { probe_temperatures_.RestartNearField(); }
  /// The probes after a heat step (and, while a replay runs, the replayed friction for their near field).
  PetscErrorCode SampleProbes() override;
  /// After every wave step while coupled (row: probes.csv has a row at t).
  void AfterWaveStep(double t, bool row) { probe_temperatures_.AfterWaveStep(t, row); }
  /// The probes' temperatures since the last call (probe_temperatures.hpp). Collective.
  PetscErrorCode ProbeSeries(io::TemperatureSeries* series) { return probe_temperatures_.Collect(series); }
  /// The sources' physics stopped: they write their records into dir and go (and
  /// the thermal stress leaves the waves).
  PetscErrorCode StopSources(const std::string& dir);
  /// Points of the crack probes (on the heat mesh's crack lines).
  const std::vector<double>& crack_probe_xy() const { return crack_probe_xy_; }
  /// Heat columns of energy.csv.
  PetscErrorCode Energy(io::EnergyRow* row) const;
  PetscErrorCode Summarise(io::RunSummary* summary) const;
  /// Checkpoints (after a heat step while the waves run): the solver and its sources; and back
  /// (after the waves have restored theirs).
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen);
  // Periodic continuation (continued_parts.hpp).
  bool replayable() const override;
  PetscErrorCode StartRecording(double t) override;
  PetscErrorCode StopRecording() override;
  PetscErrorCode Replay(ReplayMode mode) override;
  PetscErrorCode StepAveraged(double t) override;
  PetscErrorCode SolverSnapshot(const mesh::Specimen& specimen, store::Checkpoint* snapshot) const override;
  PetscErrorCode RestoreSolver(const store::Checkpoint& snapshot, const mesh::Specimen& specimen) override;
  /// Wall time spent stepping the heat [s].
  double seconds() const { return seconds_; }
  void add_seconds(double s) { seconds_ += s; }

 private:
  /// -thermoelastic: the heating (one_way, two_way) and the thermal stress on the waves (two_way).
  PetscErrorCode SetupThermoelastic(const Scene& scene, WaveComponent* waves);
  /// Which DefectShare; the partial rise enabled when needed.
  PetscErrorCode SetupDefectShare(const Scene& scene);
  /// load_ = every source's load for the step to t (averaged: a continuation's averaged twin);
  /// the friction's alone into the solver's partial load when it steps one.
  PetscErrorCode LoadSources(double t, bool averaged);
  heat::HeatSolver solver_;
  std::vector<std::unique_ptr<HeatSource>> sources_;
  std::unique_ptr<ThermalStress> thermal_stress_;  ///< -thermoelastic two_way: θ back on the waves
  ProbeTemperatures probe_temperatures_;          ///< the probes between heat steps
  FrictionHeatSource* friction_ = nullptr;        ///< among sources_, when friction heats
  Vec load_ = nullptr, defect_load_ = nullptr;
  Vec crack_load_ = nullptr;  ///< -physics heat: the prescribed crack power's load (crack_power.hpp)
  DefectShare defect_share_ = DefectShare::Whole;
  std::vector<double> crack_probe_xy_;
  std::map<std::string, double> deposited_by_source_;  ///< kept after the sources go
  double seconds_ = 0.0;
};

}  // namespace vibrotherm::coupling
