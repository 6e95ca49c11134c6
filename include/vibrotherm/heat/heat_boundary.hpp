// Thermal conditions on the outer edges of the heat mesh (PHYSICS.md §2):
//   sink        T = T0 (held; the default on faces labelled `sink`, i.e. every
//               outer edge of a generated specimen)
//   insulated   no flux (the natural condition)
//   convective  flux h (T − T_ext) out of the body (-heat_h, -heat_T_ext)
// Chosen by -heat_bc KIND for every outer edge and -heat_bc_bottom|right|top|left
// KIND per side of a generated specimen; without either, faces labelled sink
// are sinks and the others insulated.
#pragma once

#include <petscdm.h>

#include <array>
#include <string>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::heat {

enum class ThermalEdge { Sink, Insulated, Convective };

struct HeatBoundaryOptions {
  std::string all;        ///< -heat_bc ("" when not given)
  std::string side[6];    ///< -heat_bc_<side> by mesh::Side, then front and back (3D; "" when not given)
  double h = 10.0;        ///< -heat_h [W/(m² K)]
  double T_ext = -1.0;    ///< -heat_T_ext [K] (default: T0)
};
/// -heat_bc, -heat_bc_<side>, -heat_h, -heat_T_ext, declared (option_spec.hpp).
const std::vector<OptionSpec<HeatBoundaryOptions>>& HeatBoundaryOptionSpecs();
/// Reads them (-heat_T_ext's default: T0). Collective.
PetscErrorCode ReadHeatBoundaryOptions(MPI_Comm comm, double T0, HeatBoundaryOptions* options, OptionValues* values = nullptr);

/// The outer-edge terms of one heat space.
struct HeatBoundary {
  std::vector<PetscInt> sink_rows;   ///< owned global rows held at T0
  /// Convective edges, lumped: per owned global row, h ∫φ ds (the diagonal added to K).
  std::vector<PetscInt> convective_rows;
  std::vector<double> convective_h;
  double T_ext = 0.0;
  PetscInt sink_faces = 0, insulated_faces = 0, convective_faces = 0;  ///< global counts
  std::vector<std::array<double, 4>> outer_faces;  ///< 2D: this rank's outer edges, any kind: x0, y0, x1, y1
  int dimension = 2;                               ///< the mesh's (3D: faces labelled `sink` are sinks, outer_faces empty)
};
/// Classifies every outer face of space's DM and collects the rows. Collective.
PetscErrorCode BuildHeatBoundary(const fe::LagrangeSpace& space, const HeatBoundaryOptions& options,
                                 HeatBoundary* boundary);
/// Distance from (x, y) to the nearest outer edge of the body, on every rank (2D only). Collective.
PetscErrorCode DistanceToOuterEdges(MPI_Comm comm, const HeatBoundary& boundary, double x, double y, double* distance);

}  // namespace vibrotherm::heat
