// A matrix of a Lagrange space whose nonzeros are exactly the couplings of its cells'
// closures, preallocated by one pass of those closures into a MATPREALLOCATOR.
//
// Why not DMCreateMatrix's own preallocation: PETSc 3.18's DMPlexPreallocate builds
// every point's FEM adjacency (closure of the star of its closure, the cell types looked
// up point by point): 1 ms a hexahedron on this machine (a busy day), 107 s for the 102816 heat
// hexahedra of options/block3d.opts on one rank, against under 2 s for the closures.
#pragma once

#include <petscmat.h>

#include <cstddef>
#include <functional>

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::fe {

/// A matrix of the space's DM (its matrix type and block size, its local-to-global map),
/// preallocated for the closures of the cells k (indices into space.cells()) with
/// include(k) true (every cell when include is empty) and filled with zeros there, so
/// DMPlexMatSetClosure with ADD_VALUES assembles into it. Collective.
PetscErrorCode CreateCellMatrix(const LagrangeSpace& space, const std::function<bool(std::size_t)>& include, Mat* A);

}  // namespace vibrotherm::fe
