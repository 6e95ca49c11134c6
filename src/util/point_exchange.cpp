#include "vibrotherm/util/point_exchange.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>

#include "vibrotherm/util/all_gather.hpp"

namespace vibrotherm::util {
namespace {

/// A box's margin, relative to its largest extent: far above the cell locator's
/// tolerance (1e-10 of a cell), far below a cell, so a point a rank can locate is in its box.
constexpr double kRelativeMargin = 1e-6;

Box Inflated(const Box& box) {
  double extent = 0.0, magnitude = 0.0;
  for (int d = 0; d < 3; ++d) {
    if (box.lo[d] > box.hi[d]) return box;  // empty: holds nothing
    extent = std::max(extent, box.hi[d] - box.lo[d]);
    magnitude = std::max({magnitude, std::abs(box.lo[d]), std::abs(box.hi[d])});
  }
  const double pad = kRelativeMargin * extent + 1e-12 * magnitude;
  Box inflated = box;
  for (int d = 0; d < 3; ++d) inflated.lo[d] -= pad, inflated.hi[d] += pad;
  return inflated;
}

bool Holds(const Box& box, const double* x) {
  for (int d = 0; d < 3; ++d)
    if (!(x[d] >= box.lo[d] && x[d] <= box.hi[d])) return false;
  return true;
}

}  // namespace

PointExchange::~PointExchange() { (void)PetscSFDestroy(&sf_); }

PetscErrorCode PointExchange::Setup(MPI_Comm comm, const Box& box, const std::vector<double>& mine,
                                    std::size_t stride) {
  PetscFunctionBeginUser;
  PetscCheck(stride >= 3 && mine.size() % stride == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
             "point exchange: %zu values are not points of %zu", mine.size(), stride);
  PetscLogEvent event;
  PetscCall(PetscLogEventRegister("PointExchangeSetup", PETSCSF_CLASSID, &event));
  PetscCall(PetscLogEventBegin(event, 0, 0, 0, 0));
  comm_ = comm;
  stride_ = stride;
  PetscCall(PetscSFDestroy(&sf_));
  const Box own = Inflated(box);
  std::vector<double> all;
  PetscCall(AllGather(comm, {own.lo[0], own.lo[1], own.lo[2], own.hi[0], own.hi[1], own.hi[2]}, &all));
  boxes_.resize(all.size() / 6);
  for (std::size_t r = 0; r < boxes_.size(); ++r)
    for (int d = 0; d < 3; ++d) boxes_[r].lo[d] = all[6 * r + d], boxes_[r].hi[d] = all[6 * r + 3 + d];
  const PetscInt n = static_cast<PetscInt>(mine.size() / stride);
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  first_ = 0;
  PetscCallMPI(MPI_Exscan(&n, &first_, 1, MPIU_INT, MPI_SUM, comm));
  if (rank == 0) first_ = 0;  // MPI_Exscan leaves rank 0's result undefined
  counts_ = ExchangeCounts{};
  counts_.mine = static_cast<std::size_t>(n);
  global_.clear();
  std::vector<PetscMPIInt> ranks;
  std::vector<PetscInt> sizes;
  PetscCall(SendLists(mine, &ranks, &sizes));
  PetscCall(BuildGraph(ranks, sizes));
  PetscCall(SendPoints(mine));
  PetscCall(PetscLogEventEnd(event, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode PointExchange::SendLists(const std::vector<double>& mine, std::vector<PetscMPIInt>* ranks,
                                        std::vector<PetscInt>* sizes) {
  PetscFunctionBeginUser;
  const std::size_t n = mine.size() / stride_;
  std::vector<std::vector<PetscInt>> to(boxes_.size());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t r = 0; r < boxes_.size(); ++r)
      if (Holds(boxes_[r], &mine[stride_ * i])) to[r].push_back(static_cast<PetscInt>(i));
  slots_.clear();
  for (std::size_t r = 0; r < to.size(); ++r) {
    if (to[r].empty()) continue;
    ranks->push_back(static_cast<PetscMPIInt>(r));
    sizes->push_back(static_cast<PetscInt>(to[r].size()));
    slots_.insert(slots_.end(), to[r].begin(), to[r].end());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PointExchange::BuildGraph(const std::vector<PetscMPIInt>& ranks, const std::vector<PetscInt>& sizes) {
  PetscFunctionBeginUser;
  std::vector<PetscInt> todata;  // per destination: how many points, where they start among the slots, first_
  PetscInt offset = 0;
  for (PetscInt size : sizes) todata.insert(todata.end(), {size, offset, first_}), offset += size;
  PetscMPIInt nfrom = 0, *from = nullptr;
  PetscInt* fromdata = nullptr;
  PetscCall(PetscCommBuildTwoSided(comm_, 3, MPIU_INT, static_cast<PetscMPIInt>(ranks.size()), ranks.data(),
                                   todata.data(), &nfrom, &from, &fromdata));
  std::vector<PetscMPIInt> order(nfrom);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](PetscMPIInt a, PetscMPIInt b) { return from[a] < from[b]; });
  std::vector<PetscSFNode> remote;  // by sender rank, then the sender's order: by global index
  for (PetscMPIInt j : order)
    for (PetscInt k = 0; k < fromdata[3 * j]; ++k) {
      remote.push_back({from[j], fromdata[3 * j + 1] + k});
      global_.push_back(fromdata[3 * j + 2]);  // the sender's first index; its point's place added below
    }
  PetscCall(PetscFree(from));
  PetscCall(PetscFree(fromdata));
  // The slots' points to the leaves, then the graph again with the points themselves as roots
  // (a point sent to several ranks is one root of several leaves: no send buffer).
  PetscSF slots;
  std::vector<PetscInt> place(remote.size());
  PetscCall(PetscSFCreate(comm_, &slots));
  PetscCall(PetscSFSetGraph(slots, static_cast<PetscInt>(slots_.size()), static_cast<PetscInt>(remote.size()), nullptr,
                            PETSC_COPY_VALUES, remote.data(), PETSC_USE_POINTER));
  PetscCall(PetscSFBcastBegin(slots, MPIU_INT, slots_.data(), place.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(slots, MPIU_INT, slots_.data(), place.data(), MPI_REPLACE));
  PetscCall(PetscSFDestroy(&slots));
  for (std::size_t k = 0; k < remote.size(); ++k) remote[k].index = place[k], global_[k] += place[k];
  PetscCall(PetscSFCreate(comm_, &sf_));
  PetscCall(PetscSFSetGraph(sf_, static_cast<PetscInt>(counts_.mine), static_cast<PetscInt>(remote.size()), nullptr,
                            PETSC_COPY_VALUES, remote.data(), PETSC_COPY_VALUES));
  PetscCall(PetscSFSetUp(sf_));
  PetscFunctionReturn(0);
}

PetscErrorCode PointExchange::SendPoints(const std::vector<double>& mine) {
  PetscFunctionBeginUser;
  received_.resize(stride_ * global_.size());
  MPI_Datatype unit;
  PetscCallMPI(MPI_Type_contiguous(static_cast<PetscMPIInt>(stride_), MPI_DOUBLE, &unit));
  PetscCallMPI(MPI_Type_commit(&unit));
  PetscCall(PetscSFBcastBegin(sf_, unit, mine.data(), received_.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf_, unit, mine.data(), received_.data(), MPI_REPLACE));
  PetscCallMPI(MPI_Type_free(&unit));
  counts_.sent = slots_.size();
  counts_.received = global_.size();
  const PetscInt n = static_cast<PetscInt>(counts_.mine);
  PetscCallMPI(MPI_Allreduce(&n, &counts_.total, 1, MPIU_INT, MPI_SUM, comm_));
  // The points received, their global indices and the SF's remote roots (kept), the slots (setup only).
  counts_.bytes = (sizeof(double) * stride_ + sizeof(PetscInt) + sizeof(PetscSFNode)) * counts_.received +
                  sizeof(PetscInt) * counts_.sent;
  std::vector<PetscInt>().swap(slots_);
  PetscCall(PetscInfo(nullptr, "point exchange: %zu points here, %zu copies sent, %zu received of %" PetscInt_FMT
                               " in all; %zu bytes (an all-gather: %zu)\n", counts_.mine, counts_.sent,
                      counts_.received, counts_.total, counts_.bytes,
                      sizeof(double) * stride_ * static_cast<std::size_t>(counts_.total)));
  PetscFunctionReturn(0);
}

PetscErrorCode PointExchange::Settle(const std::vector<char>& accepted, const std::vector<double>& mine,
                                     std::vector<std::size_t>* owned, LostPoints* lost) {
  PetscFunctionBeginUser;
  PetscCheck(accepted.size() == global_.size() && mine.size() == stride_ * counts_.mine, PETSC_COMM_SELF,
             PETSC_ERR_ARG_SIZ, "point exchange: %zu answers for %zu points received, %zu values for %zu points",
             accepted.size(), global_.size(), mine.size(), counts_.mine);
  PetscLogEvent event;
  PetscCall(PetscLogEventRegister("PointExchangeOwner", PETSCSF_CLASSID, &event));
  PetscCall(PetscLogEventBegin(event, 0, 0, 0, 0));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  std::vector<int> leaf(accepted.size()), owner(counts_.mine, INT_MAX);
  for (std::size_t k = 0; k < accepted.size(); ++k) leaf[k] = accepted[k] ? rank : INT_MAX;
  PetscCall(PetscSFReduceBegin(sf_, MPI_INT, leaf.data(), owner.data(), MPI_MIN));  // each point's candidates
  PetscCall(PetscSFReduceEnd(sf_, MPI_INT, leaf.data(), owner.data(), MPI_MIN));
  PetscCall(PetscSFBcastBegin(sf_, MPI_INT, owner.data(), leaf.data(), MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf_, MPI_INT, owner.data(), leaf.data(), MPI_REPLACE));
  owned->clear();
  for (std::size_t k = 0; k < leaf.size(); ++k)
    if (leaf[k] == rank) owned->push_back(k);
  counts_.owned = owned->size();
  PetscCall(FindLost(owner, mine, lost));
  PetscCall(PetscLogEventEnd(event, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode PointExchange::FindLost(const std::vector<int>& owner, const std::vector<double>& mine,
                                       LostPoints* lost) {
  PetscFunctionBeginUser;
  PetscInt count = 0, first = PETSC_MAX_INT;
  for (std::size_t i = 0; i < owner.size(); ++i)
    if (owner[i] == INT_MAX && count++ == 0) first = first_ + static_cast<PetscInt>(i);
  *lost = LostPoints{};
  PetscCallMPI(MPI_Allreduce(&count, &lost->count, 1, MPIU_INT, MPI_SUM, comm_));
  if (lost->count == 0) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Allreduce(&first, &lost->first, 1, MPIU_INT, MPI_MIN, comm_));
  std::array<double, 3> x = {0, 0, 0};  // from the rank that holds it, zeros from the others
  if (first == lost->first) std::copy_n(&mine[stride_ * (first - first_)], 3, x.begin());
  PetscCallMPI(MPI_Allreduce(x.data(), lost->x.data(), 3, MPI_DOUBLE, MPI_SUM, comm_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::util
