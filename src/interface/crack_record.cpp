#include "vibrotherm/interface/crack_record.hpp"

#include <algorithm>
#include <array>

namespace vibrotherm::interface {
namespace {

constexpr int kFields = 15;

std::array<double, kFields> Pack(const CrackCellRecord& r) {
  return {double(r.slot), double(r.crack), r.xi, r.x, r.y, r.a, r.b, r.b0, r.N, r.T,
          double(static_cast<int>(r.state)), r.power, r.W, r.ux, r.uy};
}

CrackCellRecord Unpack(const double* v) {
  CrackCellRecord r;
  r.slot = static_cast<long>(v[0]);
  r.crack = static_cast<int>(v[1]);
  r.xi = v[2], r.x = v[3], r.y = v[4], r.a = v[5], r.b = v[6], r.b0 = v[7], r.N = v[8], r.T = v[9];
  r.state = static_cast<contact::ContactState>(static_cast<int>(v[10]));
  r.power = v[11], r.W = v[12], r.ux = v[13], r.uy = v[14];
  return r;
}

}  // namespace

PetscErrorCode GatherCrackRecords(MPI_Comm comm, const std::vector<CrackCellRecord>& mine,
                                  std::vector<CrackCellRecord>* on_root) {
  PetscFunctionBeginUser;
  std::vector<double> local;
  local.reserve(kFields * mine.size());
  for (const CrackCellRecord& r : mine) {
    const auto packed = Pack(r);
    local.insert(local.end(), packed.begin(), packed.end());
  }
  PetscMPIInt size, rank;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int n = static_cast<int>(local.size());
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(rank == 0 ? displs.back() + counts.back() : 0);
  PetscCallMPI(MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm));
  on_root->clear();
  for (std::size_t k = 0; k + kFields <= all.size(); k += kFields) on_root->push_back(Unpack(&all[k]));
  const bool slotted = std::all_of(on_root->begin(), on_root->end(), [](const CrackCellRecord& r) { return r.slot >= 0; });
  std::sort(on_root->begin(), on_root->end(), [slotted](const CrackCellRecord& p, const CrackCellRecord& q) {
    if (slotted) return p.slot < q.slot;
    return p.crack != q.crack ? p.crack < q.crack : p.xi < q.xi;
  });
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface
