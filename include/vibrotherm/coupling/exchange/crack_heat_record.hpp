// crack_heat.h5: the friction heat exactly as the heat solver received it, so
// that anyone can recompute the temperature it makes (e.g. the line-source
// convolution of scripts/lib/line_source.py) independently of the heat mesh.
//   time      n × 1   end of each exchange interval [s] (the first starts at 0)
//   density   n × C   line density q_c at each contact cell over the interval [W/m²]
//   elements  E × 8   crack, ξ0, ξ1, length [m], degree, cell at ξ0, at ξ1, at the middle (−1: none)
//   vertices  V × 4   crack, ξ, x, y of the wave mesh's crack vertices
// q(ξ) = Σ_c q_c φ_c(ξ) with the elements' Lagrange basis (line_transfer.hpp).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/coupling/exchange/friction_heat.hpp"
#include "vibrotherm/store/checkpoint.hpp"

namespace vibrotherm::coupling {

class CrackHeatRecord {
 public:
  /// Keeps the densities of the last interval (ending at t) on this rank.
  void Append(double t, const FrictionHeat& heat);
  /// Gathers on rank 0 and writes path. Collective.
  PetscErrorCode Write(MPI_Comm comm, const std::string& path, const FrictionHeat& heat) const;
  /// The record so far, per cell under `keys` (the owned cells' checkpoint keys), and back.
  void Save(store::Checkpoint& checkpoint, const std::vector<long long>& keys) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const std::vector<long long>& keys);

 private:
  std::vector<double> times_, densities_;  ///< densities_: intervals × owned cells
};

}  // namespace vibrotherm::coupling
