// Two-way thermoelastic coupling (-thermoelastic two_way): the thermal stress
// −βθI on the waves, PHYSICS.md §2. From ρü = ∇·(C:ε − βθ I):
//   f_j = ∫ β θ ∇·φ_j dx = −(1/T0) (Bᵀθ)_j,
// the adjoint of the heating B (thermoelastic_transfer.hpp), θ = T − T0 on the heat dofs.
//
// θ is known at heat steps only. Between two (t_n < t ≤ t_n+1) the force uses
//   θ*(t) = C⁻¹B u(t) + φ_n + (t − t_n) (φ_n − φ_n−1) / (t_n − t_n−1),   φ = θ − C⁻¹B u,
// C the heat's lumped capacity (C⁻¹ = 0 on sinks). The adiabatic part C⁻¹B u (the
// heat of the strain change, before conduction moves it) follows the waves at every
// wave step: a stiffness S = (1/T0) BᵀC⁻¹B, the adiabatic stiffening. Only what
// conduction did, φ, is extrapolated linearly from the last two heat steps. So
//   f(t, u) = g_n + (t − t_n) ġ_n − S u,  g_n = −Bᵀφ_n / T0,  ġ_n = −Bᵀ(φ_n − φ_n−1) / (T0 H).
// Why not θ itself, lagged or extrapolated: in the adiabatic regime (ωτ ≫ 1: the
// paper scene) that delays the adiabatic stiffness, which pumps energy into the
// waves (measured on the scalar model: Q⁻¹ = −3e-3 lagged, −2e-4 extrapolated at 24
// heat steps per period, −0.06 at 2: an instability for the clapping harmonics);
// here the adiabatic limit is exact (φ constant) and the error is the heat step's own.
#pragma once

#include <petscmat.h>

#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/wave/body_force.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

class ThermalStress final : public wave::BodyForce {
 public:
  ThermalStress() = default;
  ThermalStress(const ThermalStress&) = delete;
  ThermalStress& operator=(const ThermalStress&) = delete;
  ~ThermalStress() override;

  /// Attaches itself to the waves (their step includes S). transfer: B
  /// (referenced); capacity_inverse: C⁻¹ (heat vector, referenced); theta: the rise now. Collective.
  PetscErrorCode Setup(wave::WaveSolver* waves, Mat transfer, Vec capacity_inverse, Vec theta, double T0);
  /// After a heat step to t with the rise theta. Collective.
  PetscErrorCode Update(Vec theta, double t);
  /// The waves stop: no more force. Collective.
  PetscErrorCode Detach();

  /// Checkpoints (after a heat step): φ_n and the force's g_n, ġ_n, t_n; and back.
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen);
  PetscErrorCode Force(double t, Vec u, Vec f) override;
  PetscErrorCode MaxFrequencySquared(Vec mass, double* omega2) const override;
  const char* name() const override { return "-thermoelastic two_way"; }

 private:
  /// phi = θ − C⁻¹B u, u the waves' displacement now.
  PetscErrorCode Phi(Vec theta, Vec phi) const;
  wave::WaveSolver* waves_ = nullptr;
  Mat B_ = nullptr;
  Vec c_inv_ = nullptr, weight_ = nullptr;          ///< C⁻¹ and −C⁻¹/T0 (heat dofs)
  Vec heat_work_ = nullptr, phi_ = nullptr, phi_new_ = nullptr;  ///< heat dofs
  Vec g_ = nullptr, g_rate_ = nullptr;                       ///< wave dofs
  double T0_ = 0.0, t_n_ = 0.0;
  PetscLogEvent force_event_ = 0;
};

}  // namespace vibrotherm::coupling
