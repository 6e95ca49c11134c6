// The planned mirror bands (crack_mirror.hpp) in the gmsh model (private to src/mesh):
// each band as two OpenCASCADE surfaces, upper and lower, sharing the crack's line, the
// lower one's outline meshed as the upper one's reflected (periodic curves whose
// transformation is the reflection), so that MirrorBandCells can replace the lower side's
// cells by the upper side's reflected. (gmsh's periodic surfaces would copy the cells
// too, but do not survive its subdivision of a mesh that kept triangles.)
#pragma once

#include <vector>

#include "gmsh_support.hpp"
#include "vibrotherm/mesh/crack_mirror.hpp"

namespace vibrotherm::mesh::crack_mirror_gmsh {

struct BandShapes {
  int upper = -1, lower = -1;    ///< OCC surfaces (before the fragment)
  std::vector<int> crack_lines;  ///< the crack's pieces along its line (the band's ends may cut it)
};

/// Adds the band's halves and the crack's line; the caller fragments the specimen with them.
BandShapes AddBand(const CrackMirror& band);

/// After the fragment: the lower half's outline meshed as the upper one's reflected.
void MirrorOutline(const CrackMirror& band, int upper, int lower);

}  // namespace vibrotherm::mesh::crack_mirror_gmsh
