#include "vibrotherm/coupling/exchange/surface_transfer.hpp"

#include <petscdmplex.h>

#include <algorithm>

#include "vibrotherm/fe/point_owners.hpp"
#include "vibrotherm/util/two_pass_matrix.hpp"

namespace vibrotherm::coupling {
namespace {

constexpr std::size_t kPointFields = 4;  ///< x, y, z, area

/// This rank's points, packed (kPointFields doubles each).
std::vector<double> PackPoints(const SurfacePoints& mine) {
  std::vector<double> packed;
  for (std::size_t p = 0; p < mine.size(); ++p)
    packed.insert(packed.end(), {mine.x[p][0], mine.x[p][1], mine.x[p][2], mine.area[p]});
  return packed;
}

}  // namespace

SurfaceHeatTransfer::~SurfaceHeatTransfer() {
  (void)MatDestroy(&transfer_);
  (void)VecDestroy(&rate_);
}

PetscErrorCode SurfaceHeatTransfer::Setup(const fe::LagrangeSpace& heat, const SurfacePoints& mine) {
  PetscFunctionBeginUser;
  DM dm = heat.dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscCheck(mine.area.size() == mine.x.size(), PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "%zu areas for %zu points",
             mine.area.size(), mine.x.size());
  const std::vector<double> packed = PackPoints(mine);
  fe::CellLocator locator;
  PetscCall(locator.Setup(heat));
  util::PointExchange exchange;
  fe::LocatedPoints located;
  PetscCall(fe::LocateOnRanks(locator, comm, packed, kPointFields, &exchange, &located));
  if (located.lost.count > 0)
    SETERRQ(comm, PETSC_ERR_ARG_OUTOFRANGE, "surface heat source: the point (%g, %g, %g) is outside the heat mesh",
            located.lost.x[0], located.lost.x[1], located.lost.x[2]);
  Vec shape;
  PetscInt rows, global_rows;
  PetscCall(DMGetGlobalVector(dm, &shape));
  PetscCall(VecGetLocalSize(shape, &rows));
  PetscCall(VecGetSize(shape, &global_rows));
  PetscCall(DMRestoreGlobalVector(dm, &shape));
  const PetscInt n = exchange.counts().total, owned = static_cast<PetscInt>(mine.size());
  first_point_ = exchange.first();
  double area = 0.0;  // this rank's points in order, then the ranks' sums
  for (std::size_t p = 0; p < mine.size(); ++p) area += mine.area[p];
  PetscCallMPI(MPI_Allreduce(&area, &area_, 1, MPI_DOUBLE, MPI_SUM, comm));
  Mat pattern;  // a heat node at a crack meets a hundred points or more
  PetscCall(util::CreateTwoPassMatrices(comm, rows, owned, global_rows, n, &pattern, &transfer_));
  for (Mat T : {pattern, transfer_}) {
    if (T == transfer_) PetscCall(MatPreallocatorPreallocate(pattern, PETSC_TRUE, transfer_));
    for (std::size_t k : located.owned)
      PetscCall(AddColumn(heat, T, exchange.global_index(k), located.cells[k], located.refs[k],
                          exchange.received()[kPointFields * k + 3]));
    PetscCall(MatAssemblyBegin(T, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(T, MAT_FINAL_ASSEMBLY));
  }
  PetscCall(MatDestroy(&pattern));
  PetscCall(MatCreateVecs(transfer_, &rate_, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode SurfaceHeatTransfer::AddColumn(const fe::LagrangeSpace& heat, Mat T, PetscInt column, PetscInt cell,
                                              const fe::ReferencePoint& ref, double area) {
  PetscFunctionBeginUser;
  DM dm = heat.dm();
  PetscSection local, global;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  std::vector<double> psi;
  PetscCall(heat.BasisAt(ref, &psi));
  PetscInt nc, *idx = nullptr;
  PetscCall(DMPlexGetClosureIndices(dm, local, global, cell, PETSC_TRUE, &nc, &idx, nullptr, nullptr));
  for (PetscInt b = 0; b < nc; ++b) {
    const PetscInt row = idx[b] >= 0 ? idx[b] : -(idx[b] + 1);  // rows other ranks own: assembly moves them
    PetscCall(MatSetValue(T, row, column, area * psi[b], ADD_VALUES));
  }
  PetscCall(DMPlexRestoreClosureIndices(dm, local, global, cell, PETSC_TRUE, &nc, &idx, nullptr, nullptr));
  PetscFunctionReturn(0);
}

PetscErrorCode SurfaceHeatTransfer::AddRates(const std::vector<double>& density, Vec Q) {
  PetscFunctionBeginUser;
  PetscInt n;
  PetscCall(VecGetLocalSize(rate_, &n));
  PetscCheck(static_cast<PetscInt>(density.size()) == n, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "%zu densities for %" PetscInt_FMT " surface points", density.size(), n);
  PetscScalar* q;
  PetscCall(VecGetArray(rate_, &q));
  std::copy(density.begin(), density.end(), q);
  PetscCall(VecRestoreArray(rate_, &q));
  PetscCall(MatMultAdd(transfer_, rate_, Q, Q));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
