// Box meshes of DMPlexCreateBoxMesh in 2D and 3D (quads/hexes or triangles/
// tetrahedra) on PETSC_COMM_SELF, for the dimension-generic operators, and the
// helpers their checks share: node positions, nodal fields and boundary nodes.
#pragma once

#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::testing {

/// The mesh of one test case: dimension, cell shape and Lagrange degree.
struct BoxCase {
  int dim;
  bool simplex;
  int degree;
};

/// Quads, triangles, hexahedra and tetrahedra, degrees 1 and 2.
inline std::vector<BoxCase> AllBoxCases() {
  std::vector<BoxCase> cases;
  for (int dim : {2, 3})
    for (bool simplex : {false, true})
      for (int degree : {1, 2}) cases.push_back({dim, simplex, degree});
  return cases;
}

inline std::string BoxCaseName(const ::testing::TestParamInfo<BoxCase>& info) {
  const BoxCase& c = info.param;
  const char* shape = c.dim == 2 ? (c.simplex ? "tri" : "quad") : (c.simplex ? "tet" : "hex");
  return std::string(shape) + (c.simplex ? "P" : "Q") + std::to_string(c.degree);
}

/// The box [0, 1] × [0, 0.75] (× [0, 0.5]): its extent along each axis.
inline constexpr std::array<double, 3> kBoxUpper = {1.0, 0.75, 0.5};

inline double BoxVolume(int dim) {
  return dim == 2 ? kBoxUpper[0] * kBoxUpper[1] : kBoxUpper[0] * kBoxUpper[1] * kBoxUpper[2];
}

/// The grid of faces[d] cells between lower and upper split into simplices: every
/// square or cube into 2 or 6 along its main diagonal (Kuhn's split: conforming, as
/// every cell uses the same diagonal), each simplex ordered to have a positive volume.
/// (Debian's PETSc 3.18 has no simplex generator and no registered refine_tosimplex.)
/// On a communicator of several ranks, rank 0 holds the whole mesh (to be distributed).
inline PetscErrorCode KuhnSimplices(int dim, const PetscInt* faces, const double* lower, const double* upper,
                                    DM* dm, MPI_Comm comm = PETSC_COMM_SELF) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const PetscInt n[3] = {faces[0] + 1, faces[1] + 1, dim == 3 ? faces[2] + 1 : 1};
  std::vector<PetscReal> coordinates;
  for (PetscInt k = 0; k < n[2]; ++k)
    for (PetscInt j = 0; j < n[1]; ++j)
      for (PetscInt i = 0; i < n[0]; ++i) {
        const PetscInt ijk[3] = {i, j, k};
        for (int d = 0; d < dim; ++d) coordinates.push_back(lower[d] + (upper[d] - lower[d]) * ijk[d] / faces[d]);
      }
  const auto vertex = [&](const PetscInt* ijk) { return ijk[0] + n[0] * (ijk[1] + n[1] * (dim == 3 ? ijk[2] : 0)); };
  std::vector<PetscInt> cells;
  int axes[3] = {0, 1, 2};
  const PetscInt layers = rank != 0 ? 0 : dim == 3 ? faces[2] : 1;  // cells on rank 0 only
  for (PetscInt k = 0; k < layers; ++k)
    for (PetscInt j = 0; j < faces[1]; ++j)
      for (PetscInt i = 0; i < faces[0]; ++i)
        do {  // one simplex per order of the axes: walk from the low corner along them
          PetscInt ijk[3] = {i, j, k}, corners[4];
          corners[0] = vertex(ijk);
          for (int s = 0; s < dim; ++s) ++ijk[axes[s]], corners[s + 1] = vertex(ijk);
          double e[3][3];
          for (int s = 0; s < dim; ++s)
            for (int d = 0; d < dim; ++d)
              e[s][d] = coordinates[dim * corners[s + 1] + d] - coordinates[dim * corners[0] + d];
          const double volume = dim == 2 ? e[0][0] * e[1][1] - e[0][1] * e[1][0]
                                         : e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                                               e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                                               e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
          if (volume < 0) std::swap(corners[1], corners[2]);
          // Positive in VTK's sense; Plex takes a tetrahedron with its first face inward: inverted.
          if (dim == 3) PetscCall(DMPlexInvertCell(DM_POLYTOPE_TETRAHEDRON, corners));
          cells.insert(cells.end(), corners, corners + dim + 1);
        } while (std::next_permutation(axes, axes + dim));
  if (rank != 0) coordinates.clear();
  PetscCall(DMPlexCreateFromCellListPetsc(comm, dim, static_cast<PetscInt>(cells.size()) / (dim + 1),
                                          static_cast<PetscInt>(coordinates.size()) / dim, dim + 1, PETSC_TRUE,
                                          cells.data(), dim, coordinates.data(), dm));
  PetscFunctionReturn(0);
}

/// The same on the box [0, kBoxUpper].
inline PetscErrorCode KuhnSimplices(int dim, const PetscInt* faces, DM* dm) {
  const double origin[3] = {0.0, 0.0, 0.0};
  return KuhnSimplices(dim, faces, origin, kBoxUpper.data(), dm);
}

using mesh::MoveVertices;  // (mesh/plex/plex_access.hpp)

/// A box mesh with 3 × 2 (× 2) squares or cubes, interpolated, as they are or
/// split into simplices; the tensor cells get their interior vertices moved
/// off the grid so that they are not parallelograms (their maps are not affine).
inline PetscErrorCode BoxMesh(const BoxCase& c, DM* dm) {
  PetscFunctionBeginUser;
  const PetscInt faces[3] = {3, 2, 2};
  const PetscReal lower[3] = {0, 0, 0}, upper[3] = {kBoxUpper[0], kBoxUpper[1], kBoxUpper[2]};
  if (c.simplex) {
    PetscCall(KuhnSimplices(c.dim, faces, dm));
    PetscFunctionReturn(0);
  }
  PetscCall(DMPlexCreateBoxMesh(PETSC_COMM_SELF, c.dim, PETSC_FALSE, faces, lower, upper, nullptr, PETSC_TRUE, dm));
  PetscCall(MoveVertices(*dm, [&](PetscScalar* x, PetscInt n) {
    for (PetscInt v = 0; v < n / c.dim; ++v) {
      bool interior = true;
      for (int d = 0; d < c.dim; ++d)
        interior = interior && x[v * c.dim + d] > 1e-12 && x[v * c.dim + d] < upper[d] - 1e-12;
      if (interior)
        for (int d = 0; d < c.dim; ++d) x[v * c.dim + d] += 0.03 * (d + 1) * upper[d] * (v % 2 ? 1.0 : -1.0);
    }
  }));
  PetscFunctionReturn(0);
}

/// Whether a node at p (dim coordinates) lies on the box's boundary.
inline bool OnBoxBoundary(const double* p, int dim) {
  for (int d = 0; d < dim; ++d)
    if (std::abs(p[d]) < 1e-12 || std::abs(p[d] - kBoxUpper[d]) < 1e-12) return true;
  return false;
}

/// A global vector holding f(x) (components() values) at every node of the space.
inline PetscErrorCode NodalField(const fe::LagrangeSpace& space,
                                 const std::function<void(const double* x, double* value)>& f, Vec* global) {
  PetscFunctionBeginUser;
  std::vector<double> x;
  PetscCall(space.NodePositions(&x));
  Vec local;
  PetscScalar* a;
  const int D = space.dim(), Nc = static_cast<int>(space.components());
  PetscCall(DMGetLocalVector(space.dm(), &local));
  PetscCall(VecGetArray(local, &a));
  std::vector<double> value(Nc);
  for (std::size_t i = 0; i < x.size() / D; ++i) {
    f(&x[D * i], value.data());
    for (int k = 0; k < Nc; ++k) a[Nc * i + k] = value[k];
  }
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(DMCreateGlobalVector(space.dm(), global));
  PetscCall(DMLocalToGlobal(space.dm(), local, INSERT_VALUES, *global));
  PetscCall(DMRestoreLocalVector(space.dm(), &local));
  PetscFunctionReturn(0);
}

/// Largest |r| over the rows of nodes inside the box (not on its boundary).
inline double InteriorMax(const fe::LagrangeSpace& space, Vec r) {
  std::vector<double> x;
  if (space.NodePositions(&x)) return INFINITY;
  const PetscScalar* a;
  VecGetArrayRead(r, &a);
  const int D = space.dim(), Nc = static_cast<int>(space.components());
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size() / D; ++i)
    if (!OnBoxBoundary(&x[D * i], D))
      for (int k = 0; k < Nc; ++k) worst = std::max(worst, std::abs(PetscRealPart(a[Nc * i + k])));
  VecRestoreArrayRead(r, &a);
  return worst;
}

}  // namespace vibrotherm::testing
