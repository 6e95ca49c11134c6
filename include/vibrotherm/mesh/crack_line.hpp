// A crack as a polyline, built from the facets its mesh's crack surface gathered
// (crack_surface.hpp; the crack_face ids number the facets along each crack), for
// points given as a fraction of the crack length (probes at ξ = 0.5: the centre).
#pragma once

#include <petscdm.h>

#include <array>
#include <vector>

#include "vibrotherm/geometry/crack_facet.hpp"

namespace vibrotherm::mesh {

class CrackLine {
 public:
  /// Chains the facets of crack `crack` (0-based) of a complete list (every rank's) by id.
  void Build(const std::vector<geometry::CrackFacet>& facets, int crack);
  /// The point at fraction xi ∈ [0, 1] of the length from the first facet's free end.
  std::array<double, 2> At(double xi) const;
  /// Shortest distance from (x, y) to the crack.
  double Distance(double x, double y) const;
  double length() const { return length_; }
  /// Facet ids in order along the crack; facet k joins vertices k and k + 1.
  const std::vector<PetscInt>& facet_ids() const { return ids_; }
  /// ξ of vertex k (0 at the first, exactly 1 at the last) and its coordinates.
  double vertex_xi(std::size_t k) const { return k + 1 == arc_.size() ? 1.0 : arc_[k] / length_; }
  const std::array<double, 2>& vertex(std::size_t k) const { return points_[k]; }
  /// ξ of the point of the crack nearest to (x, y).
  double XiOf(double x, double y) const;
  bool empty() const { return points_.size() < 2; }

 private:
  std::vector<std::array<double, 2>> points_;  ///< vertices in order along the crack
  std::vector<double> arc_;                    ///< arc length at each vertex
  std::vector<PetscInt> ids_;                  ///< facet ids in order
  double length_ = 0.0;
};

}  // namespace vibrotherm::mesh
