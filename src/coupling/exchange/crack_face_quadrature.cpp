#include "vibrotherm/coupling/exchange/crack_face_quadrature.hpp"

#include <petscdmplex.h>

#include <array>
#include <cmath>

#include "vibrotherm/mesh/plex/crack_split.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::coupling {
namespace {

using geometry::Vec3;

/// A node of a face: its reference position (corners ±1, edge and face middles 0)
/// and the global index of its contact cell (−1: the unsplit front).
struct FaceNode {
  double r, s;
  PetscInt cell;
};

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

/// The nodes of face f (corners in cyclic order, then edge middles, then the face middle for Q2).
PetscErrorCode FaceNodes(DM dm, PetscSection section, const PetscScalar* index, int degree, PetscInt f,
                         std::vector<PetscInt>* corners, std::vector<FaceNode>* nodes) {
  PetscFunctionBeginUser;
  std::vector<PetscInt> edges;
  PetscCall(mesh::FaceCycle(dm, f, corners, &edges));
  PetscCheck(corners->size() == 4, PETSC_COMM_SELF, PETSC_ERR_SUP, "3D crack faces must be quadrilaterals");
  static const double kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const auto cell_at = [&](PetscInt point, PetscInt* cell) { return NodeCell(section, index, point, cell); };
  nodes->clear();
  for (int k = 0; k < 4; ++k) {
    FaceNode n{kCorner[k][0], kCorner[k][1], -1};
    PetscCall(cell_at((*corners)[k], &n.cell));
    nodes->push_back(n);
  }
  if (degree == 1) PetscFunctionReturn(0);
  for (int k = 0; k < 4; ++k) {
    FaceNode n{0.5 * (kCorner[k][0] + kCorner[(k + 1) % 4][0]), 0.5 * (kCorner[k][1] + kCorner[(k + 1) % 4][1]), -1};
    PetscCall(cell_at(edges[k], &n.cell));
    nodes->push_back(n);
  }
  FaceNode middle{0.0, 0.0, -1};
  PetscCall(cell_at(f, &middle.cell));
  nodes->push_back(middle);
  PetscFunctionReturn(0);
}

/// The points of one face (bilinear map of its corners) and their Φ entries (row, cell, φ).
void FacePoints(const std::array<Vec3, 4>& X, const std::vector<FaceNode>& nodes, int degree, int m,
                SurfacePoints* points, std::vector<std::array<double, 3>>* entries) {
  static const double g = std::sqrt(0.6), kGauss[3] = {-g, 0.0, g}, kWeight[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const double r = -1.0 + (2.0 * a + 1.0 + kGauss[i]) / m, s = -1.0 + (2.0 * b + 1.0 + kGauss[j]) / m;
          Vec3 x{}, xr{}, xs{};
          for (int d = 0; d < 3; ++d) {
            x[d] = 0.25 * ((1 - r) * (1 - s) * X[0][d] + (1 + r) * (1 - s) * X[1][d] + (1 + r) * (1 + s) * X[2][d] +
                           (1 - r) * (1 + s) * X[3][d]);
            xr[d] = 0.25 * ((1 - s) * (X[1][d] - X[0][d]) + (1 + s) * (X[2][d] - X[3][d]));
            xs[d] = 0.25 * ((1 - r) * (X[3][d] - X[0][d]) + (1 + r) * (X[2][d] - X[1][d]));
          }
          const Vec3 cross{xr[1] * xs[2] - xr[2] * xs[1], xr[2] * xs[0] - xr[0] * xs[2], xr[0] * xs[1] - xr[1] * xs[0]};
          const double jacobian = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
          const double row = static_cast<double>(points->size());
          points->x.push_back(x);
          points->area.push_back(kWeight[i] * kWeight[j] * jacobian / (m * m));
          for (const FaceNode& n : nodes)
            if (n.cell >= 0)
              entries->push_back({row, double(n.cell), Lagrange1D(degree, n.r, r) * Lagrange1D(degree, n.s, s)});
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

PetscErrorCode BuildCrackFaceQuadrature(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                                        int subdivisions, SurfacePoints* points, Mat* basis) {
  PetscFunctionBeginUser;
  DM dm = wave_space.dm();
  const int degree = static_cast<int>(wave_space.degree());
  Vec index;
  PetscCall(CellIndexAtNodes(crack, wave_space, &index));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  mesh::VertexPositions<3> x;
  PetscCall(x.Setup(dm));
  const PetscScalar* idx;
  PetscCall(VecGetArrayRead(index, &idx));
  std::vector<PetscInt> cohesive;
  PetscCall(mesh::CohesiveCells(dm, &cohesive));
  *points = SurfacePoints{};
  std::vector<std::array<double, 3>> entries;
  std::vector<PetscInt> corners;
  std::vector<FaceNode> nodes;
  for (PetscInt c : cohesive) {  // overlap 0: every local cell is owned
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    int plus;
    PetscCall(mesh::PlusSide(dm, c, &plus));
    const PetscInt face = cone[plus];
    PetscCall(FaceNodes(dm, section, idx, degree, face, &corners, &nodes));
    const std::array<Vec3, 4> X = {x(corners[0]), x(corners[1]), x(corners[2]), x(corners[3])};
    FacePoints(X, nodes, degree, subdivisions, points, &entries);
  }
  PetscCall(VecRestoreArrayRead(index, &idx));
  PetscCall(VecDestroy(&index));
  PetscCall(AssembleBasis(PetscObjectComm((PetscObject)dm), entries, static_cast<PetscInt>(points->size()),
                          static_cast<PetscInt>(crack.cells().size()), basis));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
