// The friction density on a 3D crack as the wave mesh carries it, ready for the
// surface transfer (surface_transfer.hpp): the 3D analogue of the 2D line
// transfer's wave elements.
//
// The contact cells' densities q_c [W/m²] are nodal values on the crack's faces:
// on each face (the + face of a cohesive cell) the density is their Lagrange
// interpolant q(r, s) = Σ_c q_c φ_c(r, s), with no cell (q = 0) at the unsplit
// front, as 2D's buried tips. The heat load it makes is ∫ q ψ_h dA over the faces,
// which this file writes as a quadrature: points x_p with areas A_p (m × m
// sub-squares of every face, 3 × 3 Gauss points each), and Φ (points × contact
// cells) with Φ_pc = φ_c(x_p). The heat load is then Ψ Φ q, Ψ the surface
// transfer of the points: exact for a heat basis polynomial of degree ≤ 3 on each
// sub-square (a heat mesh whose crack faces are the wave faces split in 1, 2 or m),
// and conservative always: Σ_p A_p φ_c(x_p) is the cell's weight ∫φ_c dA.
#pragma once

#include <petscmat.h>

#include "vibrotherm/coupling/exchange/surface_points.hpp"
#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/interface/crack_interface.hpp"

namespace vibrotherm::coupling {

/// This rank's quadrature points on the + faces of its cohesive cells (points) and
/// Φ (rows: every rank's points in that order; columns: the contact cells in the
/// interface's owned layout). Collective over wave_space's communicator.
PetscErrorCode BuildCrackFaceQuadrature(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                                        int subdivisions, SurfacePoints* points, Mat* basis);

}  // namespace vibrotherm::coupling
