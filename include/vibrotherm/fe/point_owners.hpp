// Points of every rank located in the local cells of a space on whichever ranks hold
// them, each owned by exactly one: the lowest rank that locates it. The points travel
// by util::PointExchange (each only to the ranks whose cells' bounding box holds it),
// so no rank sees every point; the wave-to-heat and surface heat transfers share this.
#pragma once

#include <vector>

#include "vibrotherm/fe/cell_locator.hpp"
#include "vibrotherm/util/point_exchange.hpp"

namespace vibrotherm::fe {

/// What this rank made of the points it received (exchange->received()).
struct LocatedPoints {
  std::vector<PetscInt> cells;        ///< the local cell of each received point (-1: none)
  std::vector<ReferencePoint> refs;   ///< its reference coordinates there
  std::vector<std::size_t> owned;     ///< the received points this rank assembles, ascending
  util::LostPoints lost;              ///< the points no rank located
};

/// Sends `mine` (stride doubles a point, x, y, z first) to the ranks whose cells may hold
/// them, locates the points this rank receives with `locator` and settles their owners. Collective.
PetscErrorCode LocateOnRanks(const CellLocator& locator, MPI_Comm comm, const std::vector<double>& mine,
                             std::size_t stride, util::PointExchange* exchange, LocatedPoints* located);

}  // namespace vibrotherm::fe
