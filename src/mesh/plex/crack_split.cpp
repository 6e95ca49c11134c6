// The PyLith recipe: crack faces and their vertices in a "fault" label; the crack
// submesh, oriented, gives through its subpoint map the side of every point;
// DMPlexLabelCohesiveComplete completes it, DMPlexConstructCohesiveCells splits.
#include "vibrotherm/mesh/plex/crack_split.hpp"

#include <map>
#include <vector>

#include "vibrotherm/geometry/crack_chord.hpp"
#include "vibrotherm/geometry/frame.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::mesh {
namespace {

/// In 3D, adds the crack front to `front` (value 1): the edges of crack faces with
/// exactly one crack face in their support, not on the outer boundary, and their
/// vertices. PETSc 3.18 silently grows a buried crack by one cell layer unless
/// both are in the boundary label (../shared/design/3D-NOTES.md §2). In 2D the
/// front is the tip vertices the mesher labels.
PetscErrorCode LabelCrackFront(DM dm, DMLabel fault, DMLabel front) {
  PetscFunctionBeginUser;
  PetscInt dim;
  PetscCall(DMGetDimension(dm, &dim));
  if (dim < 3) PetscFunctionReturn(0);
  PetscInt eStart, eEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eStart, &eEnd));
  for (PetscInt e = eStart; e < eEnd; ++e) {
    PetscInt nfaces, crack_faces = 0, value;
    bool on_boundary = false;
    const PetscInt* faces;
    PetscCall(DMPlexGetSupportSize(dm, e, &nfaces));
    PetscCall(DMPlexGetSupport(dm, e, &faces));
    for (PetscInt i = 0; i < nfaces; ++i) {
      PetscInt cells;
      PetscCall(DMPlexGetSupportSize(dm, faces[i], &cells));
      on_boundary = on_boundary || cells == 1;
      PetscCall(DMLabelGetValue(fault, faces[i], &value));
      if (value == 1) ++crack_faces;
    }
    if (crack_faces != 1 || on_boundary) continue;
    const PetscInt* ends;
    PetscCall(DMPlexGetCone(dm, e, &ends));
    PetscCall(DMLabelSetValue(front, e, 1));
    for (int k = 0; k < 2; ++k) PetscCall(DMLabelSetValue(front, ends[k], 1));
  }
  PetscFunctionReturn(0);
}

/// The split must add one cohesive cell per crack face, no more: the check the
/// 3.18 front defect fails silently (DMPlexCheck* pass).
PetscErrorCode CheckCohesiveCount(DM split, PetscInt crack_faces) {
  PetscFunctionBeginUser;
  std::vector<PetscInt> cells;
  PetscCall(CohesiveCells(split, &cells));
  const PetscInt cohesive = static_cast<PetscInt>(cells.size());
  PetscCheck(cohesive == crack_faces, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "crack split: %" PetscInt_FMT " cohesive cells for %" PetscInt_FMT " crack faces (the crack grew)",
             cohesive, crack_faces);
  PetscFunctionReturn(0);
}

/// The bulk neighbour of a cohesive cell's first face (cone[0], either side) on the serial split mesh.
PetscErrorCode BulkNeighbour(DM split, PetscInt cohesive, PetscInt* face, PetscInt* bulk) {
  PetscFunctionBeginUser;
  const PetscInt *cone, *support;
  PetscInt size;
  PetscCall(DMPlexGetCone(split, cohesive, &cone));
  PetscCall(DMPlexGetSupportSize(split, cone[0], &size));
  PetscCall(DMPlexGetSupport(split, cone[0], &support));
  PetscCheck(size == 2, PETSC_COMM_SELF, PETSC_ERR_PLIB, "crack split: a crack face with %" PetscInt_FMT
             " cells around it (a bulk cell and its cohesive cell expected)", size);
  *face = cone[0];
  *bulk = support[0] == cohesive ? support[1] : support[0];
  PetscFunctionReturn(0);
}

/// Where each cohesive cell's first face is and the crack normal there, by the dimension's
/// convention: 3D the oriented normal of the face (geometry/frame.hpp), 2D the facet's
/// tangent along its crack's chord turned by +90° (geometry/crack_chord.hpp).
template <int D>
class CrackNormals;

template <>
class CrackNormals<3> {
 public:
  PetscErrorCode Setup(DM, const VertexPositions<3>&, const std::vector<PetscInt>&) { return 0; }
  PetscErrorCode At(DM split, PetscInt face, geometry::Point<3>* centre, geometry::Point<3>* n) const {
    PetscFunctionBeginUser;
    PetscReal area, c[3], normal[3];
    PetscCall(DMPlexComputeCellGeometryFVM(split, face, &area, c, normal));
    *centre = {c[0], c[1], c[2]};
    *n = geometry::OrientedCrackNormal({normal[0], normal[1], normal[2]});
    PetscFunctionReturn(0);
  }
};

template <>
class CrackNormals<2> {
 public:
  /// The crack facets of the cohesive cells' first faces, and their cracks' chords (from every
  /// facet of each crack: the mesh is serial, so all are here).
  PetscErrorCode Setup(DM split, const VertexPositions<2>& x, const std::vector<PetscInt>& cohesive) {
    PetscFunctionBeginUser;
    DMLabel crack, ids;
    PetscCall(DMGetLabel(split, labels::crack, &crack));
    PetscCall(DMGetLabel(split, labels::crack_face, &ids));
    PetscCheck(crack && ids, PETSC_COMM_SELF, PETSC_ERR_PLIB, "crack split: no %s or %s label", labels::crack,
               labels::crack_face);
    std::vector<geometry::CrackFacet> facets;
    for (PetscInt c : cohesive) {
      const PetscInt *cone, *ends;
      PetscCall(DMPlexGetCone(split, c, &cone));
      PetscCall(DMPlexGetCone(split, cone[0], &ends));
      PetscInt id, k;
      PetscCall(DMLabelGetValue(ids, cone[0], &id));
      PetscCall(DMLabelGetValue(crack, cone[0], &k));
      PetscCheck(id >= 0 && k >= 1, PETSC_COMM_SELF, PETSC_ERR_PLIB,
                 "crack split: a crack face without its %s id or %s number", labels::crack_face, labels::crack);
      facets_[cone[0]] = {id, static_cast<int>(k - 1), x(ends[0]), x(ends[1])};
      facets.push_back(facets_[cone[0]]);
    }
    chords_ = geometry::CrackChords(facets);
    PetscFunctionReturn(0);
  }
  PetscErrorCode At(DM, PetscInt face, geometry::Point<2>* centre, geometry::Point<2>* n) const {
    const geometry::CrackFacet& f = facets_.at(face);
    *centre = {0.5 * (f.p0[0] + f.p1[0]), 0.5 * (f.p0[1] + f.p1[1])};
    *n = geometry::FrameFromTangent(geometry::TangentAlong(f, chords_.at(f.crack))).normal;
    return 0;
  }

 private:
  std::map<PetscInt, geometry::CrackFacet> facets_;
  std::map<int, geometry::CrackChord> chords_;
};

/// Labels crack_plus the face of each cohesive cell whose bulk neighbour lies along the
/// crack normal, on the serial split mesh (both neighbours there): the side survives
/// distribution, where a cohesive cell may lose both neighbours.
template <int D>
PetscErrorCode LabelPlusFaces(DM split) {
  PetscFunctionBeginUser;
  PetscBool distributed;
  PetscCall(DMPlexIsDistributed(split, &distributed));
  PetscCheck(!distributed, PETSC_COMM_SELF, PETSC_ERR_PLIB, "crack split: the + faces are labelled on a serial mesh");
  PetscCall(DMCreateLabel(split, labels::crack_plus));
  std::vector<PetscInt> cohesive;
  PetscCall(CohesiveCells(split, &cohesive));
  VertexPositions<D> x;
  PetscCall(x.Setup(split));
  CrackNormals<D> normals;
  PetscCall(normals.Setup(split, x, cohesive));
  for (PetscInt c : cohesive) {
    PetscInt face, bulk;
    PetscCall(BulkNeighbour(split, c, &face, &bulk));
    geometry::Point<D> centre{}, n{}, inside{};
    PetscCall(normals.At(split, face, &centre, &n));
    PetscCall(CellCentroid(split, x, bulk, &inside));
    const bool along = geometry::Dot(geometry::Sub(inside, centre), n) > 0.0;
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(split, c, &cone));
    PetscCall(DMSetLabelValue(split, labels::crack_plus, cone[along ? 0 : 1], 1));
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode SplitCracks(DM dm, DM* split) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  DMLabel crack, tips;
  PetscCall(DMGetLabel(dm, labels::crack, &crack));
  PetscCall(DMGetLabel(dm, labels::crack_tip, &tips));
  PetscInt fStart, fEnd, nfaces = 0, total = 0;
  PetscCall(FacetRange(dm, &fStart, &fEnd));

  DMLabel fault;
  PetscCall(DMLabelCreate(PETSC_COMM_SELF, "vibrotherm_fault", &fault));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    PetscInt v;
    PetscCall(DMLabelGetValue(crack, f, &v));
    if (v > 0) {
      PetscCall(DMLabelSetValue(fault, f, 1));
      ++nfaces;
    }
  }
  PetscCallMPI(MPI_Allreduce(&nfaces, &total, 1, MPIU_INT, MPI_SUM, comm));
  if (total == 0) {
    PetscCall(DMLabelDestroy(&fault));
    // Nothing to split: the same topology, but its own DM, so the wave and heat
    // spaces do not overwrite each other's section.
    PetscCall(DMClone(dm, split));
    PetscFunctionReturn(0);
  }
  PetscCall(DMPlexLabelComplete(dm, fault));

  // PETSc 3.18 reads the tip stratum without checking for an empty one: a crack
  // reaching the outer boundary at both ends has no tip, so give the label a
  // vertex off every crack, which DMPlexLabelCohesiveComplete discards.
  DMLabel tips_or_dummy;
  PetscCall(DMLabelDuplicate(tips, &tips_or_dummy));
  PetscCall(LabelCrackFront(dm, fault, tips_or_dummy));
  PetscInt ntips;
  PetscCall(DMLabelGetStratumSize(tips_or_dummy, 1, &ntips));
  if (ntips == 0) {
    PetscInt vStart, vEnd;
    PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
    for (PetscInt v = vStart; v < vEnd; ++v) {
      PetscInt value;
      PetscCall(DMLabelGetValue(fault, v, &value));
      if (value < 0) {
        PetscCall(DMLabelSetValue(tips_or_dummy, v, 1));
        break;
      }
    }
  }

  DM crack_mesh;
  PetscCall(DMPlexCreateSubmesh(dm, fault, 1, PETSC_TRUE, &crack_mesh));
  PetscCall(DMPlexOrient(crack_mesh));
  DMLabel subpoints, cohesive;
  PetscCall(DMPlexGetSubpointMap(crack_mesh, &subpoints));
  PetscCall(DMLabelDuplicate(subpoints, &cohesive));
  PetscInt dim;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMLabelClearStratum(cohesive, dim));
  PetscCall(DMPlexLabelCohesiveComplete(dm, cohesive, tips_or_dummy, 1, PETSC_FALSE, crack_mesh));
  PetscCall(DMPlexConstructCohesiveCells(dm, cohesive, nullptr, split));
  PetscCall(CheckCohesiveCount(*split, nfaces));
  PetscCall(dim == 3 ? LabelPlusFaces<3>(*split) : LabelPlusFaces<2>(*split));
  PetscCall(PetscObjectSetName((PetscObject)*split, "specimen"));

  PetscCall(DMLabelDestroy(&cohesive));
  PetscCall(DMLabelDestroy(&tips_or_dummy));
  PetscCall(DMLabelDestroy(&fault));
  PetscCall(DMDestroy(&crack_mesh));
  PetscFunctionReturn(0);
}

PetscErrorCode PlusSide(DM split, PetscInt cohesive, int* plus) {
  PetscFunctionBeginUser;
  DMLabel plus_faces;
  PetscCall(DMGetLabel(split, labels::crack_plus, &plus_faces));
  PetscCheck(plus_faces, PETSC_COMM_SELF, PETSC_ERR_PLIB, "crack: no %s label (SplitCracks sets it)",
             labels::crack_plus);
  const PetscInt* cone;
  PetscCall(DMPlexGetCone(split, cohesive, &cone));
  PetscInt first, second;
  PetscCall(DMLabelGetValue(plus_faces, cone[0], &first));
  PetscCall(DMLabelGetValue(plus_faces, cone[1], &second));
  PetscCheck((first == 1) != (second == 1), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "crack: cohesive cell %" PetscInt_FMT " has %s of its faces labelled %s", cohesive,
             first == 1 ? "both" : "neither", labels::crack_plus);
  *plus = first == 1 ? 0 : 1;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
