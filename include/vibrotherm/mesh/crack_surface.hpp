// The cracks of one distributed mesh as every rank knows them, held by the
// specimen for each of its meshes (wave and heat): the only place crack facets
// are gathered across ranks. Per crack it gives the facets (every rank's, and
// the mesh points of this rank's), their measures (geometry/crack_facet.hpp)
// and frames (geometry/frame.hpp), and the parameterisation of outputs: in 2D
// the arc-length fraction ξ of the crack's polyline (crack_line.hpp); a 3D
// crack will give coordinates on the crack plane instead.
//
// Which facets: on a split mesh one per cohesive cell (its − face, cone[0]),
// in cohesive-cell order; on an unsplit mesh the owned labelled facets in point
// order. Each crack_face id appears once over the ranks.
#pragma once

#include <petscdm.h>

#include <vector>

#include "vibrotherm/geometry/crack_facet.hpp"
#include "vibrotherm/geometry/frame.hpp"
#include "vibrotherm/mesh/crack_line.hpp"

namespace vibrotherm::mesh {

/// A crack facet of this rank's mesh.
struct OwnedCrackFacet {
  PetscInt cell;       ///< the cohesive cell on a split mesh, else the facet itself
  PetscInt facet;      ///< the facet point (on a split mesh the cohesive cell's − face)
  std::size_t index;   ///< its entry in CrackSurface::facets()
};

class CrackSurface {
 public:
  /// Gathers the facets of cracks 0 .. ncracks − 1 of dm on every rank; a 3D dm's stay empty
  /// (its cracks are surfaces, read from their labels). Collective.
  PetscErrorCode Setup(DM dm, PetscInt ncracks);

  /// Every rank's facets, rank by rank (the same list on every rank).
  const std::vector<geometry::CrackFacet>& facets() const { return facets_; }
  /// This rank's facets, in the order they were gathered.
  const std::vector<OwnedCrackFacet>& owned() const { return owned_; }
  /// Crack k's polyline: ξ ∈ [0, 1] from the end with the smaller x (then y).
  const CrackLine& line(PetscInt crack) const { return lines_.at(crack); }
  const std::vector<CrackLine>& lines() const { return lines_; }
  PetscInt crack_count() const { return static_cast<PetscInt>(lines_.size()); }
  /// Frame of a facet: tangent from p0 to p1, normal turned +90° (orient it with the crack's direction).
  static geometry::Frame<2> FacetFrame(const geometry::CrackFacet& f) {
    return geometry::FrameFromTangent(geometry::Normalized(geometry::Sub(f.p1, f.p0)));
  }

 private:
  PetscErrorCode CollectOwned(DM dm, std::vector<double>* packed);

  std::vector<geometry::CrackFacet> facets_;
  std::vector<OwnedCrackFacet> owned_;
  std::vector<CrackLine> lines_;
};

}  // namespace vibrotherm::mesh
