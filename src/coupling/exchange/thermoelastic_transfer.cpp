#include "vibrotherm/coupling/exchange/thermoelastic_transfer.hpp"

#include <petscdmplex.h>

#include <array>
#include <vector>

#include "vibrotherm/fe/point_owners.hpp"
#include "vibrotherm/util/two_pass_matrix.hpp"

namespace vibrotherm::coupling {
namespace {

/// Heat quadrature points, packed: per point where (x, y, z; z = 0 in 2D), its weight,
/// its heat cell's nodes' global rows, their basis values (this rank's, or those it received).
struct HeatPoints {
  const std::vector<double>* packed = nullptr;
  int nodes = 0;  ///< heat nodes per cell
  std::size_t stride() const { return 4 + 2 * static_cast<std::size_t>(nodes); }
  const double* at(std::size_t i) const { return &(*packed)[stride() * i]; }
};

/// This rank's heat quadrature points, packed as HeatPoints.
PetscErrorCode PackHeatPoints(const fe::LagrangeSpace& heat, std::vector<double>* mine) {
  PetscFunctionBeginUser;
  DM dm = heat.dm();
  PetscSection local, global;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  const int nb = heat.nodes_per_cell(), dim = heat.dim();
  std::vector<double> xyz;
  fe::CellQuadrature q;
  mine->clear();
  for (PetscInt c : heat.cells()) {
    PetscCall(heat.Evaluate(c, &q));
    PetscCall(heat.QuadraturePoints(c, &xyz));
    PetscInt n, *rows = nullptr;
    PetscCall(DMPlexGetClosureIndices(dm, local, global, c, PETSC_TRUE, &n, &rows, nullptr, nullptr));
    for (int p = 0; p < q.points; ++p) {
      mine->insert(mine->end(), {xyz[dim * p], xyz[dim * p + 1], dim == 3 ? xyz[dim * p + 2] : 0.0, q.weight[p]});
      for (int b = 0; b < nb; ++b) mine->push_back(static_cast<double>(rows[b] >= 0 ? rows[b] : -(rows[b] + 1)));
      mine->insert(mine->end(), q.value + p * nb, q.value + (p + 1) * nb);
    }
    PetscCall(DMPlexRestoreClosureIndices(dm, local, global, c, PETSC_TRUE, &n, &rows, nullptr, nullptr));
  }
  PetscFunctionReturn(0);
}

/// The inverse of the dim × dim row-major J (2 or 3).
std::array<double, 9> Inverse(const std::array<double, 9>& J, int dim) {
  if (dim == 2) {
    const double det = J[0] * J[3] - J[1] * J[2];
    return {J[3] / det, -J[1] / det, -J[2] / det, J[0] / det};
  }
  const double c00 = J[4] * J[8] - J[5] * J[7], c01 = J[5] * J[6] - J[3] * J[8], c02 = J[3] * J[7] - J[4] * J[6];
  const double det = J[0] * c00 + J[1] * c01 + J[2] * c02;
  return {c00 / det, (J[2] * J[7] - J[1] * J[8]) / det, (J[1] * J[5] - J[2] * J[4]) / det,
          c01 / det, (J[0] * J[8] - J[2] * J[6]) / det, (J[2] * J[3] - J[0] * J[5]) / det,
          c02 / det, (J[1] * J[6] - J[0] * J[7]) / det, (J[0] * J[4] - J[1] * J[3]) / det};
}

/// The owned points in runs that share a heat cell (the same heat rows) and a wave cell:
/// each run is one block of the transfer, so the matrix sees one insertion per run, not
/// one per quadrature point (a heat cell inside one wave cell is a single run).
std::vector<std::vector<std::size_t>> RunsOfPoints(const HeatPoints& points, const fe::LocatedPoints& located) {
  std::vector<std::vector<std::size_t>> runs;
  auto same_rows = [&](std::size_t i, std::size_t j) {
    for (int b = 0; b < points.nodes; ++b)
      if (points.at(i)[4 + b] != points.at(j)[4 + b]) return false;
    return true;
  };
  for (std::size_t i : located.owned) {
    if (runs.empty() || located.cells[runs.back().back()] != located.cells[i] || !same_rows(runs.back().back(), i))
      runs.emplace_back();
    runs.back().push_back(i);
  }
  return runs;
}

/// A run's block of the transfer: its heat rows × its wave cell's closure dofs (node-major,
/// dim components), summed over the run's points; the values only when `values` is given.
PetscErrorCode RunBlock(const fe::LagrangeSpace& wave, const fe::CellLocator& locator, const HeatPoints& points,
                        const fe::LocatedPoints& located, const std::vector<std::size_t>& run,
                        const WaveToHeatKernel& kernel, std::vector<PetscInt>* rows, std::vector<PetscInt>* cols,
                        std::vector<double>* values) {
  PetscFunctionBeginUser;
  const PetscInt cell = located.cells[run.front()];
  PetscSection local, global;
  PetscCall(DMGetLocalSection(wave.dm(), &local));
  PetscCall(DMGetGlobalSection(wave.dm(), &global));
  PetscInt nc, *closure = nullptr;
  PetscCall(DMPlexGetClosureIndices(wave.dm(), local, global, cell, PETSC_TRUE, &nc, &closure, nullptr, nullptr));
  cols->resize(nc);
  for (PetscInt k = 0; k < nc; ++k) (*cols)[k] = closure[k] >= 0 ? closure[k] : -(closure[k] + 1);
  PetscCall(DMPlexRestoreClosureIndices(wave.dm(), local, global, cell, PETSC_TRUE, &nc, &closure, nullptr, nullptr));
  PetscCheck(nc == static_cast<PetscInt>(wave.nodes_per_cell()) * wave.dim(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "wave-to-heat transfer: a wave cell of %" PetscInt_FMT " dofs, not nodes x dim", nc);
  const double* first = points.at(run.front());
  rows->assign(first + 4, first + 4 + points.nodes);  // exact: global rows are below 2^53
  if (!values) PetscFunctionReturn(0);
  const int dim = wave.dim(), nb = wave.nodes_per_cell();
  std::vector<fe::ReferencePoint> refs;
  for (std::size_t i : run) refs.push_back(located.refs[i]);
  std::vector<double> phi, dphi, dof_kernel(static_cast<std::size_t>(nb) * dim);
  PetscCall(wave.BasisAndDerivativesAt(refs, &phi, &dphi));
  values->assign(rows->size() * nc, 0.0);
  for (std::size_t q = 0; q < run.size(); ++q) {
    const double* p = points.at(run[q]);
    const std::array<double, 9> iJ = Inverse(locator.Jacobian(cell, refs[q]), dim);  // dξ_j/dx_k at [j][k]
    for (int a = 0; a < nb; ++a)
      for (int k = 0; k < dim; ++k) {  // the kernel of the dof (node a, component k): ∂φ_a/∂x_k
        double d = 0.0;
        for (int j = 0; j < dim; ++j) d += dphi[(q * nb + a) * dim + j] * iJ[dim * j + k];
        dof_kernel[dim * a + k] = kernel(phi[q * nb + a], d);
      }
    for (std::size_t h = 0; h < rows->size(); ++h)
      for (int c = 0; c < nb * dim; ++c) (*values)[h * nc + c] += p[3] * p[4 + points.nodes + h] * dof_kernel[c];
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode AssembleWaveToHeat(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat,
                                  const WaveToHeatKernel& kernel, Mat* transfer, util::ExchangeCounts* counts) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)wave.dm());
  std::vector<double> mine;
  PetscCall(PackHeatPoints(heat, &mine));
  fe::CellLocator locator;
  PetscCall(locator.Setup(wave));
  HeatPoints points{nullptr, heat.nodes_per_cell()};
  util::PointExchange exchange;
  fe::LocatedPoints located;
  PetscCall(fe::LocateOnRanks(locator, comm, mine, points.stride(), &exchange, &located));
  // A point no wave cell holds would drop its share silently (and the damping transfer's
  // column scaling would hide it): the two meshes must cover the same body.
  PetscCheck(located.lost.count == 0, comm, PETSC_ERR_PLIB,
             "wave-to-heat transfer: %" PetscInt_FMT " of %" PetscInt_FMT " heat quadrature points lie in no wave cell",
             located.lost.count, exchange.counts().total);
  if (counts) *counts = exchange.counts();
  std::vector<double>().swap(mine);
  points.packed = &exchange.received();
  Vec u;
  PetscInt rows, cols, global_rows, global_cols;
  PetscCall(DMGetGlobalVector(heat.dm(), &u));
  PetscCall(VecGetLocalSize(u, &rows));
  PetscCall(VecGetSize(u, &global_rows));
  PetscCall(DMRestoreGlobalVector(heat.dm(), &u));
  PetscCall(DMGetGlobalVector(wave.dm(), &u));
  PetscCall(VecGetLocalSize(u, &cols));
  PetscCall(VecGetSize(u, &global_cols));
  PetscCall(DMRestoreGlobalVector(wave.dm(), &u));
  Mat pattern, B;
  PetscCall(util::CreateTwoPassMatrices(comm, rows, cols, global_rows, global_cols, &pattern, &B));
  const std::vector<std::vector<std::size_t>> runs = RunsOfPoints(points, located);
  std::vector<PetscInt> block_rows, block_cols;
  std::vector<double> values;
  for (Mat M : {pattern, B}) {
    if (M == B) PetscCall(MatPreallocatorPreallocate(pattern, PETSC_TRUE, B));
    for (const std::vector<std::size_t>& run : runs) {
      PetscCall(RunBlock(wave, locator, points, located, run, kernel, &block_rows, &block_cols,
                         M == B ? &values : nullptr));
      if (M == pattern) values.assign(block_rows.size() * block_cols.size(), 0.0);
      PetscCall(MatSetValues(M, static_cast<PetscInt>(block_rows.size()), block_rows.data(),
                             static_cast<PetscInt>(block_cols.size()), block_cols.data(), values.data(), ADD_VALUES));
    }
    PetscCall(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(MatDestroy(&pattern));
  *transfer = B;
  PetscFunctionReturn(0);
}

PetscErrorCode AssembleThermoelasticTransfer(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat, double beta_T0,
                                             Mat* transfer) {
  return AssembleWaveToHeat(wave, heat, [beta_T0](double, double d) { return -beta_T0 * d; }, transfer);
}

PetscErrorCode AssembleDampingTransfer(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat, Mat* transfer) {
  PetscFunctionBeginUser;
  Mat T;
  PetscCall(AssembleWaveToHeat(wave, heat, [](double phi, double) { return phi; }, &T));
  // Each wave dof's energy all into the heat mesh: columns scaled to sum 1 (∫ψ_h summed over h is ∫φ_j,
  // up to the heat cells' quadrature of a wave basis function).
  Vec ones, sums;
  PetscCall(MatCreateVecs(T, &sums, &ones));
  PetscCall(VecSet(ones, 1.0));
  PetscCall(MatMultTranspose(T, ones, sums));
  PetscScalar* s;
  PetscInt n;
  PetscCall(VecGetLocalSize(sums, &n));
  PetscCall(VecGetArray(sums, &s));
  for (PetscInt i = 0; i < n; ++i) s[i] = s[i] != 0.0 ? 1.0 / s[i] : 0.0;
  PetscCall(VecRestoreArray(sums, &s));
  PetscCall(MatDiagonalScale(T, nullptr, sums));
  PetscCall(VecDestroy(&ones));
  PetscCall(VecDestroy(&sums));
  *transfer = T;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
