// The heat mesh: the specimen meshed for heat conduction, separately from the
// wave mesh. Friction heats a layer √(α t) thick at the crack (10-300 µm at the
// times that matter), far thinner than the wave mesh: around every crack a
// structured band of quadrilaterals, layers graded from `h_crack` at the crack
// line to `h_along` at the band edge, `h_along` long along the crack; the band
// continues past buried tips (ξ ends) by its half-width so tips sit inside a
// fine, regular patch. Outside the band an unstructured quad mesh grows to h.
// The mesh is not split: temperature is continuous across the crack.
#pragma once

#include <petscsys.h>

#include "vibrotherm/mesh/mesh_data.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::mesh {

struct HeatMeshSizes {
  double h_crack = 5e-6;  ///< -heat_mesh_h_crack: first-layer thickness at the crack [m]
  double growth = 1.25;   ///< -heat_mesh_growth: thickness ratio of successive layers
  double h_along = 2.5e-4;  ///< -heat_mesh_h_along: element length along the crack [m]
  double h = 2e-3;        ///< -heat_mesh_h: element size away from the cracks [m]
  double grading = 0.6;   ///< -heat_mesh_grading: size growth per metre of distance outside the bands
  bool graded = true;     ///< -heat_mesh graded|wave: false reuses the unsplit wave mesh

  /// Layers on each side of a crack and the band half-width they fill.
  int layers() const;
  double band_half_width(int layers) const;
  /// Throws std::invalid_argument naming the option.
  void validate() const;
};

/// Meshes the generated specimen for heat (quads). Throws std::invalid_argument
/// when a crack's band cannot fit (cracks too close to each other or to a corner).
MeshData generate_heat_mesh(const SpecimenGeometry& geometry, const HeatMeshSizes& sizes);

}  // namespace vibrotherm::mesh
