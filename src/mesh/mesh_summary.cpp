#include "vibrotherm/mesh/mesh_summary.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::mesh {
namespace {

PetscErrorCode CountOwned(DM dm, PetscInt depth, PetscInt* count) {
  PetscFunctionBeginUser;
  std::vector<bool> ghost;
  PetscCall(GhostPoints(dm, &ghost));
  PetscInt pStart, pEnd, chart0, mine = 0;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(DMPlexGetDepthStratum(dm, depth, &pStart, &pEnd));
  for (PetscInt p = pStart; p < pEnd; ++p) mine += !ghost[p - chart0];
  PetscCallMPI(MPI_Allreduce(&mine, count, 1, MPIU_INT, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

PetscErrorCode EdgeLength(const VertexCoordinates& x, DM dm, PetscInt edge, double* length) {
  PetscFunctionBeginUser;
  const PetscInt* cone;
  PetscCall(DMPlexGetCone(dm, edge, &cone));
  const auto a = x(cone[0]), b = x(cone[1]);
  *length = std::hypot(b[0] - a[0], b[1] - a[1]);
  PetscFunctionReturn(0);
}

/// The heat mesh's cells per rank and in all, and its edge length range, from this rank's.
PetscErrorCode ShareHeatMeshCounts(MPI_Comm comm, PetscInt local, double h_min, double h_max, MeshSummary* s) {
  PetscFunctionBeginUser;
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  s->heat_cells_per_rank.assign(size, 0);
  PetscCallMPI(MPI_Allgather(&local, 1, MPIU_INT, s->heat_cells_per_rank.data(), 1, MPIU_INT, comm));
  PetscCallMPI(MPI_Allreduce(&local, &s->heat_cells, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&h_min, &s->heat_h_min, 1, MPI_DOUBLE, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(&h_max, &s->heat_h_max, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscFunctionReturn(0);
}

/// Cells, vertices, edge lengths and cells per rank of the heat mesh.
PetscErrorCode SummariseHeatMesh(const Specimen& specimen, MeshSummary* s) {
  PetscFunctionBeginUser;
  DM dm = specimen.heat;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  s->heat_source = specimen.heat_source;
  PetscCall(CountOwned(dm, 0, &s->heat_vertices));
  VertexCoordinates x;
  PetscCall(x.Setup(dm));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  double h_min = INFINITY, h_max = 0.0;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    const PetscInt* cone;
    PetscInt n;
    PetscCall(DMPlexGetConeSize(dm, c, &n));
    PetscCall(DMPlexGetCone(dm, c, &cone));
    for (PetscInt k = 0; k < n; ++k) {
      double h = 0.0;
      PetscCall(EdgeLength(x, dm, cone[k], &h));
      h_min = std::min(h_min, h);
      h_max = std::max(h_max, h);
    }
  }
  PetscCall(ShareHeatMeshCounts(comm, cEnd - cStart, h_min, h_max, s));  // no overlap: every cell is owned
  PetscFunctionReturn(0);
}

/// Per crack, this rank's crack-tip vertices (labelled crack_tip), each attributed
/// to the crack of a face it bounds.
PetscErrorCode CountCrackTips(DM dm, DMLabel crack, DMLabel tip, const std::vector<bool>& ghost, PetscInt chart0,
                              std::vector<PetscInt>* tips) {
  PetscFunctionBeginUser;
  IS tip_is;
  PetscCall(DMLabelGetStratumIS(tip, 1, &tip_is));
  if (tip_is) {
    PetscInt n;
    const PetscInt* v;
    PetscCall(ISGetLocalSize(tip_is, &n));
    PetscCall(ISGetIndices(tip_is, &v));
    for (PetscInt i = 0; i < n; ++i) {
      if (ghost[v[i] - chart0]) continue;
      const PetscInt* support;
      PetscInt ns;
      PetscCall(DMPlexGetSupportSize(dm, v[i], &ns));
      PetscCall(DMPlexGetSupport(dm, v[i], &support));
      for (PetscInt k = 0; k < ns; ++k) {
        PetscInt id;
        PetscCall(DMLabelGetValue(crack, support[k], &id));
        if (id >= 1) {
          ++(*tips)[id - 1];
          break;
        }
      }
    }
    PetscCall(ISRestoreIndices(tip_is, &v));
    PetscCall(ISDestroy(&tip_is));
  }
  PetscFunctionReturn(0);
}

/// Per crack: this rank's counts and length summed over the ranks.
PetscErrorCode SummariseCracks(MPI_Comm comm, const Specimen& specimen, const std::vector<PetscInt>& facets,
                               const std::vector<PetscInt>& pairs, const std::vector<PetscInt>& tips,
                               const std::vector<double>& length, MeshSummary* s) {
  PetscFunctionBeginUser;
  const std::size_t nc = specimen.cracks.size();
  s->cracks.assign(nc, CrackSummary{});
  for (std::size_t i = 0; i < nc; ++i) {
    CrackSummary& cs = s->cracks[i];
    cs.name = specimen.cracks[i].name;
    cs.requested_length = specimen.cracks[i].requested_length;
    cs.breaks = specimen.cracks[i].breaks;
    PetscCallMPI(MPI_Allreduce(&facets[i], &cs.facets, 1, MPIU_INT, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(&pairs[i], &cs.node_pairs, 1, MPIU_INT, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(&tips[i], &cs.tips, 1, MPIU_INT, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(&length[i], &cs.length, 1, MPI_DOUBLE, MPI_SUM, comm));
  }
  PetscFunctionReturn(0);
}

/// 3D: shortest and longest edge of this rank's mesh.
PetscErrorCode EdgeRange(DM dm, double* h_min, double* h_max) {
  PetscFunctionBeginUser;
  VertexPositions<3> x;
  PetscCall(x.Setup(dm));
  PetscInt eStart, eEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eStart, &eEnd));
  *h_min = INFINITY, *h_max = 0.0;
  for (PetscInt e = eStart; e < eEnd; ++e) {
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, e, &cone));
    const double h = geometry::Norm(geometry::Sub(x(cone[1]), x(cone[0])));
    if (h == 0.0) continue;  // a tensor edge of a cohesive cell at the crack front
    *h_min = std::min(*h_min, h), *h_max = std::max(*h_max, h);
  }
  PetscFunctionReturn(0);
}

/// 3D: one cohesive cell's area (its − face) and its owned tensor edges, split (pairs) or not (front).
PetscErrorCode CohesiveCell3D(DM dm, PetscInt c, const std::vector<bool>& ghost, PetscInt chart0,
                              std::set<PetscInt>* seen, CrackSummary* crack) {
  PetscFunctionBeginUser;
  const PetscInt *cone, *faces;
  PetscInt nfaces;
  PetscCall(DMPlexGetCone(dm, c, &cone));
  PetscReal area, centre[3], normal[3];
  PetscCall(DMPlexComputeCellGeometryFVM(dm, cone[0], &area, centre, normal));
  crack->area += area;
  PetscCall(DMPlexGetConeSize(dm, c, &nfaces));
  PetscCall(DMPlexGetCone(dm, c, &faces));
  for (PetscInt k = 2; k < nfaces; ++k) {  // the tensor faces: (edge A, edge B, tensor edge, tensor edge)
    const PetscInt* edges;
    PetscCall(DMPlexGetCone(dm, faces[k], &edges));
    for (int j = 2; j < 4; ++j) {
      const PetscInt* pair;
      PetscCall(DMPlexGetCone(dm, edges[j], &pair));
      if (ghost[edges[j] - chart0] || !seen->insert(edges[j]).second) continue;
      if (pair[0] != pair[1]) ++crack->node_pairs;
      else ++crack->tips;
    }
  }
  PetscFunctionReturn(0);
}

/// Cells, vertices, edge lengths and cells per rank of the 3D heat box.
PetscErrorCode SummariseBoxHeatMesh(const Specimen& specimen, MeshSummary* s) {
  PetscFunctionBeginUser;
  DM dm = specimen.heat;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscCall(CountOwned(dm, 0, &s->heat_vertices));
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  double h[2];
  PetscCall(EdgeRange(dm, &h[0], &h[1]));
  PetscCall(ShareHeatMeshCounts(comm, cEnd - cStart, h[0], h[1], s));  // no overlap: every cell is owned
  PetscFunctionReturn(0);
}

/// 3D: the area of the faces labelled source, summed over the ranks (each face once).
PetscErrorCode SourceArea(DM dm, const std::vector<bool>& ghost, PetscInt chart0, double* area) {
  PetscFunctionBeginUser;
  double mine = 0.0;
  std::vector<PetscInt> faces;
  PetscCall(StratumPoints(dm, to_string(EdgeKind::Source), 1, &faces));
  for (PetscInt f : faces) {
    PetscReal a, c[3], normal[3];
    if (ghost[f - chart0]) continue;
    PetscCall(DMPlexComputeCellGeometryFVM(dm, f, &a, c, normal));
    mine += a;
  }
  PetscCallMPI(MPI_Allreduce(&mine, area, 1, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

/// The 3D box: bulk and cohesive cells, edge range, each crack's faces, area, split and front vertices.
PetscErrorCode ComputeBoxSummary(const Specimen& specimen, MeshSummary* s) {
  PetscFunctionBeginUser;
  DM dm = specimen.wave;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  std::vector<bool> ghost;
  PetscCall(GhostPoints(dm, &ghost));
  PetscInt chart0, cStart, cEnd, bulk = 0;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  DMLabel crack_label;
  PetscCall(DMGetLabel(dm, labels::crack, &crack_label));
  std::vector<CrackSummary> local(specimen.cracks.size());
  std::set<PetscInt> seen;
  PetscInt cohesive_cells = 0;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    PetscCall(IsCohesiveCell(dm, c, &cohesive));
    bulk += !cohesive;
    if (!cohesive) continue;
    const PetscInt* cone;
    PetscInt id;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    PetscCall(DMLabelGetValue(crack_label, cone[0], &id));
    PetscCheck(id >= 1 && id <= static_cast<PetscInt>(local.size()), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "cohesive cell %" PetscInt_FMT " has no crack label", c);
    ++cohesive_cells, ++local[id - 1].facets;
    PetscCall(CohesiveCell3D(dm, c, ghost, chart0, &seen, &local[id - 1]));
  }
  double h[2];
  PetscCall(EdgeRange(dm, &h[0], &h[1]));
  s->dimension = 3, s->cell_type = "hex", s->heat_source = specimen.heat_source;
  PetscCallMPI(MPI_Allreduce(&bulk, &s->cells, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&cohesive_cells, &s->cohesive_cells, 1, MPIU_INT, MPI_SUM, comm));
  s->cells_per_rank.assign(s->ranks, 0);
  PetscCallMPI(MPI_Allgather(&bulk, 1, MPIU_INT, s->cells_per_rank.data(), 1, MPIU_INT, comm));
  PetscCallMPI(MPI_Allreduce(&h[0], &s->h_min, 1, MPI_DOUBLE, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(&h[1], &s->h_max, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCall(CountOwned(dm, 0, &s->vertices));
  s->cracks.clear();
  for (std::size_t k = 0; k < local.size(); ++k) {
    CrackSummary crack;
    crack.name = specimen.cracks[k].name;
    crack.requested_length = specimen.cracks[k].requested_length;
    crack.breaks = specimen.cracks[k].breaks;
    PetscCallMPI(MPI_Allreduce(&local[k].facets, &crack.facets, 1, MPIU_INT, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(&local[k].node_pairs, &crack.node_pairs, 1, MPIU_INT, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(&local[k].tips, &crack.tips, 1, MPIU_INT, MPI_SUM, comm));
    PetscCallMPI(MPI_Allreduce(&local[k].area, &crack.area, 1, MPI_DOUBLE, MPI_SUM, comm));
    s->cracks.push_back(crack);
  }
  PetscCall(SourceArea(dm, ghost, chart0, &s->source_area));
  PetscCall(SummariseBoxHeatMesh(specimen, s));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ComputeMeshSummary(const Specimen& specimen, MeshSummary* s) {
  PetscFunctionBeginUser;
  DM dm = specimen.wave;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt dim;
  PetscMPIInt size;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  s->ranks = size;
  s->source = specimen.source;
  if (dim == 3) PetscFunctionReturn(ComputeBoxSummary(specimen, s));
  VertexCoordinates x;
  PetscCall(x.Setup(dm));
  DMLabel crack, tip;
  PetscCall(DMGetLabel(dm, labels::crack, &crack));
  PetscCall(DMGetLabel(dm, labels::crack_tip, &tip));

  const std::size_t nc = specimen.cracks.size();
  std::vector<PetscInt> facets(nc, 0), pairs(nc, 0), tips(nc, 0);
  std::vector<double> length(nc, 0.0);
  std::vector<bool> ghost;
  PetscCall(GhostPoints(dm, &ghost));
  PetscInt chart0, cStart, cEnd, bulk = 0, cohesive = 0;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  double h_min = INFINITY, h_max = 0.0;
  PetscInt corners = 0;
  std::set<PetscInt> tensor_edges_seen;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool is_cohesive;
    PetscCall(IsCohesiveCell(dm, c, &is_cohesive));
    const PetscInt* cone;
    PetscInt cone_size;
    PetscCall(DMPlexGetConeSize(dm, c, &cone_size));
    PetscCall(DMPlexGetCone(dm, c, &cone));
    if (!is_cohesive) {
      ++bulk;
      corners = cone_size;
      for (PetscInt k = 0; k < cone_size; ++k) {
        double h = 0.0;
        PetscCall(EdgeLength(x, dm, cone[k], &h));
        h_min = std::min(h_min, h);
        h_max = std::max(h_max, h);
      }
      continue;
    }
    ++cohesive;  // cohesive cells are never ghosts (no overlap)
    PetscInt id;
    PetscCall(DMLabelGetValue(crack, cone[0], &id));
    PetscCheck(id >= 1 && id <= static_cast<PetscInt>(nc), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "cohesive cell %" PetscInt_FMT " has no crack label", c);
    for (PetscInt k = 2; k < 4; ++k) {  // tensor edges: (side A, side B) vertex pairs
      const PetscInt* pair;
      PetscCall(DMPlexGetCone(dm, cone[k], &pair));
      if (pair[0] != pair[1] && !ghost[cone[k] - chart0] && tensor_edges_seen.insert(cone[k]).second) ++pairs[id - 1];
    }
  }
  PetscCall(CountCrackTips(dm, crack, tip, ghost, chart0, &tips));
  for (const OwnedCrackFacet& owned : specimen.wave_cracks.owned()) {  // this rank's cohesive cells, in order
    const geometry::CrackFacet& f = specimen.wave_cracks.facets()[owned.index];
    ++facets[f.crack];
    length[f.crack] += geometry::Measure(f);
  }

  PetscCallMPI(MPI_Allreduce(&bulk, &s->cells, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&cohesive, &s->cohesive_cells, 1, MPIU_INT, MPI_SUM, comm));
  s->cells_per_rank.assign(size, 0);
  PetscCallMPI(MPI_Allgather(&bulk, 1, MPIU_INT, s->cells_per_rank.data(), 1, MPIU_INT, comm));
  PetscCallMPI(MPI_Allreduce(&h_min, &s->h_min, 1, MPI_DOUBLE, MPI_MIN, comm));
  PetscCallMPI(MPI_Allreduce(&h_max, &s->h_max, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &corners, 1, MPIU_INT, MPI_MAX, comm));
  s->cell_type = corners == 4 ? "quad" : "tri";
  PetscCall(CountOwned(dm, 0, &s->vertices));
  PetscCall(SummariseHeatMesh(specimen, s));
  PetscCall(SummariseCracks(comm, specimen, facets, pairs, tips, length, s));
  PetscFunctionReturn(0);
}

PetscErrorCode PrintMeshSummary(MPI_Comm comm, const MeshSummary& s) {
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "Mesh (%s): %" PetscInt_FMT " %s cells, %" PetscInt_FMT " vertices, %" PetscInt_FMT
                              " cohesive cells, %d rank%s\n",
                        s.source.c_str(), s.cells, s.cell_type.c_str(), s.vertices, s.cohesive_cells, s.ranks,
                        s.ranks > 1 ? "s" : ""));
  PetscCall(PetscPrintf(comm, "  element edge length: min %.4g m, max %.4g m\n", s.h_min, s.h_max));
  if (s.ranks > 1) {
    PetscCall(PetscPrintf(comm, "  cells per rank:"));
    for (PetscInt n : s.cells_per_rank) PetscCall(PetscPrintf(comm, " %" PetscInt_FMT, n));
    PetscCall(PetscPrintf(comm, "\n"));
  }
  for (const CrackSummary& c : s.cracks)
    if (s.dimension == 3)
      PetscCall(PetscPrintf(comm,
                            "  %s: %" PetscInt_FMT " faces (= cohesive cells), %" PetscInt_FMT " split vertices, %"
                            PetscInt_FMT " front vertices, area %.6g m^2\n",
                            c.name.c_str(), c.facets, c.node_pairs, c.tips, c.area));
    else
      PetscCall(PetscPrintf(comm, "  %s: %" PetscInt_FMT " facets, %" PetscInt_FMT " contact node pairs, %" PetscInt_FMT
                                  " buried tips, length %.6g m\n",
                            c.name.c_str(), c.facets, c.node_pairs, c.tips, c.length));
  if (s.cracks.empty()) PetscCall(PetscPrintf(comm, "  no cracks\n"));
  if (s.dimension == 3) PetscCall(PetscPrintf(comm, "  source faces: area %.6g m^2\n", s.source_area));
  PetscCall(PetscPrintf(comm, "Heat mesh (%s): %" PetscInt_FMT " cells, %" PetscInt_FMT
                              " vertices, element edge length min %.3g m, max %.3g m\n",
                        s.heat_source.c_str(), s.heat_cells, s.heat_vertices, s.heat_h_min, s.heat_h_max));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
