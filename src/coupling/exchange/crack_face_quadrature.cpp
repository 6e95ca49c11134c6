#include "vibrotherm/coupling/exchange/crack_face_quadrature.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "vibrotherm/mesh/plex/crack_split.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::coupling {
namespace {

using geometry::Vec3;

/// A node of a face: its reference position (corners ±1, edge and face middles 0)
/// and the global index of its contact cell (−1: an unsplit tip or front).
struct FaceNode {
  double r, s;
  PetscInt cell;
};

/// A crack face's reference shape, chosen once from the mesh's dimension.
struct FaceShape {
  int directions;                                   ///< 1: a segment (2D), 2: a quadrilateral (3D)
  std::vector<std::array<double, 2>> corners;       ///< reference corners in cyclic order (s = 0 on a segment)
  /// The face point's corners in that order and its edges (edges[k] joins corners k, k + 1).
  PetscErrorCode (*read)(DM, PetscInt, std::vector<PetscInt>*, std::vector<PetscInt>*);
  /// x(r, s) from the corners X; returns the Jacobian of the face's measure there.
  double (*map)(const std::vector<Vec3>& X, double r, double s, Vec3* x);
  /// Reference coordinates (per direction) where the face is cut at the kinks lying on it.
  std::array<std::vector<double>, 2> (*cuts)(const std::vector<Vec3>& X, const std::vector<Vec3>& kinks);
};

PetscErrorCode SegmentEnds(DM dm, PetscInt face, std::vector<PetscInt>* corners, std::vector<PetscInt>* edges) {
  PetscFunctionBeginUser;
  const PetscInt* cone;
  PetscCall(DMPlexGetCone(dm, face, &cone));
  corners->assign(cone, cone + 2);
  edges->clear();  // a segment's middle node is the face point itself
  PetscFunctionReturn(0);
}

PetscErrorCode QuadrilateralCycle(DM dm, PetscInt face, std::vector<PetscInt>* corners, std::vector<PetscInt>* edges) {
  PetscFunctionBeginUser;
  PetscCall(mesh::FaceCycle(dm, face, corners, edges));
  PetscCheck(corners->size() == 4, PETSC_COMM_SELF, PETSC_ERR_SUP, "3D crack faces must be quadrilaterals");
  PetscFunctionReturn(0);
}

double SegmentMap(const std::vector<Vec3>& X, double r, double /*s*/, Vec3* x) {
  for (int d = 0; d < 3; ++d) (*x)[d] = 0.5 * ((1 - r) * X[0][d] + (1 + r) * X[1][d]);
  return 0.5 * geometry::Norm(geometry::Sub(X[1], X[0]));
}

double QuadrilateralMap(const std::vector<Vec3>& X, double r, double s, Vec3* x) {
  Vec3 xr{}, xs{};
  for (int d = 0; d < 3; ++d) {
    (*x)[d] = 0.25 * ((1 - r) * (1 - s) * X[0][d] + (1 + r) * (1 - s) * X[1][d] + (1 + r) * (1 + s) * X[2][d] +
                      (1 - r) * (1 + s) * X[3][d]);
    xr[d] = 0.25 * ((1 - s) * (X[1][d] - X[0][d]) + (1 + s) * (X[2][d] - X[3][d]));
    xs[d] = 0.25 * ((1 - r) * (X[3][d] - X[0][d]) + (1 + r) * (X[2][d] - X[1][d]));
  }
  const Vec3 cross{xr[1] * xs[2] - xr[2] * xs[1], xr[2] * xs[0] - xr[0] * xs[2], xr[0] * xs[1] - xr[1] * xs[0]};
  return std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
}

/// The kinks that project inside the segment X0 X1 within a tenth of its length of it, as
/// r ∈ (−1, 1): on a straight crack they lie on it; a curved crack's heat vertices lie off
/// the wave chords by their sagitta. A cut too many costs points, never accuracy.
std::array<std::vector<double>, 2> SegmentCuts(const std::vector<Vec3>& X, const std::vector<Vec3>& kinks) {
  const Vec3 along = geometry::Sub(X[1], X[0]);
  const double length2 = geometry::Dot(along, along), tol = 0.1 * std::sqrt(length2);
  std::array<std::vector<double>, 2> cuts;
  for (const Vec3& k : kinks) {
    const Vec3 from = geometry::Sub(k, X[0]);
    const double t = geometry::Dot(from, along) / length2;
    if (t <= 0.0 || t >= 1.0 || geometry::Norm(geometry::Sub(from, geometry::Scale(t, along))) > tol) continue;
    cuts[0].push_back(2.0 * t - 1.0);
  }
  return cuts;
}

/// A 3D heat mesh's crack faces nest in the wave faces' m × m parts: no cuts.
std::array<std::vector<double>, 2> NoCuts(const std::vector<Vec3>&, const std::vector<Vec3>&) { return {}; }

const FaceShape& ShapeOfFaces(int mesh_dim) {
  static const FaceShape kSegment{1, {{-1, 0}, {1, 0}}, SegmentEnds, SegmentMap, SegmentCuts};
  static const FaceShape kQuadrilateral{
      2, {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, QuadrilateralCycle, QuadrilateralMap, NoCuts};
  return mesh_dim == 3 ? kQuadrilateral : kSegment;
}

/// Points along one reference direction of a face, part by part: 3 Gauss points on each
/// piece of each of `parts` equal parts, a part cut into pieces at the `cuts` inside it.
struct DirectionRule {
  int parts = 1;
  std::vector<std::vector<std::array<double, 2>>> points;  ///< per part: (r, weight on the part's [−1, 1])
};

DirectionRule Rule(int parts, std::vector<double> cuts) {
  static const double g = std::sqrt(0.6), kGauss[3] = {-g, 0.0, g}, kWeight[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  DirectionRule rule{parts, {}};
  for (int a = 0; a < parts; ++a) {
    std::vector<double> u{-1.0, 1.0};  // the part's own coordinate: r = −1 + (2a + 1 + u) / parts
    for (double c : cuts) {
      const double v = (c + 1.0) * parts - 2.0 * a - 1.0;
      if (v > -1.0 + 1e-12 && v < 1.0 - 1e-12) u.push_back(v);
    }
    std::sort(u.begin(), u.end());
    u.erase(std::unique(u.begin(), u.end(), [](double p, double q) { return q - p < 1e-12; }), u.end());
    std::vector<std::array<double, 2>> part;
    for (std::size_t k = 0; k + 1 < u.size(); ++k) {
      const double middle = 0.5 * (u[k] + u[k + 1]), half = 0.5 * (u[k + 1] - u[k]);
      for (int i = 0; i < 3; ++i)
        part.push_back({-1.0 + (2.0 * a + 1.0 + (middle + half * kGauss[i])) / parts, kWeight[i] * half});
    }
    rule.points.push_back(part);
  }
  return rule;
}

/// One-dimensional Lagrange basis of `degree` on the nodes −1, (0,) 1, at node a.
double Lagrange1D(int degree, double a, double r) {
  if (degree == 1) return 0.5 * (1.0 + a * r);
  if (a == 0.0) return 1.0 - r * r;
  return 0.5 * r * (r + a);
}

/// Global contact-cell index + 1 at the first dof of every cell's + node, on every
/// rank that holds the node (0 elsewhere): each cell written by its owner, moved by ADD.
PetscErrorCode CellIndexAtNodes(const interface::CrackInterface& crack, const fe::LagrangeSpace& space, Vec* local) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  const PetscInt owned = static_cast<PetscInt>(crack.cells().size());
  PetscInt first = 0;
  PetscCallMPI(MPI_Exscan(&owned, &first, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) first = 0;
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  Vec global;
  PetscCall(DMCreateLocalVector(dm, local));
  PetscCall(DMCreateGlobalVector(dm, &global));
  PetscCall(VecSet(*local, 0.0));
  PetscCall(VecSet(global, 0.0));
  PetscScalar* v;
  PetscCall(VecGetArray(*local, &v));
  for (PetscInt i = 0; i < owned; ++i) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(section, crack.cells()[i].plus, &off));
    v[off] = static_cast<PetscScalar>(first + i + 1);
  }
  PetscCall(VecRestoreArray(*local, &v));
  PetscCall(DMLocalToGlobal(dm, *local, ADD_VALUES, global));
  PetscCall(DMGlobalToLocal(dm, global, INSERT_VALUES, *local));
  PetscCall(VecDestroy(&global));
  PetscFunctionReturn(0);
}

/// The contact cell of the node at `point` (−1: none).
PetscErrorCode NodeCell(PetscSection section, const PetscScalar* index, PetscInt point, PetscInt* cell) {
  PetscFunctionBeginUser;
  PetscInt off;
  PetscCall(PetscSectionGetOffset(section, point, &off));
  *cell = static_cast<PetscInt>(std::lround(PetscRealPart(index[off]))) - 1;
  PetscFunctionReturn(0);
}

/// The nodes of face f: corners, then edge middles, then the face middle (Q2).
PetscErrorCode FaceNodes(DM dm, const FaceShape& shape, PetscSection section, const PetscScalar* index, int degree,
                         PetscInt f, std::vector<PetscInt>* corners, std::vector<FaceNode>* nodes) {
  PetscFunctionBeginUser;
  std::vector<PetscInt> edges;
  PetscCall(shape.read(dm, f, corners, &edges));
  const auto cell_at = [&](PetscInt point, PetscInt* cell) { return NodeCell(section, index, point, cell); };
  const std::size_t n = shape.corners.size();
  nodes->clear();
  for (std::size_t k = 0; k < n; ++k) {
    FaceNode node{shape.corners[k][0], shape.corners[k][1], -1};
    PetscCall(cell_at((*corners)[k], &node.cell));
    nodes->push_back(node);
  }
  if (degree == 1) PetscFunctionReturn(0);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const auto &a = shape.corners[k], &b = shape.corners[(k + 1) % n];
    FaceNode node{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), -1};
    PetscCall(cell_at(edges[k], &node.cell));
    nodes->push_back(node);
  }
  FaceNode middle{0.0, 0.0, -1};
  PetscCall(cell_at(f, &middle.cell));
  nodes->push_back(middle);
  PetscFunctionReturn(0);
}

/// The points of one face and their Φ entries (row, cell, φ): its parts m × m (3D) or
/// m (2D), 3 Gauss points along each direction of each piece.
void FacePoints(const FaceShape& shape, const std::vector<Vec3>& X, const std::vector<FaceNode>& nodes, int degree,
                const CrackFaceSplit& split, SurfacePoints* points, std::vector<std::array<double, 3>>* entries) {
  const auto cuts = shape.cuts(X, split.kinks);
  const DirectionRule single{1, {{{0.0, 1.0}}}};  // a direction the face does not have
  const DirectionRule rr = Rule(split.subdivisions, cuts[0]);
  const DirectionRule rs = shape.directions == 2 ? Rule(split.subdivisions, cuts[1]) : single;
  for (const auto& part_r : rr.points)
    for (const auto& part_s : rs.points)
      for (const auto& [r, wr] : part_r)
        for (const auto& [s, ws] : part_s) {
          Vec3 x{};
          const double jacobian = shape.map(X, r, s, &x);
          const double row = static_cast<double>(points->size());
          points->x.push_back(x);
          points->area.push_back(wr * ws * jacobian / (rr.parts * rs.parts));
          for (const FaceNode& n : nodes) {
            if (n.cell < 0) continue;
            double phi = Lagrange1D(degree, n.r, r);
            if (shape.directions == 2) phi *= Lagrange1D(degree, n.s, s);
            entries->push_back({row, double(n.cell), phi});
          }
        }
}

/// Φ from the entries of this rank's points (local rows 0.. are global first_row..).
PetscErrorCode AssembleBasis(MPI_Comm comm, const std::vector<std::array<double, 3>>& entries, PetscInt rows,
                             PetscInt cells, Mat* basis) {
  PetscFunctionBeginUser;
  PetscInt first = 0;
  PetscCallMPI(MPI_Exscan(&rows, &first, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) first = 0;
  PetscCall(MatCreateAIJ(comm, rows, cells, PETSC_DETERMINE, PETSC_DETERMINE, 9, nullptr, 9, nullptr, basis));
  PetscCall(MatSetOption(*basis, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  for (const auto& e : entries)
    PetscCall(MatSetValue(*basis, first + static_cast<PetscInt>(e[0]), static_cast<PetscInt>(e[1]), e[2], ADD_VALUES));
  PetscCall(MatAssemblyBegin(*basis, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*basis, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

}  // namespace

std::vector<Vec3> CrackLineVertices(const mesh::CrackSurface& cracks) {
  std::vector<Vec3> vertices;
  for (const geometry::CrackFacet& f : cracks.facets())
    for (const geometry::Vec2& p : {f.p0, f.p1}) vertices.push_back({p[0], p[1], 0.0});
  return vertices;
}

PetscErrorCode BuildCrackFaceQuadrature(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                                        const CrackFaceSplit& split, SurfacePoints* points, Mat* basis) {
  PetscFunctionBeginUser;
  DM dm = wave_space.dm();
  const FaceShape& shape = ShapeOfFaces(static_cast<int>(wave_space.dim()));
  const int degree = static_cast<int>(wave_space.degree());
  Vec index;
  PetscCall(CellIndexAtNodes(crack, wave_space, &index));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  mesh::VertexPositions<3> position;  // z = 0 on a 2D mesh
  PetscCall(position.Setup(dm));
  const PetscScalar* idx;
  PetscCall(VecGetArrayRead(index, &idx));
  std::vector<PetscInt> cohesive;
  PetscCall(mesh::CohesiveCells(dm, &cohesive));
  *points = SurfacePoints{};
  std::vector<std::array<double, 3>> entries;
  std::vector<PetscInt> corners;
  std::vector<FaceNode> nodes;
  std::vector<Vec3> X;
  for (PetscInt c : cohesive) {  // overlap 0: every local cell is owned
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    int plus;
    PetscCall(mesh::PlusSide(dm, c, &plus));
    const PetscInt face = cone[plus];
    PetscCall(FaceNodes(dm, shape, section, idx, degree, face, &corners, &nodes));
    X.clear();
    for (PetscInt v : corners) X.push_back(position(v));
    FacePoints(shape, X, nodes, degree, split, points, &entries);
  }
  PetscCall(VecRestoreArrayRead(index, &idx));
  PetscCall(VecDestroy(&index));
  PetscCall(AssembleBasis(PetscObjectComm((PetscObject)dm), entries, static_cast<PetscInt>(points->size()),
                          static_cast<PetscInt>(crack.cells().size()), basis));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
