#include "vibrotherm/interface/crack_record.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

#include "vibrotherm/util/all_gather.hpp"

namespace vibrotherm::interface {
namespace {

constexpr int kFields = 20;

std::array<double, kFields> Pack(const CrackCellRecord& r) {
  return {double(r.slot), double(r.crack), r.xi, r.x, r.y, r.a, r.b, r.b0, r.N, r.T,
          double(static_cast<int>(r.state)), r.power, r.W, r.ux, r.uy, r.s1, r.s2, r.z, r.b2, r.T2};
}

CrackCellRecord Unpack(const double* v) {
  CrackCellRecord r;
  r.slot = static_cast<long>(v[0]);
  r.crack = static_cast<int>(v[1]);
  r.xi = v[2], r.x = v[3], r.y = v[4], r.a = v[5], r.b = v[6], r.b0 = v[7], r.N = v[8], r.T = v[9];
  r.state = static_cast<contact::ContactState>(static_cast<int>(v[10]));
  r.power = v[11], r.W = v[12], r.ux = v[13], r.uy = v[14];
  r.s1 = v[15], r.s2 = v[16], r.z = v[17], r.b2 = v[18], r.T2 = v[19];
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
  std::vector<double> all;
  PetscCall(util::GatherToRoot(comm, local, &all));
  on_root->clear();
  for (std::size_t k = 0; k + kFields <= all.size(); k += kFields) on_root->push_back(Unpack(&all[k]));
  const bool slotted = std::all_of(on_root->begin(), on_root->end(), [](const CrackCellRecord& r) { return r.slot >= 0; });
  const auto key = [](const CrackCellRecord& r) {  // ξ is NaN on a 3D surface: there s1, then s2
    return std::make_tuple(r.crack, std::isnan(r.xi) ? 0.0 : r.xi, r.s1, r.s2);
  };
  std::sort(on_root->begin(), on_root->end(), [slotted, &key](const CrackCellRecord& p, const CrackCellRecord& q) {
    return slotted ? p.slot < q.slot : key(p) < key(q);
  });
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface
