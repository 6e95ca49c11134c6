// Prescribed crack heating (-physics heat -heat_crack_power): a uniform power per unit
// crack area on every facet of each crack, integrated against the heat basis into a
// load Q for HeatSolver::SetSourceLoad (1ᵀQ is then exactly the power times the area).
#pragma once

#include <petscvec.h>

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/mesh/crack_surface.hpp"

namespace vibrotherm::heat {

/// Q (a global vector of space's DM) from power_by_crack[k] [W/m²] on the facets of crack k
/// of `cracks` (the heat mesh's, 2D). Every rank passes the same powers. Collective.
PetscErrorCode CrackPowerLoad(const fe::LagrangeSpace& space, const mesh::CrackSurface& cracks,
                              const std::vector<double>& power_by_crack, Vec Q);
/// The same from the facets labelled `crack` (value k + 1 for crack k), as a 3D heat mesh
/// marks them. Collective.
PetscErrorCode LabelledCrackPowerLoad(const fe::LagrangeSpace& space, const std::vector<double>& power_by_crack,
                                      Vec Q);

}  // namespace vibrotherm::heat
