// Points of every rank sent only to the ranks that may hold them, and each given to
// exactly one of those: the replacement of an all-gather of every point on every rank.
//
// Each rank gives a box (its cells' bounding box, inflated here by a relative
// tolerance) and its points (packed, `stride` doubles each, x, y, z first; z = 0 in
// 2D). The boxes alone are all-gathered (6 doubles a rank); each point goes to the
// ranks whose box holds it, along a PetscSF whose roots are this rank's points and
// whose leaves are the copies the destinations receive (PetscCommBuildTwoSided tells
// each rank who sends how many; a first SF over the copies tells it which). A rank receives its
// points in the order of their global index (sender's rank, then its list), so a
// loop over them runs as a loop over the gathered list did.
//
// Ownership (Settle): every receiving rank says which points it accepts (e.g. found
// them in a cell); the lowest accepting rank of each point is its owner, decided
// over the point's candidates only (an SF reduce with MPI_MIN to the sender, then a
// bcast back). A point no rank accepts is counted and named (Lost): the caller's error.
// Memory per rank: the points it receives (sent from the caller's own list), not the global total.
#pragma once

#include <petscsf.h>

#include <array>
#include <vector>

namespace vibrotherm::util {

/// An axis-aligned box (lo > hi on some axis: empty).
struct Box {
  std::array<double, 3> lo = {0, 0, 0}, hi = {0, 0, 0};
};

/// What one rank's exchange moved: its points, the copies it sent and received, the
/// received points it owns (after Settle), all points.
struct ExchangeCounts {
  std::size_t mine = 0, sent = 0, received = 0, owned = 0;
  PetscInt total = 0;   ///< points on all ranks
  std::size_t bytes = 0;  ///< this rank's point buffers and indices (an all-gather: total × stride × 8)
};

/// The points no rank accepted: how many (all ranks), and the first (lowest global index) and its place.
struct LostPoints {
  PetscInt count = 0;
  PetscInt first = -1;
  std::array<double, 3> x = {0, 0, 0};
};

class PointExchange {
 public:
  PointExchange() = default;
  PointExchange(const PointExchange&) = delete;
  PointExchange& operator=(const PointExchange&) = delete;
  ~PointExchange();

  /// Sends each of `mine` (stride doubles a point) to every rank whose box (`box` on
  /// this rank) holds it. Collective.
  PetscErrorCode Setup(MPI_Comm comm, const Box& box, const std::vector<double>& mine, std::size_t stride);
  /// The points received, packed as sent, by ascending global index.
  const std::vector<double>& received() const { return received_; }
  std::size_t received_count() const { return global_.size(); }
  /// Global index of received point k: its sender's first index + its place in the sender's list.
  PetscInt global_index(std::size_t k) const { return global_[k]; }
  /// Global index of this rank's first point (the ranks' points numbered in rank order).
  PetscInt first() const { return first_; }
  /// owned = the received points this rank takes (the lowest rank that accepted each),
  /// ascending; accepted[k] for every received point k; mine as given to Setup (to name
  /// a lost point). Collective.
  PetscErrorCode Settle(const std::vector<char>& accepted, const std::vector<double>& mine,
                        std::vector<std::size_t>* owned, LostPoints* lost);
  const ExchangeCounts& counts() const { return counts_; }

 private:
  PetscErrorCode SendLists(const std::vector<double>& mine, std::vector<PetscMPIInt>* ranks,
                           std::vector<PetscInt>* sizes);
  PetscErrorCode BuildGraph(const std::vector<PetscMPIInt>& ranks, const std::vector<PetscInt>& sizes);
  PetscErrorCode SendPoints(const std::vector<double>& mine);
  PetscErrorCode FindLost(const std::vector<int>& owner, const std::vector<double>& mine, LostPoints* lost);

  MPI_Comm comm_ = MPI_COMM_NULL;
  std::size_t stride_ = 0;
  std::vector<Box> boxes_;       ///< every rank's inflated box
  std::vector<PetscInt> slots_;  ///< during Setup: the point of each copy sent (by destination rank, then point)
  std::vector<double> received_;
  std::vector<PetscInt> global_;
  PetscInt first_ = 0;  ///< global index of this rank's first point
  PetscSF sf_ = nullptr;
  ExchangeCounts counts_;
};

}  // namespace vibrotherm::util
