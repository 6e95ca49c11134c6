#include "vibrotherm/wave/wave_operator.hpp"

#include "vibrotherm/wave/elastic_operator.hpp"
#include "vibrotherm/wave/stability.hpp"

namespace vibrotherm::wave {

WaveOperator::~WaveOperator() {
  (void)VecDestroy(&M_);
  (void)VecDestroy(&Minv_);
  (void)MatDestroy(&K_);
  (void)MatDestroy(&A_);
}

PetscErrorCode WaveOperator::Setup(DM dm, const ElasticMaterial& material, PetscInt degree) {
  PetscFunctionBeginUser;
  PetscInt dim;  // one displacement component per dimension of the mesh
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(space_.Setup(dm, degree, dim));
  PetscCall(AssembleElasticOperators(space_, material, &K_, &M_));
  PetscCall(VecDuplicate(M_, &Minv_));
  PetscCall(VecCopy(M_, Minv_));
  PetscCall(VecReciprocal(Minv_));
  PetscCall(VecGetSize(M_, &global_dofs_));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveOperator::LargestFrequency(double* omega_max) const {
  PetscFunctionBeginUser;
  PetscCall(LargestAngularFrequency(K_, M_, omega_max));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveOperator::MakeStepping(bool keep_stiffness, StiffnessKernel kernel) {
  PetscFunctionBeginUser;
  if (keep_stiffness) {
    PetscCall(MatDuplicate(K_, MAT_COPY_VALUES, &A_));
  } else {  // scaled in place: one matrix, not two
    A_ = K_;
    K_ = nullptr;
  }
  PetscCall(ScaleToAcceleration(A_, M_));
  blocked_ = kernel == StiffnessKernel::kBlocked;
  if (blocked_) PetscCall(kernel_.Setup(A_));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveOperator::Apply(Vec u, Vec a) const {
  PetscFunctionBeginUser;
  if (blocked_) PetscCall(kernel_.Apply(u, a));
  else PetscCall(MatMult(A_, u, a));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
