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
  double xi = 0.0;  ///< fraction along the crack (3D: s1, the distance from the crack's centre along t1 [m])
  double eta = 0.0;  ///< 3D: s2, the distance from the crack's centre along t2 [m]
  double x = 0.0, y = 0.0, z = 0.0;
  double b2 = 0.0, T2 = 0.0;  ///< 3D: the second tangential components [m], [Pa]
  double a = 0.0, b = 0.0, b0 = 0.0;  ///< half approach, half tangential displacement, slip offset [m]
  double N = 0.0, T = 0.0;            ///< tractions [Pa]
  contact::ContactState state = contact::ContactState::Loss;
  double power = 0.0;      ///< friction power in the last step [W/m²]
  double W = 0.0;          ///< dissipated so far [J/m²]
  double ux = 0.0, uy = 0.0;  ///< displacement of the + node [m]
};

/// Every rank's records on rank 0 (others get none), ordered by slot when all
/// slots are set, else by crack and ξ. Collective.
PetscErrorCode GatherCrackRecords(MPI_Comm comm, const std::vector<CrackCellRecord>& mine,
                                  std::vector<CrackCellRecord>* on_root);

}  // namespace vibrotherm::interface
