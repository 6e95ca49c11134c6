// The contact cells of a 3D split mesh (PHYSICS.md §3.5): one per split node pair
// of the crack's faces — vertices, and with Q2 the edges' and faces' middle nodes —
// owned by this rank (the pairs: interface/contact_pairs, as in 2D). The crack front
// is not split (its pairs are one point): no cell there, the faces are held together
// along it.
//
// Frame of a planar crack (geometry::CrackFrame), the 2D convention extended: n is
// oriented with n_y > 0 (n_x < 0 for a vertical crack, n_z > 0 for one parallel to the
// front face), t1 = (n_y, −n_x, 0)/|·| the horizontal strike (as the 2D tangent s; x for
// a crack parallel to the front face) and t2 = n × t1 (−z for an untilted crack, the
// down-dip of a tilted one), so (t1, t2, n) is right handed. The
// + node is on the face the split labelled crack_plus (its bulk neighbour lies
// along n: decided on the serial mesh). A node's weight is ∫φ dA over every crack
// face around it, summed across ranks (its tributary area [m²]).
#pragma once

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/interface/crack_interface.hpp"

namespace vibrotherm::interface {

/// This rank's contact cells (plus, minus, n, s = t1, s2 = t2, weight, x, y, z, crack from the
/// crack label's value − 1). Collective.
PetscErrorCode ContactCells3D(const fe::LagrangeSpace& space, std::vector<ContactCell>* cells);

}  // namespace vibrotherm::interface
