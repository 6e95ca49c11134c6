// Thermoelastic heating as a heat source (one-way: waves → heat), PHYSICS.md §2:
//   q = −T0 β tr(ε̇),  β = (3λ + 2G) α_L,  plane strain (ε_zz = 0, tr ε = ∇·u).
// Exact in time: the heat a step deposits is −T0 β Δ tr ε, the change of the
// strain trace over the step (it telescopes: the heat deposited by time t is
// −T0 β (tr ε(t) − tr ε(0)) however the steps fall). In space, the load
//   Q_h = ∫ ψ_h (−T0 β ∇·Δu) dx / Δt
// is integrated over the heat mesh's cells: the matrix B of
// thermoelastic_transfer.hpp, built once, then Q = B Δu / Δt, one MatMult per heat step.
#pragma once

#include <petscmat.h>

#include <string>

#include "vibrotherm/coupling/exchange/heat_sources.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

class ThermoelasticSource final : public HeatSource {
 public:
  ThermoelasticSource() = default;
  ThermoelasticSource(const ThermoelasticSource&) = delete;
  ThermoelasticSource& operator=(const ThermoelasticSource&) = delete;
  ~ThermoelasticSource() override;

  /// transfer: B (thermoelastic_transfer.hpp; referenced). Collective.
  PetscErrorCode Setup(const wave::WaveSolver& waves, Mat transfer);
  PetscErrorCode AddLoad(double t, double interval, Vec Q) override;
  PetscErrorCode Finish(const std::string& dir) override;
  double deposited() const override { return deposited_; }
  const char* name() const override { return "thermoelastic"; }
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const override;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) override;

 private:
  const wave::WaveSolver* waves_ = nullptr;
  Mat B_ = nullptr;
  Vec u_prev_ = nullptr, work_ = nullptr;
  double deposited_ = 0.0;
};

}  // namespace vibrotherm::coupling
