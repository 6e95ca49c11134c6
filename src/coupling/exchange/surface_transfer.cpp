#include "vibrotherm/coupling/exchange/surface_transfer.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <climits>

#include "vibrotherm/fe/cell_locator.hpp"
#include "vibrotherm/util/all_gather.hpp"
#include "vibrotherm/util/two_pass_matrix.hpp"

namespace vibrotherm::coupling {
namespace {

constexpr std::size_t kPointFields = 4;  ///< x, y, z, area

/// Every rank's points (kPointFields doubles each) on every rank, and this rank's first global index.
PetscErrorCode GatherPoints(MPI_Comm comm, const SurfacePoints& mine, std::vector<double>* all, PetscInt* first) {
  PetscFunctionBeginUser;
  std::vector<double> packed;
  for (std::size_t p = 0; p < mine.size(); ++p)
    packed.insert(packed.end(), {mine.x[p][0], mine.x[p][1], mine.x[p][2], mine.area[p]});
  PetscCall(util::AllGather(comm, packed, all));
  const PetscInt owned = static_cast<PetscInt>(mine.size());
  *first = 0;
  PetscCallMPI(MPI_Exscan(&owned, first, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) *first = 0;  // MPI_Exscan leaves rank 0's result undefined
  PetscFunctionReturn(0);
}

/// The local cell and reference point of every point, and the rank that adds it (the lowest holding it).
PetscErrorCode LocateOnce(const fe::LagrangeSpace& heat, const std::vector<double>& all, std::vector<PetscInt>* cells,
                          std::vector<fe::ReferencePoint>* refs, std::vector<int>* owner) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)heat.dm());
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const std::size_t n = all.size() / kPointFields;
  fe::CellLocator locator;
  PetscCall(locator.Setup(heat));
  cells->assign(n, -1);
  refs->assign(n, fe::ReferencePoint{});
  owner->assign(n, INT_MAX);
  for (std::size_t i = 0; i < n; ++i) {
    locator.Locate(&all[kPointFields * i], &(*cells)[i], &(*refs)[i]);
    if ((*cells)[i] >= 0) (*owner)[i] = rank;
  }
  if (n > 0) PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, owner->data(), static_cast<int>(n), MPI_INT, MPI_MIN, comm));
  const auto lost = std::find(owner->begin(), owner->end(), INT_MAX);
  if (lost != owner->end()) {
    const double* x = &all[kPointFields * static_cast<std::size_t>(lost - owner->begin())];
    SETERRQ(comm, PETSC_ERR_ARG_OUTOFRANGE, "surface heat source: the point (%g, %g, %g) is outside the heat mesh",
            x[0], x[1], x[2]);
  }
  PetscFunctionReturn(0);
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
  PetscCheck(heat.dim() == 3, comm, PETSC_ERR_SUP, "surface heat source: a 3D heat mesh is needed, this one is %dD",
             heat.dim());
  PetscCheck(mine.area.size() == mine.x.size(), PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "%zu areas for %zu points",
             mine.area.size(), mine.x.size());
  std::vector<double> all;
  PetscCall(GatherPoints(comm, mine, &all, &first_point_));
  std::vector<PetscInt> cells;
  std::vector<fe::ReferencePoint> refs;
  std::vector<int> owner;
  PetscCall(LocateOnce(heat, all, &cells, &refs, &owner));
  Vec shape;
  PetscInt rows, global_rows;
  PetscCall(DMGetGlobalVector(dm, &shape));
  PetscCall(VecGetLocalSize(shape, &rows));
  PetscCall(VecGetSize(shape, &global_rows));
  PetscCall(DMRestoreGlobalVector(dm, &shape));
  const PetscInt n = static_cast<PetscInt>(owner.size()), owned = static_cast<PetscInt>(mine.size());
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  area_ = 0.0;
  for (PetscInt i = 0; i < n; ++i) area_ += all[kPointFields * i + 3];
  Mat pattern;  // a heat node at a crack meets a hundred points or more
  PetscCall(util::CreateTwoPassMatrices(comm, rows, owned, global_rows, n, &pattern, &transfer_));
  for (Mat T : {pattern, transfer_}) {
    if (T == transfer_) PetscCall(MatPreallocatorPreallocate(pattern, PETSC_TRUE, transfer_));
    for (PetscInt i = 0; i < n; ++i)
      if (owner[i] == rank) PetscCall(AddColumn(heat, T, i, cells[i], refs[i], all[kPointFields * i + 3]));
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
