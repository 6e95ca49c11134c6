#include "vibrotherm/wave/lts_levels.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/mesh/plex/lts_partition.hpp"
#include "vibrotherm/wave/elastic_operator.hpp"

namespace vibrotherm::wave {

double CellAngularFrequency(const fe::CellQuadrature& q, const ElasticMaterial& material, bool hrz) {
  const int n = q.dim * q.nodes;
  std::vector<double> K(n * n), me(n), x(n), y(n);
  ElementStiffness(q, material.lambda(), material.shear_modulus(), K.data());
  ElementLumpedMass(q, material.density, hrz, me.data());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) K[i * n + j] /= std::sqrt(me[i] * me[j]);  // symmetric M^-1/2 K M^-1/2
  // Power iteration from a checkerboard start (the highest mode's shape); the
  // estimate only groups cells: each level's exact spectrum sets the step.
  for (int i = 0; i < n; ++i) x[i] = ((i / q.dim + i) % 2 ? 1.0 : -1.0) * (1.0 + 0.01 * i);
  double lambda = 0.0;
  for (int it = 0; it < 100; ++it) {
    double norm = 0.0, rayleigh = 0.0;
    for (int i = 0; i < n; ++i) {
      y[i] = 0.0;
      for (int j = 0; j < n; ++j) y[i] += K[i * n + j] * x[j];
      rayleigh += x[i] * y[i];
      norm += y[i] * y[i];
    }
    norm = std::sqrt(norm);
    if (norm == 0.0) break;
    double xx = 0.0;
    for (int i = 0; i < n; ++i) xx += x[i] * x[i];
    lambda = rayleigh / xx;
    for (int i = 0; i < n; ++i) x[i] = y[i] / norm;
  }
  return std::sqrt(std::max(0.0, lambda));
}

namespace {

/// Per cell, ω_e (collective: none).
PetscErrorCode CellFrequencies(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                               std::vector<double>* omega) {
  PetscFunctionBeginUser;
  const bool hrz = space.simplex() && space.degree() == 2;
  fe::CellQuadrature q;
  omega->clear();
  for (PetscInt c : space.cells()) {
    PetscCall(space.Evaluate(c, &q));
    omega->push_back(CellAngularFrequency(q, material, hrz));
  }
  PetscFunctionReturn(0);
}

/// Per local dof (local vector, ghosts included): the finest level of the cells holding it, on any rank.
PetscErrorCode LocalDofFinest(const fe::LagrangeSpace& space, const LtsLevels& levels, Vec finest_local) {
  PetscFunctionBeginUser;
  std::vector<PetscInt> finest;
  std::vector<std::vector<char>> touched;
  PetscCall(DofLevels(space, levels, &finest, &touched));
  Vec global;
  PetscCall(DMGetGlobalVector(space.dm(), &global));
  PetscScalar* g;
  PetscCall(VecGetArray(global, &g));
  for (std::size_t i = 0; i < finest.size(); ++i) g[i] = finest[i];
  PetscCall(VecRestoreArray(global, &g));
  PetscCall(DMGlobalToLocal(space.dm(), global, INSERT_VALUES, finest_local));
  PetscCall(DMRestoreGlobalVector(space.dm(), &global));
  PetscFunctionReturn(0);
}

/// Cells sharing a node at most one level apart: coarse cells next to finer ones are refined (collective).
PetscErrorCode SmoothLevels(const fe::LagrangeSpace& space, LtsLevels* levels) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  Vec finest;
  PetscCall(DMGetLocalVector(dm, &finest));
  for (int changed = 1; changed;) {
    PetscCall(LocalDofFinest(space, *levels, finest));
    std::vector<PetscInt>* level = &levels->cell_level;
    int local_changed = 0;
    for (std::size_t k = 0; k < level->size(); ++k) {
      PetscScalar* values = nullptr;
      PetscInt size;
      PetscCall(DMPlexVecGetClosure(dm, section, finest, space.cells()[k], &size, &values));
      PetscInt neighbour = 0;
      for (PetscInt i = 0; i < size; ++i) neighbour = std::max(neighbour, static_cast<PetscInt>(PetscRealPart(values[i])));
      PetscCall(DMPlexVecRestoreClosure(dm, section, finest, space.cells()[k], &size, &values));
      if (neighbour - 1 > (*level)[k]) (*level)[k] = neighbour - 1, local_changed = 1;
    }
    PetscCallMPI(MPI_Allreduce(&local_changed, &changed, 1, MPI_INT, MPI_MAX, comm));
  }
  PetscCall(DMRestoreLocalVector(dm, &finest));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode AssignCellLevels(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                const LtsOptions& options, LtsLevels* levels) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)space.dm());
  std::vector<double> omega;
  PetscCall(CellFrequencies(space, material, &omega));
  double local_max = 0.0, omega_max;
  for (double w : omega) local_max = std::max(local_max, w);
  PetscCallMPI(MPI_Allreduce(&local_max, &omega_max, 1, MPI_DOUBLE, MPI_MAX, comm));
  // Doublings above the finest step, then numbered from the coarsest.
  std::vector<PetscInt> up(omega.size());
  PetscInt local_top = 0, top;
  for (std::size_t k = 0; k < omega.size(); ++k) {
    up[k] = mesh::LtsDoublings(omega_max / omega[k], options.wiggle, options.max_levels);
    local_top = std::max(local_top, up[k]);
  }
  PetscCallMPI(MPI_Allreduce(&local_top, &top, 1, MPIU_INT, MPI_MAX, comm));
  levels->levels = top + 1;
  levels->cell_level.resize(up.size());
  for (std::size_t k = 0; k < up.size(); ++k) levels->cell_level[k] = top - up[k];
  PetscCall(SmoothLevels(space, levels));
  PetscFunctionReturn(0);
}

PetscErrorCode DofLevels(const fe::LagrangeSpace& space, const LtsLevels& levels, std::vector<PetscInt>* finest,
                         std::vector<std::vector<char>>* touched) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  Vec local, global;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGetGlobalVector(dm, &global));
  PetscInt m;
  PetscCall(VecGetLocalSize(global, &m));
  finest->assign(m, -1);
  touched->assign(levels.levels, std::vector<char>(m, 0));
  const std::vector<PetscScalar> ones(space.components() * space.nodes_per_cell(), 1.0);
  for (PetscInt l = 0; l < levels.levels; ++l) {
    PetscCall(VecSet(local, 0.0));
    for (std::size_t k = 0; k < levels.cell_level.size(); ++k)
      if (levels.cell_level[k] == l) PetscCall(DMPlexVecSetClosure(dm, section, local, space.cells()[k], ones.data(), INSERT_VALUES));
    PetscCall(VecSet(global, 0.0));
    PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, global));
    const PetscScalar* g;
    PetscCall(VecGetArrayRead(global, &g));
    for (PetscInt i = 0; i < m; ++i)
      if (PetscRealPart(g[i]) > 0.0) (*touched)[l][i] = 1, (*finest)[i] = l;
    PetscCall(VecRestoreArrayRead(global, &g));
  }
  PetscCall(DMRestoreGlobalVector(dm, &global));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
