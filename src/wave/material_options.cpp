#include "vibrotherm/wave/material.hpp"

namespace vibrotherm::wave {

PetscErrorCode ReadElasticMaterial(MPI_Comm comm, ElasticMaterial* m) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Elastic material (plane strain)", nullptr);
  PetscCall(PetscOptionsReal("-material_density", "Density [kg/m^3]", nullptr, m->density, &m->density, nullptr));
  PetscCall(PetscOptionsReal("-material_E", "Young's modulus [Pa]", nullptr, m->E, &m->E, nullptr));
  PetscCall(PetscOptionsReal("-material_nu", "Poisson ratio", nullptr, m->nu, &m->nu, nullptr));
  PetscOptionsEnd();
  PetscCheck(m->density > 0.0, comm, PETSC_ERR_USER_INPUT, "-material_density must be > 0, got %g", m->density);
  PetscCheck(m->E > 0.0, comm, PETSC_ERR_USER_INPUT, "-material_E must be > 0, got %g", m->E);
  PetscCheck(m->nu > -1.0 && m->nu < 0.5, comm, PETSC_ERR_USER_INPUT, "-material_nu must be in (-1, 0.5), got %g", m->nu);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
