// The heat of material damping (-material_damping_heat; PHYSICS.md §2): the energy the
// damping C = αM takes from each wave dof, exactly as the waves account it (h α m v̄²
// per step, material_damping.cpp), deposited where it is taken. Per heat step the
// dofs' energies E since the last step arrive as the load D E / Δt, with D of
// thermoelastic_transfer.hpp (AssembleDampingTransfer: every column sums to 1), so
// the heat deposited equals the waves' `damped` column to rounding. A whole-specimen
// source: most scenes want it off (the crack's friction is the signal). A periodic
// continuation replays it like the friction: each heat dof's cumulative energy over
// the recorded period, phase-locked or averaged (periodic_replay.hpp).
#pragma once

#include <petscmat.h>

#include <string>
#include <vector>

#include "vibrotherm/coupling/exchange/heat_sources.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

class DampingHeatSource final : public ReplayableHeatSource {
 public:
  DampingHeatSource() = default;
  DampingHeatSource(const DampingHeatSource&) = delete;
  DampingHeatSource& operator=(const DampingHeatSource&) = delete;
  ~DampingHeatSource() override;

  /// transfer: D (referenced). Refused (naming the options) when the waves keep no per-dof damping
  /// energy (local time stepping accounts it kick by kick). Collective.
  PetscErrorCode Setup(wave::WaveSolver* waves, Mat transfer);
  PetscErrorCode AddLoad(double t, double interval, Vec Q) override;
  PetscErrorCode Finish(const std::string& dir) override;
  const char* name() const override { return "damping"; }
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const override;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) override;
  PetscErrorCode AddAverageLoad(Vec Q) override;

 private:
  /// work_ = the energy per heat dof of the step ending at t: the waves' (live), or the replay's.
  PetscErrorCode StepEnergy(double t);
  wave::WaveSolver* waves_ = nullptr;
  Mat D_ = nullptr;
  Vec energy_ = nullptr, work_ = nullptr;
  std::vector<double> Cumulative() const override { return cumulative_; }
  MPI_Comm comm() const override { return PetscObjectComm((PetscObject)D_); }
  std::vector<double> cumulative_;  ///< energy deposited so far per owned heat dof [J/m]
};

}  // namespace vibrotherm::coupling
