#include "vibrotherm/coupling/exchange/thermoelastic_transfer.hpp"

#include <petscdmplex.h>

#include <array>
#include <climits>
#include <vector>

#include "vibrotherm/fe/cell_locator.hpp"
#include "vibrotherm/util/all_gather.hpp"

namespace vibrotherm::coupling {
namespace {

/// A quadrature point of the heat mesh as every rank sees it: where, its weight,
/// and the heat basis values with their global rows (up to 9 nodes).
constexpr int kMaxHeatNodes = 9;
constexpr int kPointFields = 3 + 2 * kMaxHeatNodes;  // x, y, w, rows[9], psi[9]

/// Every rank's heat quadrature points, packed (kPointFields doubles each). Collective.
PetscErrorCode GatherHeatPoints(const fe::LagrangeSpace& heat, std::vector<double>* all) {
  PetscFunctionBeginUser;
  DM dm = heat.dm();
  PetscSection local, global;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  const int nb = heat.nodes_per_cell();
  PetscCheck(nb <= kMaxHeatNodes, PETSC_COMM_SELF, PETSC_ERR_SUP, "thermoelastic: heat elements of %d nodes", nb);
  std::vector<double> mine, xy;
  fe::CellQuadrature q;
  for (PetscInt c : heat.cells()) {
    PetscCall(heat.Evaluate(c, &q));
    PetscCall(heat.QuadraturePoints(c, &xy));
    PetscInt n, *rows = nullptr;
    PetscCall(DMPlexGetClosureIndices(dm, local, global, c, PETSC_TRUE, &n, &rows, nullptr, nullptr));
    for (int p = 0; p < q.points; ++p) {
      double packed[kPointFields] = {xy[2 * p], xy[2 * p + 1], q.weight[p]};
      for (int b = 0; b < kMaxHeatNodes; ++b) {
        packed[3 + b] = b < nb ? static_cast<double>(rows[b] >= 0 ? rows[b] : -(rows[b] + 1)) : -1.0;
        packed[3 + kMaxHeatNodes + b] = b < nb ? q.value[p * nb + b] : 0.0;
      }
      mine.insert(mine.end(), packed, packed + kPointFields);
    }
    PetscCall(DMPlexRestoreClosureIndices(dm, local, global, c, PETSC_TRUE, &n, &rows, nullptr, nullptr));
  }
  PetscCall(util::AllGather(PetscObjectComm((PetscObject)dm), mine, all));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode AssembleWaveToHeat(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat,
                                  const WaveToHeatKernel& kernel, Mat* transfer) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)wave.dm());
  std::vector<double> points;
  PetscCall(GatherHeatPoints(heat, &points));
  const std::size_t n = points.size() / kPointFields;
  fe::CellLocator locator;
  PetscCall(locator.Setup(wave));
  std::vector<PetscInt> cells(n);
  std::vector<std::array<double, 2>> refs(n);
  std::vector<int> mine(n, INT_MAX), owner(n);
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (std::size_t i = 0; i < n; ++i) {
    locator.Locate(points[kPointFields * i], points[kPointFields * i + 1], &cells[i], &refs[i]);
    if (cells[i] >= 0) mine[i] = rank;
  }
  // A point on a partition boundary belongs to the lowest rank holding it: counted once.
  if (n) PetscCallMPI(MPI_Allreduce(mine.data(), owner.data(), static_cast<int>(n), MPI_INT, MPI_MIN, comm));
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
  Mat B;
  PetscCall(MatCreateAIJ(comm, rows, cols, global_rows, global_cols, 60, nullptr, 60, nullptr, &B));
  PetscCall(MatSetOption(B, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscSection local, global;
  PetscCall(DMGetLocalSection(wave.dm(), &local));
  PetscCall(DMGetGlobalSection(wave.dm(), &global));
  const int nb = wave.nodes_per_cell();
  std::vector<double> phi, dphi, values;
  for (std::size_t i = 0; i < n; ++i) {
    if (owner[i] != rank) continue;
    const double* p = &points[kPointFields * i];
    PetscCall(wave.BasisAndDerivativesAt(refs[i], &phi, &dphi));
    const auto J = locator.Jacobian(cells[i], refs[i]);
    const double det = J[0] * J[3] - J[1] * J[2];
    const double iJ[4] = {J[3] / det, -J[1] / det, -J[2] / det, J[0] / det};  // dξ_j/dx_i at [j][i]
    PetscInt nc, *wave_cols = nullptr;
    PetscCall(DMPlexGetClosureIndices(wave.dm(), local, global, cells[i], PETSC_TRUE, &nc, &wave_cols, nullptr, nullptr));
    std::vector<PetscInt> cols_here(nc), rows_here;
    for (PetscInt k = 0; k < nc; ++k) cols_here[k] = wave_cols[k] >= 0 ? wave_cols[k] : -(wave_cols[k] + 1);
    PetscCall(DMPlexRestoreClosureIndices(wave.dm(), local, global, cells[i], PETSC_TRUE, &nc, &wave_cols, nullptr, nullptr));
    for (int b = 0; b < kMaxHeatNodes && p[3 + b] >= 0; ++b) rows_here.push_back(static_cast<PetscInt>(p[3 + b]));
    values.assign(rows_here.size() * nc, 0.0);
    for (std::size_t h = 0; h < rows_here.size(); ++h)
      for (int a = 0; a < nb; ++a)
        for (int k = 0; k < 2; ++k) {  // ∂φ_a/∂x_k of the dof (node a, component k)
          const double d = dphi[2 * a] * iJ[k] + dphi[2 * a + 1] * iJ[2 + k];
          values[h * nc + 2 * a + k] = p[2] * p[3 + kMaxHeatNodes + h] * kernel(phi[a], d);
        }
    PetscCall(MatSetValues(B, static_cast<PetscInt>(rows_here.size()), rows_here.data(), nc, cols_here.data(),
                           values.data(), ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(B, MAT_FINAL_ASSEMBLY));
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
