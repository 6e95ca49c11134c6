// One contact cell's state as the outputs write it (probes.csv crack rows,
// crack_state.csv): named fields, one definition shared by every writer, and
// the only place that knows how a record travels between ranks.
#pragma once

#include <petscsys.h>

#include <vector>

#include "vibrotherm/contact/memory_diagram.hpp"

namespace vibrotherm::interface {

struct CrackCellRecord {
  long slot = -1;   ///< where the gathered record goes (probe index, or −1: sort along the cracks)
  int crack = 0;    ///< 0-based
  double xi = 0.0;   ///< fraction along a 2D crack line; NaN on a 3D crack surface (it has none)
  double s1 = 0.0, s2 = 0.0;  ///< from the crack's centre (its cells' centroid) along the tangents t1, t2 [m]
  double x = 0.0, y = 0.0, z = 0.0;
  double b2 = 0.0, T2 = 0.0;  ///< the second tangential components [m], [Pa] (0 in 2D)
  double a = 0.0, b = 0.0, b0 = 0.0;  ///< half approach, half tangential displacement, slip offset [m]
  double N = 0.0, T = 0.0;            ///< tractions [Pa]
  contact::ContactState state = contact::ContactState::Loss;
  double power = 0.0;      ///< friction power in the last step [W/m²]
  double W = 0.0;          ///< dissipated so far [J/m²]
  double ux = 0.0, uy = 0.0;  ///< displacement of the + node [m]
};

/// Every rank's records on rank 0 (others get none), ordered by slot when all
/// slots are set, else by crack, ξ (2D), s1 and s2. Collective.
PetscErrorCode GatherCrackRecords(MPI_Comm comm, const std::vector<CrackCellRecord>& mine,
                                  std::vector<CrackCellRecord>* on_root);

}  // namespace vibrotherm::interface
