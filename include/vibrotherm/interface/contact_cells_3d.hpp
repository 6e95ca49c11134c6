// The contact cells of a 3D split mesh (PHYSICS.md §3.5): one per split node pair
// of the crack's faces — vertices, and with Q2 the edges' and faces' middle nodes —
// owned by this rank. The crack front is not split (its pairs are one point): no
// cell there, the faces are held together along it.
//
// Frame of a planar crack whose normal lies in the x–y plane (the box crack), the
// 2D convention extended: n is oriented with n_y > 0 (n_x < 0 for a vertical
// crack), t1 = n turned by −90° about z (the strike, as the 2D tangent s) and
// t2 = n × t1 (= −z), so (t1, t2, n) is right handed (geometry::CrackFrame). The
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
