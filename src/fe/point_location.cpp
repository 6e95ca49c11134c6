#include "vibrotherm/fe/point_location.hpp"

#include <algorithm>
#include <climits>

namespace vibrotherm::fe {

PetscErrorCode LocatePoints(const LagrangeSpace& space, const std::vector<double>& xy,
                            std::vector<LocatedPoint>* points, std::vector<bool>* inside) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)space.dm());
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const std::size_t D = static_cast<std::size_t>(space.dim()), n = xy.size() / D;
  points->assign(n, LocatedPoint{});
  std::vector<ReferencePoint> refs(n);
  std::vector<int> mine(n, INT_MAX), owner(n);
  for (std::size_t i = 0; i < n; ++i) {
    PetscCall(space.Locate(&xy[D * i], &(*points)[i].cell, &refs[i]));
    if ((*points)[i].cell >= 0) mine[i] = rank;
  }
  if (n > 0) PetscCallMPI(MPI_Allreduce(mine.data(), owner.data(), static_cast<int>(n), MPI_INT, MPI_MIN, comm));
  inside->assign(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    (*inside)[i] = owner[i] != INT_MAX;
    LocatedPoint& p = (*points)[i];
    if (owner[i] != rank) p.cell = -1;
    if (p.cell >= 0) PetscCall(space.BasisAt(refs[i], &p.phi));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode EvaluateScalarAtPoints(const LagrangeSpace& space, Vec local, const std::vector<LocatedPoint>& points,
                                      std::vector<double>* values) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  std::vector<double> mine(points.size(), 0.0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (points[p].cell < 0) continue;
    PetscScalar* c = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm, section, local, points[p].cell, &n, &c));
    for (std::size_t b = 0; b < points[p].phi.size(); ++b) mine[p] += points[p].phi[b] * PetscRealPart(c[b]);
    PetscCall(DMPlexVecRestoreClosure(dm, section, local, points[p].cell, &n, &c));
  }
  values->assign(points.size(), 0.0);
  if (!points.empty())
    PetscCallMPI(MPI_Allreduce(mine.data(), values->data(), static_cast<int>(mine.size()), MPI_DOUBLE, MPI_SUM,
                               PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::fe
