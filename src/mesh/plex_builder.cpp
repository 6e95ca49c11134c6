#include "vibrotherm/mesh/plex_builder.hpp"

#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::mesh {
namespace {

/// Sets label `name` on the DM face joining each edge's vertices (value from value_of(edge)).
template <class ValueOf>
PetscErrorCode MarkEdges(DM dm, const char* name, const std::vector<MeshEdge>& edges, ValueOf value_of) {
  PetscFunctionBeginUser;
  PetscCall(DMCreateLabel(dm, name));
  DMLabel label;
  PetscCall(DMGetLabel(dm, name, &label));
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  for (const MeshEdge& e : edges) {
    const PetscInt verts[2] = {vStart + e.v0, vStart + e.v1};
    PetscInt n;
    const PetscInt* join;
    PetscCall(DMPlexGetJoin(dm, 2, verts, &n, &join));
    PetscCheck(n == 1, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
               "mesh: labelled edge (%d, %d) is not an edge of the 2D mesh (non-conforming mesh?)", e.v0, e.v1);
    PetscCall(DMLabelSetValue(label, join[0], value_of(e)));
    PetscCall(DMPlexRestoreJoin(dm, 2, verts, &n, &join));
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode CreateSerialPlex(MPI_Comm comm, const MeshData& mesh, DM* dm) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const bool root = rank == 0;
  std::vector<PetscInt> cells(mesh.cells.begin(), mesh.cells.end());
  PetscCall(DMPlexCreateFromCellListPetsc(comm, 2, root ? mesh.cell_count() : 0, root ? mesh.vertex_count() : 0,
                                          mesh.corners, PETSC_TRUE, root ? cells.data() : nullptr, 2,
                                          root ? mesh.coords.data() : nullptr, dm));
  PetscCall(PetscObjectSetName((PetscObject)*dm, "specimen"));
  auto none = std::vector<MeshEdge>{};
  PetscCall(MarkEdges(*dm, labels::crack, root ? mesh.crack_edges : none, [](const MeshEdge& e) { return e.tag + 1; }));
  PetscCall(MarkEdges(*dm, labels::side, root ? mesh.side_edges : none, [](const MeshEdge& e) { return e.tag; }));
  PetscCall(MarkEdges(*dm, labels::sink, root ? mesh.sink_edges : none, [](const MeshEdge&) { return 1; }));
  for (EdgeKind kind : all_edge_kinds()) {
    std::vector<MeshEdge> of_kind;
    if (root)
      for (const MeshEdge& e : mesh.kind_edges)
        if (e.tag == static_cast<int>(kind)) of_kind.push_back(e);
    PetscCall(MarkEdges(*dm, to_string(kind), of_kind, [](const MeshEdge&) { return 1; }));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LabelCrackFacetsAndTips(DM dm, const std::vector<std::string>& crack_names) {
  PetscFunctionBeginUser;
  DMLabel crack, facet_id, tip;
  PetscCall(DMGetLabel(dm, labels::crack, &crack));
  PetscCall(DMCreateLabel(dm, labels::crack_face));
  PetscCall(DMGetLabel(dm, labels::crack_face, &facet_id));
  PetscCall(DMCreateLabel(dm, labels::crack_tip));
  PetscCall(DMGetLabel(dm, labels::crack_tip, &tip));
  PetscInt fStart, fEnd;
  PetscCall(FacetRange(dm, &fStart, &fEnd));
  VertexCoordinates x;
  PetscCall(x.Setup(dm));
  PetscInt next_id = 0;
  for (std::size_t c = 0; c < crack_names.size(); ++c) {
    // Faces of this crack (refinement also labels vertices: keep faces only).
    std::map<PetscInt, std::vector<PetscInt>> faces_at;  // vertex → crack faces
    PetscInt count = 0;
    for (PetscInt f = fStart; f < fEnd; ++f) {
      PetscInt v;
      PetscCall(DMLabelGetValue(crack, f, &v));
      if (v != static_cast<PetscInt>(c) + 1) continue;
      const PetscInt* cone;
      PetscCall(DMPlexGetCone(dm, f, &cone));
      faces_at[cone[0]].push_back(f);
      faces_at[cone[1]].push_back(f);
      ++count;
    }
    if (count == 0) continue;  // rank without the mesh
    // ξ runs from the end with the smaller x (then y): the same direction on every mesh of the specimen.
    PetscInt start = -1;
    std::array<double, 2> start_x{};
    for (const auto& [v, faces] : faces_at) {
      PetscCheck(faces.size() <= 2, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
                 "mesh: %s branches (a vertex joins %zu crack edges)", crack_names[c].c_str(), faces.size());
      if (faces.size() != 1) continue;
      const auto p = x(v);
      const double tol = 1e-12 * (std::abs(p[0]) + std::abs(start_x[0]) + 1e-300);
      if (start < 0 || p[0] < start_x[0] - tol || (std::abs(p[0] - start_x[0]) <= tol && p[1] < start_x[1]))
        start = v, start_x = p;
    }
    PetscCheck(start >= 0, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "mesh: %s is a closed loop", crack_names[c].c_str());
    // Walk from the start vertex, numbering faces in order.
    PetscInt v = start, prev_face = -1, walked = 0;
    for (;;) {
      PetscInt face = -1;
      for (PetscInt f : faces_at[v])
        if (f != prev_face) face = f;
      if (face < 0) break;
      PetscCall(DMLabelSetValue(facet_id, face, next_id++));
      ++walked;
      const PetscInt* cone;
      PetscCall(DMPlexGetCone(dm, face, &cone));
      v = cone[0] == v ? cone[1] : cone[0];
      prev_face = face;
    }
    PetscCheck(walked == count, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "mesh: %s is not one connected line",
               crack_names[c].c_str());
    // Tips: ends of the crack that touch no outer face.
    for (const auto& [vertex, faces] : faces_at) {
      if (faces.size() != 1) continue;
      const PetscInt* support;
      PetscInt nsupport;
      PetscCall(DMPlexGetSupportSize(dm, vertex, &nsupport));
      PetscCall(DMPlexGetSupport(dm, vertex, &support));
      bool outer = false;
      for (PetscInt s = 0; s < nsupport; ++s) {
        PetscInt cells;
        PetscCall(DMPlexGetSupportSize(dm, support[s], &cells));
        outer = outer || cells == 1;
      }
      if (!outer) PetscCall(DMLabelSetValue(tip, vertex, 1));
    }
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
