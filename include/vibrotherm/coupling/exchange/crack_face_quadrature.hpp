// The friction density on a crack as the wave mesh carries it, ready for the
// surface transfer (surface_transfer.hpp), in both dimensions: the faces of the
// crack are segments in 2D and quadrilaterals in 3D (the + face of each cohesive
// cell), one code for both (a face shape chosen once from the DM's dimension).
//
// The contact cells' densities q_c [W/m²] are nodal values on the crack's faces:
// on each face the density is their Lagrange interpolant q(r[, s]) = Σ_c q_c φ_c,
// with no cell (q = 0) at an unsplit buried tip or front. The heat load it makes
// is ∫ q ψ_h over the faces, written here as a quadrature: points x_p with
// measures A_p (3 Gauss points along each reference direction of every piece of
// a face) and Φ (points × contact cells) with Φ_pc = φ_c(x_p). The heat load is
// then Ψ Φ q, Ψ the surface transfer of the points.
//
// The pieces: each face cut into m equal parts along each reference direction
// (`subdivisions`), and a segment face further at the `kinks` that lie on it (the
// heat mesh's crack vertices in 2D, where the heat basis has kinks). The rule is
// exact where the heat basis is one polynomial of degree ≤ 3 on each piece: in 2D
// always (the pieces are the overlaps of wave and heat crack elements, as the
// line transfer's exact integrals, line_transfer.hpp, now the oracle of a test);
// in 3D for heat faces that are the wave faces split in 1, 2 or m. Conservative
// always: Σ_p A_p φ_c(x_p) is the cell's weight ∫φ_c.
#pragma once

#include <petscmat.h>

#include <vector>

#include "vibrotherm/coupling/exchange/surface_points.hpp"
#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/mesh/crack_surface.hpp"

namespace vibrotherm::coupling {

/// How the crack faces are cut into the pieces that carry the Gauss points.
struct CrackFaceSplit {
  int subdivisions = 1;               ///< equal parts along each reference direction of a face
  std::vector<geometry::Vec3> kinks;  ///< points of 2D crack lines where segment faces are cut too (z = 0)
};

/// The vertices of a mesh's crack lines (z = 0; none for a 3D mesh, whose CrackSurface is
/// empty): given as kinks, the heat mesh's cut the wave faces where its basis kinks.
std::vector<geometry::Vec3> CrackLineVertices(const mesh::CrackSurface& cracks);

/// This rank's quadrature points on the + faces of its cohesive cells (points, z = 0
/// in 2D) and Φ (rows: every rank's points in that order; columns: the contact cells
/// in the interface's owned layout). Collective over wave_space's communicator.
PetscErrorCode BuildCrackFaceQuadrature(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                                        const CrackFaceSplit& split, SurfacePoints* points, Mat* basis);

}  // namespace vibrotherm::coupling
