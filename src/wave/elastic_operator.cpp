#include "vibrotherm/wave/elastic_operator.hpp"

#include <algorithm>
#include <functional>
#include <vector>

namespace vibrotherm::wave {

void ElementStiffness(const fe::CellQuadrature& q, double lambda, double G, double* Ke) {
  const int Nb = q.nodes, D = q.dim, n = D * Nb;
  std::fill(Ke, Ke + n * n, 0.0);
  for (int p = 0; p < q.points; ++p) {
    const double w = q.weight[p];
    const double* g = &q.grad[p * Nb * D];
    for (int a = 0; a < Nb; ++a)
      for (int b = 0; b < Nb; ++b) {
        const double dot = fe::GradientDot(g + D * a, g + D * b, D);
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j)
            Ke[(D * a + i) * n + D * b + j] +=
                w * (lambda * g[D * a + i] * g[D * b + j] + G * ((i == j ? dot : 0.0) + g[D * a + j] * g[D * b + i]));
      }
  }
}

void ElementLumpedMass(const fe::CellQuadrature& q, double rho, bool hrz, double* me) {
  const int Nb = q.nodes, D = q.dim;
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
  double diag_sum = 0.0;
  for (double d : diag) diag_sum += d;
  for (int a = 0; a < Nb; ++a)
    std::fill(me + D * a, me + D * (a + 1), hrz ? diag[a] * cell_mass / diag_sum : row_sum[a]);
}

namespace {

/// K += the element stiffness of the cells `include` accepts (by index in
/// space.cells()); mass_local (if given) += their lumped masses.
PetscErrorCode AddCells(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                        const std::function<bool(std::size_t)>& include, Mat K, Vec mass_local) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  const double lambda = material.lambda(), G = material.shear_modulus();
  // The displacement has as many components as the mesh has dimensions.
  PetscCheck(space.components() == space.dim(), PetscObjectComm((PetscObject)dm), PETSC_ERR_ARG_WRONG,
             "elastic operator on a %" PetscInt_FMT "-component space of a %dD mesh", space.components(), space.dim());
  const int n = space.dim() * space.nodes_per_cell();
  const bool hrz = space.simplex() && space.degree() == 2;
  std::vector<PetscScalar> Ke(n * n), me(n);
  fe::CellQuadrature q;
  for (std::size_t k = 0; k < space.cells().size(); ++k) {
    if (include && !include(k)) continue;
    const PetscInt c = space.cells()[k];
    PetscCall(space.Evaluate(c, &q));
    ElementStiffness(q, lambda, G, Ke.data());
    PetscCall(DMPlexMatSetClosure(dm, section, nullptr, K, c, Ke.data(), ADD_VALUES));
    if (!mass_local) continue;
    ElementLumpedMass(q, material.density, hrz, me.data());
    PetscCall(DMPlexVecSetClosure(dm, section, mass_local, c, me.data(), ADD_VALUES));
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode AssembleElasticStiffness(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                        const std::function<bool(std::size_t)>& include, Mat* K) {
  PetscFunctionBeginUser;
  // Only the entries of these cells: DMPlex would otherwise store the whole
  // mesh's pattern as explicit zeros (and every product would pay for them).
  // (vibrotherm never sets preallocate-only elsewhere: back to PETSc's default after.)
  PetscCall(DMSetMatrixPreallocateOnly(space.dm(), PETSC_TRUE));
  PetscCall(DMCreateMatrix(space.dm(), K));
  PetscCall(DMSetMatrixPreallocateOnly(space.dm(), PETSC_FALSE));
  PetscCall(MatSetOption(*K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(AddCells(space, material, include, *K, nullptr));
  PetscCall(MatAssemblyBegin(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*K, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode AssembleElasticOperators(const fe::LagrangeSpace& space, const ElasticMaterial& material, Mat* K,
                                        Vec* lumped_mass) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  PetscCall(DMCreateMatrix(dm, K));
  PetscCall(MatSetOption(*K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  Vec mass_local;
  PetscCall(DMGetLocalVector(dm, &mass_local));
  PetscCall(VecSet(mass_local, 0.0));
  PetscCall(AddCells(space, material, nullptr, *K, mass_local));
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

PetscErrorCode ScaleToAcceleration(Mat K, Vec lumped_mass) {
  PetscFunctionBeginUser;
  Vec minus_inverse;
  PetscCall(VecDuplicate(lumped_mass, &minus_inverse));
  PetscCall(VecCopy(lumped_mass, minus_inverse));
  PetscCall(VecReciprocal(minus_inverse));
  PetscCall(VecScale(minus_inverse, -1.0));
  PetscCall(MatDiagonalScale(K, minus_inverse, nullptr));
  PetscCall(VecDestroy(&minus_inverse));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
