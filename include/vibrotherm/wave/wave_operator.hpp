// The linear elastic operator of the waves on a mesh, without time: the displacement
// space (one component per dimension of the DM), the stiffness K and the row-sum lumped
// mass M (elastic_operator.hpp), and the stepping operator A = −M⁻¹K an explicit step
// applies, by PETSc's MatMult or by the 2×2-block kernel (block_kernel.hpp). The
// integrators (wave_solver.hpp) step with it; the energies and the harmonic start read it.
#pragma once

#include <petscmat.h>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/block_kernel.hpp"
#include "vibrotherm/wave/material.hpp"

namespace vibrotherm::wave {

/// How the explicit step applies A = −M⁻¹K: PETSc's MatMult, or the 2×2-block kernel (block_kernel.hpp).
enum class StiffnessKernel { kPetsc, kBlocked };

class WaveOperator {
 public:
  WaveOperator() = default;
  WaveOperator(const WaveOperator&) = delete;
  WaveOperator& operator=(const WaveOperator&) = delete;
  ~WaveOperator();

  /// The space of `degree` on dm, K and the lumped M (and M⁻¹). Collective.
  PetscErrorCode Setup(DM dm, const ElasticMaterial& material, PetscInt degree);
  /// ω_max of M⁻¹K (SLEPc); before MakeStepping, which replaces K. Collective.
  PetscErrorCode LargestFrequency(double* omega_max) const;
  /// A = −M⁻¹K made from K in place (keep_stiffness: K is kept too, for an implicit
  /// integrator's Jacobian); `kernel`: how Apply multiplies. Collective.
  PetscErrorCode MakeStepping(bool keep_stiffness, StiffnessKernel kernel);
  /// a = A u (after MakeStepping). Collective.
  PetscErrorCode Apply(Vec u, Vec a) const;

  const fe::LagrangeSpace& space() const { return space_; }
  /// The lumped mass M and its inverse (global vectors of the DM, read only).
  Vec mass() const { return M_; }
  Vec inverse_mass() const { return Minv_; }
  /// A = −M⁻¹K (after MakeStepping), and K (before it, or kept by it; null otherwise).
  Mat stepping() const { return A_; }
  Mat stiffness() const { return K_; }
  PetscInt dofs() const { return global_dofs_; }

 private:
  fe::LagrangeSpace space_;
  Mat K_ = nullptr, A_ = nullptr;
  Vec M_ = nullptr, Minv_ = nullptr;
  BlockKernel kernel_;
  bool blocked_ = false;  ///< Apply by kernel_
  PetscInt global_dofs_ = 0;
};

}  // namespace vibrotherm::wave
