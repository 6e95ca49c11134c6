// The waves of a run: the wave TS and, when a crack transmits tractions, the
// crack contact as its extra force (the interface is built from the crack law's
// properties, not its name). Owns both until the run stops the waves.
#pragma once

#include <petscsys.h>

#include <memory>

#include "vibrotherm/coupling/continuation/continued_parts.hpp"
#include "vibrotherm/coupling/observe/wave_energy_row.hpp"
#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

class WaveComponent final : public ContinuedWaves {
 public:
  /// Builds the solver (stage "Wave setup") and the crack interface when a crack transmits tractions;
  /// restarting: the state comes from a checkpoint, the harmonic start is not solved (its checks are made).
  PetscErrorCode Setup(const mesh::Specimen& specimen, const Scene& scene, io::RunSummary* summary,
                       bool restarting = false);
  wave::WaveSolver& solver() override { return *solver_; }
  const wave::WaveSolver& solver() const override { return *solver_; }
  /// The crack contact, or null (no crack, or a law that transmits nothing).
  interface::CrackInterface* crack() override { return crack_.get(); }
  const interface::CrackInterface* crack() const override { return crack_.get(); }
  /// `steps` constant steps, or fewer landing exactly on t_end when it comes first.
  PetscErrorCode Advance(PetscInt steps, double t_end);
  /// Steps to t_end exactly (quantized steps land there).
  PetscErrorCode AdvanceTo(double t_end);
  /// Wave and interface columns of energy.csv now (collective).
  PetscErrorCode Energy(io::EnergyRow* row) const { return WaveEnergyRow(*solver_, row); }
  /// Fills the wave and contact parts of the summary and frees the solvers.
  PetscErrorCode Stop(io::RunSummary* summary);
  bool running() const { return solver_ != nullptr; }
  /// Checkpoints: the wave solver and the crack interface; and back.
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen);
  // The periodic continuation (continued_parts.hpp).
  PetscErrorCode Snapshot(const mesh::Specimen& specimen, store::Checkpoint* snapshot) const override;
  std::vector<double> Accumulated() const override;
  PetscErrorCode ResumeFrom(const store::Checkpoint& snapshot, const mesh::Specimen& specimen,
                            const std::vector<double>& increments) override;

 private:
  /// The initial state -wave_start asks for: rest (nothing to do), harmonic, or a saved state.
  PetscErrorCode StartWaves(const mesh::Specimen& specimen, const Scene& scene);
  /// With a continuation possible, -max_steps counts the steps taken (refused where they pass it).
  PetscErrorCode CheckStepBudget() const;
  std::unique_ptr<wave::WaveSolver> solver_;
  std::unique_ptr<interface::CrackInterface> crack_;
  double max_steps_ = 0.0;  ///< -max_steps, checked while stepping when a continuation may skip most steps
};

}  // namespace vibrotherm::coupling
