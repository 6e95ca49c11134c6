// The crack interface in checkpoints: per contact cell (keyed by the serial
// number of its + point, the same on any partition) the crack law's committed
// memory and the interface's own per-cell values; the accounts per rank.
#include <algorithm>

#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::interface {
namespace {
/// Per cell: a, power, W, last N, dW, state, then b and the last T along each of the crack's
/// `tangents` directions (1 in 2D, 2 in 3D).
int CellValues(int tangents) { return 6 + 2 * tangents; }
}  // namespace

PetscErrorCode CrackInterface::Save(store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) const {
  PetscFunctionBeginUser;
  std::vector<long long> keys, counts;
  std::vector<double> cells, memory;
  const int tangents = dim_ - 1;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    keys.push_back(origin[cells_[i].plus]);
    const contact::StepResult& s = last_[i];
    cells.insert(cells.end(), {a_[i], power_[i], W_[i], s.N, s.dW, static_cast<double>(s.state)});
    for (int k = 0; k < tangents; ++k) cells.push_back(b_[i][k]);
    for (int k = 0; k < tangents; ++k) cells.push_back(s.T[k]);
    const std::vector<double> state = law_->save_state(i);
    counts.push_back(static_cast<long long>(state.size()));
    memory.insert(memory.end(), state.begin(), state.end());
  }
  checkpoint.PutKeyed("crack/cells", keys, CellValues(tangents), cells);
  checkpoint.PutKeyed("crack/law", keys, counts, memory);
  checkpoint.PutPerRank("crack/accounts", {dissipated_local_, friction_excess_, largest_normal_});
  double maxima[2] = {friction_excess_, largest_normal_};
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, maxima, 2, MPI_DOUBLE, MPI_MAX, comm_));
  checkpoint.PutShared("crack/maxima", {maxima[0], maxima[1]});
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::Restore(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) {
  PetscFunctionBeginUser;
  std::vector<long long> keys, counts;
  for (const ContactCell& c : cells_) keys.push_back(origin[c.plus]);
  std::vector<double> cells, memory;
  const int tangents = dim_ - 1, values = CellValues(tangents);
  PetscCall(checkpoint.GetKeyed("crack/cells", keys, values, &cells));
  PetscCall(checkpoint.GetKeyed("crack/law", keys, &counts, &memory));
  std::size_t at = 0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const double* v = &cells[values * i];
    a_[i] = v[0], power_[i] = v[1], W_[i] = v[2];
    last_[i].N = v[3], last_[i].dW = v[4];
    last_[i].state = static_cast<contact::ContactState>(static_cast<int>(v[5]));
    b_[i] = last_[i].T = zero_slip_;
    for (int k = 0; k < tangents; ++k) b_[i][k] = v[6 + k], last_[i].T[k] = v[6 + tangents + k];
    VibrothermCallCpp(PETSC_COMM_SELF, law_->restore_state(i, memory.data() + at, static_cast<std::size_t>(counts[i])));
    at += static_cast<std::size_t>(counts[i]);
  }
  std::vector<double> accounts, maxima;
  PetscCall(checkpoint.GetPerRank("crack/accounts", &accounts));
  PetscCall(checkpoint.GetShared("crack/maxima", &maxima, 2));
  dissipated_local_ = accounts[0];
  // Maxima are not sums: on another rank count every rank starts from the global ones.
  friction_excess_ = checkpoint.same_ranks() ? accounts[1] : maxima[0];
  largest_normal_ = checkpoint.same_ranks() ? accounts[2] : maxima[1];
  PetscFunctionReturn(0);
}

std::vector<double> CrackInterface::Accumulated() const {
  std::vector<double> values = W_;
  values.push_back(dissipated_local_);
  return values;
}

void CrackInterface::JumpAhead(const std::vector<double>& increments) {
  for (std::size_t i = 0; i < W_.size(); ++i) W_[i] += increments.at(i);
  dissipated_local_ += increments.at(W_.size());
}

}  // namespace vibrotherm::interface
