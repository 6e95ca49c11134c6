// Eigenvalues and eigenvectors of a symmetric 3×3 matrix (cyclic Jacobi
// rotations: a few sweeps to machine precision, no library). PETSc-free.
#pragma once

#include "vibrotherm/geometry/point.hpp"

namespace vibrotherm::geometry {

struct SymmetricEigen3 {
  Point<3> value;               ///< eigenvalues, descending
  std::array<Vec3, 3> vector;  ///< unit eigenvectors, vector[k] for value[k]
};

/// The eigen-decomposition of the symmetric matrix a (only its upper triangle is read).
SymmetricEigen3 EigenSymmetric3(const std::array<Vec3, 3>& a);

}  // namespace vibrotherm::geometry
