// Prescribed crack heating (-physics heat -heat_crack_power): a uniform power per unit
// crack area on every facet labelled `crack` (value k + 1 for crack k: mesh/plex/labels.hpp,
// the same label in 2D and 3D), integrated against the heat basis into a load Q for
// HeatSolver::SetSourceLoad (1ᵀQ is then exactly the power times the crack's area).
#pragma once

#include <petscvec.h>

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::heat {

/// Q (a global vector of space's DM) from power_by_crack[k] [W/m²] on the facets of crack k.
/// Every rank passes the same powers; a facet on a partition boundary counts once. Collective.
PetscErrorCode CrackPowerLoad(const fe::LagrangeSpace& space, const std::vector<double>& power_by_crack, Vec Q);

}  // namespace vibrotherm::heat
