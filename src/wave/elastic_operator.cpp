#include "vibrotherm/wave/elastic_operator.hpp"

#include <algorithm>
#include <vector>

namespace vibrotherm::wave {

void ElementStiffness(const fe::CellQuadrature& q, double lambda, double G, double* Ke) {
  const int Nb = q.nodes, n = 2 * Nb;
  std::fill(Ke, Ke + n * n, 0.0);
  for (int p = 0; p < q.points; ++p) {
    const double w = q.weight[p];
    const double* g = &q.grad[p * Nb * 2];
    for (int a = 0; a < Nb; ++a)
      for (int b = 0; b < Nb; ++b) {
        const double dot = g[2 * a] * g[2 * b] + g[2 * a + 1] * g[2 * b + 1];
        for (int i = 0; i < 2; ++i)
          for (int j = 0; j < 2; ++j)
            Ke[(2 * a + i) * n + 2 * b + j] +=
                w * (lambda * g[2 * a + i] * g[2 * b + j] + G * ((i == j ? dot : 0.0) + g[2 * a + j] * g[2 * b + i]));
      }
  }
}

PetscErrorCode AssembleElasticOperators(const fe::LagrangeSpace& space, const ElasticMaterial& material, Mat* K,
                                        Vec* lumped_mass) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  PetscCall(DMCreateMatrix(dm, K));
  PetscCall(MatSetOption(*K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  Vec mass_local;
  PetscCall(DMGetLocalVector(dm, &mass_local));
  PetscCall(VecSet(mass_local, 0.0));

  const double lambda = material.lambda(), G = material.shear_modulus(), rho = material.density;
  const int Nb = space.nodes_per_cell(), n = 2 * Nb;
  const bool hrz = space.simplex() && space.degree() == 2;
  std::vector<PetscScalar> Ke(n * n), me(n);
  fe::CellQuadrature q;
  for (PetscInt c : space.cells()) {
    PetscCall(space.Evaluate(c, &q));
    std::vector<double> row_sum(Nb, 0.0), diag(Nb, 0.0);
    double cell_mass = 0.0;
    for (int p = 0; p < q.points; ++p) {
      const double w = q.weight[p];
      const double* phi = q.value + p * Nb;
      cell_mass += w * rho;
      for (int a = 0; a < Nb; ++a) {
        row_sum[a] += w * rho * phi[a];
        diag[a] += w * rho * phi[a] * phi[a];
      }
    }
    ElementStiffness(q, lambda, G, Ke.data());
    double diag_sum = 0.0;
    for (double d : diag) diag_sum += d;
    for (int a = 0; a < Nb; ++a) me[2 * a] = me[2 * a + 1] = hrz ? diag[a] * cell_mass / diag_sum : row_sum[a];
    PetscCall(DMPlexMatSetClosure(dm, section, nullptr, *K, c, Ke.data(), ADD_VALUES));
    PetscCall(DMPlexVecSetClosure(dm, section, mass_local, c, me.data(), ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(DMCreateGlobalVector(dm, lumped_mass));
  PetscCall(VecSet(*lumped_mass, 0.0));
  PetscCall(DMLocalToGlobal(dm, mass_local, ADD_VALUES, *lumped_mass));
  PetscCall(DMRestoreLocalVector(dm, &mass_local));
  PetscReal min_mass;
  PetscCall(VecMin(*lumped_mass, nullptr, &min_mass));
  PetscCheck(min_mass > 0.0, PetscObjectComm((PetscObject)dm), PETSC_ERR_PLIB, "lumped mass has a non-positive entry (%g)",
             min_mass);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
