#include "vibrotherm/mesh/crack_surface.hpp"

#include <petscdmplex.h>

#include <cmath>

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/util/all_gather.hpp"

namespace vibrotherm::mesh {
namespace {

constexpr std::size_t kPacked = 6;  // id, crack, x0, y0, x1, y1

/// This rank's cohesive cells, and whether the mesh is split (has them on some rank). Collective.
PetscErrorCode CohesiveCellsIfSplit(DM dm, std::vector<PetscInt>* cells, bool* split) {
  PetscFunctionBeginUser;
  PetscCall(mesh::CohesiveCells(dm, cells));
  int any = !cells->empty();
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, PetscObjectComm((PetscObject)dm)));
  *split = any;
  PetscFunctionReturn(0);
}

/// The owned labelled crack facets of an unsplit mesh, in point order.
PetscErrorCode LabelledFacets(DM dm, DMLabel crack_label, DMLabel ids, std::vector<PetscInt>* facets) {
  PetscFunctionBeginUser;
  std::vector<bool> ghost;
  PetscCall(GhostPoints(dm, &ghost));
  PetscInt chart0, fStart, fEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(FacetRange(dm, &fStart, &fEnd));
  for (PetscInt f = fStart; f < fEnd && crack_label && ids; ++f) {
    PetscInt c, id;
    PetscCall(DMLabelGetValue(crack_label, f, &c));
    PetscCall(DMLabelGetValue(ids, f, &id));
    if (c >= 1 && id >= 0 && !ghost[f - chart0]) facets->push_back(f);
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode CrackSurface::CollectOwned(DM dm, std::vector<double>* packed) {
  PetscFunctionBeginUser;
  DMLabel crack_label, ids;
  PetscCall(DMGetLabel(dm, labels::crack, &crack_label));
  PetscCall(DMGetLabel(dm, labels::crack_face, &ids));
  std::vector<PetscInt> points;
  bool split = false;
  PetscCall(CohesiveCellsIfSplit(dm, &points, &split));
  if (!split) PetscCall(LabelledFacets(dm, crack_label, ids, &points));
  VertexCoordinates x;
  PetscCall(x.Setup(dm));
  owned_.clear();
  for (PetscInt point : points) {
    PetscInt facet = point, id, crack;
    if (split) {
      const PetscInt* cone;
      PetscCall(DMPlexGetCone(dm, point, &cone));
      facet = cone[0];
    }
    PetscCall(DMLabelGetValue(ids, facet, &id));
    PetscCall(DMLabelGetValue(crack_label, facet, &crack));
    const PetscInt* vertices;
    PetscCall(DMPlexGetCone(dm, facet, &vertices));
    const auto p0 = x(vertices[0]), p1 = x(vertices[1]);
    packed->insert(packed->end(), {double(id), double(crack - 1), p0[0], p0[1], p1[0], p1[1]});
    owned_.push_back({point, facet, 0});
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CrackSurface::Setup(DM dm, PetscInt ncracks) {
  PetscFunctionBeginUser;
  *this = CrackSurface{};  // a 3D mesh keeps it empty
  PetscInt dim;
  PetscCall(DMGetDimension(dm, &dim));
  if (dim != 2) PetscFunctionReturn(0);  // crack lines only: a 3D crack's faces are read from its labels
  std::vector<double> mine, all;
  PetscCall(CollectOwned(dm, &mine));
  PetscCall(util::AllGather(PetscObjectComm((PetscObject)dm), mine, &all));
  for (std::size_t k = 0; k + kPacked <= all.size(); k += kPacked)
    facets_.push_back({std::lround(all[k]), static_cast<int>(all[k + 1]), {all[k + 2], all[k + 3]},
                       {all[k + 4], all[k + 5]}});
  // This rank's entries follow those of the ranks before it.
  PetscInt before = 0, count = static_cast<PetscInt>(owned_.size());
  PetscCallMPI(MPI_Exscan(&count, &before, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)dm), &rank));
  if (rank == 0) before = 0;
  for (std::size_t k = 0; k < owned_.size(); ++k) owned_[k].index = static_cast<std::size_t>(before) + k;
  lines_.assign(ncracks, CrackLine{});
  for (PetscInt c = 0; c < ncracks; ++c) lines_[c].Build(facets_, static_cast<int>(c));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
