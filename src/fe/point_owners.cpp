#include "vibrotherm/fe/point_owners.hpp"

namespace vibrotherm::fe {

PetscErrorCode LocateOnRanks(const CellLocator& locator, MPI_Comm comm, const std::vector<double>& mine,
                             std::size_t stride, util::PointExchange* exchange, LocatedPoints* located) {
  PetscFunctionBeginUser;
  PetscCall(exchange->Setup(comm, locator.bounds(), mine, stride));
  const std::size_t n = exchange->received_count();
  located->cells.assign(n, -1);
  located->refs.assign(n, ReferencePoint{0.0, 0.0, 0.0});
  std::vector<char> found(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    locator.Locate(&exchange->received()[stride * k], &located->cells[k], &located->refs[k]);
    found[k] = located->cells[k] >= 0;
  }
  PetscCall(exchange->Settle(found, mine, &located->owned, &located->lost));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::fe
