// Requirement (issue 40, item 4): util::PointExchange sends each point only to the ranks whose
// box holds it and gives it to exactly one of those, the lowest that accepts it. On any
// number of ranks: rank r's box is the slab [r/N, (r+1)/N] × [0, 1] (z = 0), neighbours
// sharing a face; every rank gives points in every slab, some on the faces between
// slabs (held by two boxes, accepted by both), and one outside every box.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "vibrotherm/util/point_exchange.hpp"

namespace vibrotherm::testing {
namespace {

constexpr std::size_t kStride = 4;  // x, y, z, a payload

/// Rank `rank`'s points: per slab s of `size`, its middle and its low face (x = s/size), then
/// one at x = 2 (in no box); the payload is 1000 rank + the point's place.
std::vector<double> PointsOf(int rank, int size) {
  std::vector<double> mine;
  for (int s = 0; s < size; ++s)
    for (double x : {(s + 0.5) / size, static_cast<double>(s) / size})
      mine.insert(mine.end(), {x, 0.25 + 0.1 * rank, 0.0, 1000.0 * rank + mine.size() / kStride});
  mine.insert(mine.end(), {2.0, 0.5, 0.0, 1000.0 * rank + mine.size() / kStride});
  return mine;
}

TEST(PointExchange, EachPointGoesToTheBoxesHoldingItAndToOneOwner) {
  PetscMPIInt rank, size;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  util::Box box;
  box.lo = {static_cast<double>(rank) / size, 0.0, 0.0};
  box.hi = {static_cast<double>(rank + 1) / size, 1.0, 0.0};
  const std::vector<double> mine = PointsOf(rank, size);
  util::PointExchange exchange;
  ASSERT_EQ(exchange.Setup(PETSC_COMM_WORLD, box, mine, kStride), 0);
  const std::size_t n = exchange.received_count();
  std::vector<char> accepted(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double* p = &exchange.received()[kStride * k];
    EXPECT_GE(p[0], box.lo[0] - 1e-9);  // only the points of this rank's box came
    EXPECT_LE(p[0], box.hi[0] + 1e-9);
    if (k > 0) {
      EXPECT_LT(exchange.global_index(k - 1), exchange.global_index(k));  // by global index
    }
    const PetscInt sender = static_cast<PetscInt>(p[3]) / 1000, place = static_cast<PetscInt>(p[3]) % 1000;
    EXPECT_EQ(exchange.global_index(k), sender * static_cast<PetscInt>(2 * size + 1) + place);
    accepted[k] = p[0] >= box.lo[0] && p[0] <= box.hi[0];
  }
  std::vector<std::size_t> owned;
  util::LostPoints lost;
  ASSERT_EQ(exchange.Settle(accepted, mine, &owned, &lost), 0);
  // A face point x = s/size (s ≥ 1) is held by ranks s−1 and s: the lower owns it.
  for (std::size_t k : owned) {
    const double x = exchange.received()[kStride * k];
    EXPECT_FALSE(rank > 0 && x == static_cast<double>(rank) / size) << "rank " << rank << " took the face x = " << x;
  }
  const PetscInt points = static_cast<PetscInt>(2 * size + 1) * size;
  EXPECT_EQ(exchange.counts().total, points);
  unsigned long long mine_owned = owned.size(), all_owned = 0;
  MPI_Allreduce(&mine_owned, &all_owned, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD);
  EXPECT_EQ(all_owned, static_cast<unsigned long long>(points - size));  // all but the lost, once each
  if (size > 1) {
    EXPECT_LT(n, static_cast<std::size_t>(points));
  }
  EXPECT_EQ(lost.count, size);
  EXPECT_EQ(lost.first, static_cast<PetscInt>(2 * size));  // rank 0's last
  EXPECT_EQ(lost.x[0], 2.0);
  EXPECT_EQ(lost.x[1], 0.5);
}

}  // namespace
}  // namespace vibrotherm::testing
