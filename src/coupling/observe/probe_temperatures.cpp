#include "vibrotherm/coupling/observe/probe_temperatures.hpp"

#include <cmath>

namespace vibrotherm::coupling {
namespace {

/// Lagrange weights at t of the nodes ts (1 to 3 of them).
std::vector<double> LagrangeWeights(const std::vector<double>& ts, double t) {
  std::vector<double> w(ts.size(), 1.0);
  for (std::size_t i = 0; i < ts.size(); ++i)
    for (std::size_t j = 0; j < ts.size(); ++j)
      if (j != i) w[i] *= (t - ts[j]) / (ts[i] - ts[j]);
  return w;
}

}  // namespace

PetscErrorCode ProbeTemperatures::Setup(heat::HeatSolver* heat, const std::vector<double>& points) {
  PetscFunctionBeginUser;
  heat_ = heat;
  PetscCall(probes_.Locate(heat->space(), points));
  std::vector<double> rise;
  PetscCall(FieldRise(&rise));
  functionals_.clear();
  Vec phi;
  PetscCall(DMCreateGlobalVector(heat->space().dm(), &phi));
  for (std::size_t p = 0; p < rise.size(); ++p) {
    PetscCall(probes_.Functional(p, phi));
    const PetscScalar* x;
    PetscInt n;
    PetscCall(VecGetLocalSize(phi, &n));
    PetscCall(VecGetArrayRead(phi, &x));
    functionals_.emplace_back();
    for (PetscInt i = 0; i < n; ++i)
      if (PetscRealPart(x[i]) != 0.0) functionals_.back().push_back({i, PetscRealPart(x[i])});
    PetscCall(VecRestoreArrayRead(phi, &x));
  }
  PetscCall(VecDestroy(&phi));
  PetscCall(PartialRise(&rise));
  samples_ = {{heat->time(), rise}};
  PetscFunctionReturn(0);
}

PetscErrorCode ProbeTemperatures::PartialRise(std::vector<double>* rise) const {
  PetscFunctionBeginUser;
  const PetscScalar* theta;
  PetscCall(VecGetArrayRead(heat_->rise(), &theta));
  rise->assign(functionals_.size(), 0.0);
  for (std::size_t p = 0; p < functionals_.size(); ++p)
    for (const auto& [i, w] : functionals_[p]) (*rise)[p] += w * PetscRealPart(theta[i]);
  PetscCall(VecRestoreArrayRead(heat_->rise(), &theta));
  PetscFunctionReturn(0);
}

PetscErrorCode ProbeTemperatures::SetupNearField(const interface::CrackInterface& crack, const FrictionHeat& friction,
                                                 PetscInt steps, double heat_step) {
  PetscFunctionBeginUser;
  near_ = std::make_unique<CrackNearField>();
  PetscCall(near_->Setup(crack, friction, heat_, probes_, steps, heat_step));
  if (!near_->any()) near_.reset();
  PetscFunctionReturn(0);
}

PetscErrorCode ProbeTemperatures::FieldRise(std::vector<double>* rise) const {
  PetscFunctionBeginUser;
  PetscCall(probes_.Temperatures(heat_->rise(), heat_->material().T0, rise));
  for (double& r : *rise) r -= heat_->material().T0;
  PetscFunctionReturn(0);
}

void ProbeTemperatures::AfterWaveStep(double t, bool row) {
  if (near_) near_->AfterWaveStep(t);
  if (row) rows_.push_back(t);
}

PetscErrorCode ProbeTemperatures::AfterHeatStep() {
  PetscFunctionBeginUser;
  const double t = heat_->time();
  Sample now{t, {}};
  PetscCall(PartialRise(&now.rise));
  samples_.push_back(now);
  if (samples_.size() > 3) samples_.pop_front();
  if (near_) PetscCall(near_->AfterHeatStep(t));
  // Nodes newest first, as CrackNearField::Discrete orders its values.
  std::vector<double> ts;
  for (auto s = samples_.rbegin(); s != samples_.rend(); ++s) ts.push_back(s->t);
  if (rows_.empty() || rows_.back() < t * (1 - 1e-14)) rows_.push_back(t);  // the step's end is a sample too
  const std::size_t probes = now.rise.size();
  std::vector<std::array<double, 3>> discrete(probes, {0.0, 0.0, 0.0});
  for (std::size_t p = 0; p < probes && near_; ++p)
    if (near_->active(p)) discrete[p] = near_->Discrete(p);
  std::size_t done = 0;
  while (done < rows_.size() && rows_[done] <= t * (1 + 1e-14)) ++done;
  const std::vector<double> times(rows_.begin(), rows_.begin() + static_cast<long>(done));
  const std::size_t first = closed_.size();
  for (double tr : times) {
    const std::vector<double> w = LagrangeWeights(ts, tr);
    Row row{tr, std::vector<double>(probes, 0.0)};
    for (std::size_t p = 0; p < probes; ++p)
      for (std::size_t j = 0; j < ts.size(); ++j)
        row.part[p] += w[j] * (samples_[samples_.size() - 1 - j].rise[p] - discrete[p][j]);
    closed_.push_back(std::move(row));
  }
  std::vector<double> exact;
  for (std::size_t p = 0; p < probes && near_; ++p) {
    if (!near_->active(p)) continue;
    PetscCall(near_->Exact(p, times, &exact));
    for (std::size_t r = 0; r < times.size(); ++r) closed_[first + r].part[p] += exact[r];
  }
  rows_.erase(rows_.begin(), rows_.begin() + static_cast<long>(done));
  PetscFunctionReturn(0);
}

PetscErrorCode ProbeTemperatures::Collect(io::TemperatureSeries* series) {
  PetscFunctionBeginUser;
  const double T0 = heat_->material().T0;
  series->t.clear();
  series->T.clear();
  if (closed_.empty()) {  // no heat step since: the field now (t = 0, the heat running alone)
    std::vector<double> rise;
    PetscCall(FieldRise(&rise));
    series->t.push_back(heat_->time());
    series->T.push_back(rise);
    for (double& r : series->T.back()) r += T0;
    rows_.clear();
    PetscFunctionReturn(0);
  }
  std::vector<double> part, sum;
  for (const Row& r : closed_) part.insert(part.end(), r.part.begin(), r.part.end());
  sum.resize(part.size());
  PetscCallMPI(MPI_Allreduce(part.data(), sum.data(), static_cast<int>(part.size()), MPI_DOUBLE, MPI_SUM,
                             PetscObjectComm((PetscObject)heat_->space().dm())));
  std::size_t k = 0;
  for (const Row& r : closed_) {
    series->t.push_back(r.t);
    series->T.emplace_back();
    for (std::size_t p = 0; p < r.part.size(); ++p) series->T.back().push_back(T0 + sum[k++]);
  }
  closed_.clear();
  PetscFunctionReturn(0);
}

PetscErrorCode ProbeTemperatures::Save(store::Checkpoint& checkpoint, const std::vector<long long>& cell_keys) const {
  PetscFunctionBeginUser;
  std::vector<double> times, rises;  // this rank's parts (another partition: their sums on rank 0)
  for (const Sample& s : samples_) {
    times.push_back(s.t);
    rises.insert(rises.end(), s.rise.begin(), s.rise.end());
  }
  checkpoint.PutShared("probe_temperatures/times", times);
  checkpoint.PutPerRank("probe_temperatures/rises", rises);
  if (near_) PetscCall(near_->Save(checkpoint, cell_keys));
  PetscFunctionReturn(0);
}

PetscErrorCode ProbeTemperatures::Restore(const store::Checkpoint& checkpoint, const std::vector<long long>& cell_keys) {
  PetscFunctionBeginUser;
  std::vector<double> times, rises;
  PetscCall(checkpoint.GetShared("probe_temperatures/times", &times));
  PetscCall(checkpoint.GetPerRank("probe_temperatures/rises", &rises));
  const std::size_t probes = functionals_.size();
  samples_.clear();
  for (std::size_t k = 0; k < times.size(); ++k)
    samples_.push_back({times[k], std::vector<double>(rises.begin() + static_cast<long>(k * probes),
                                                      rises.begin() + static_cast<long>((k + 1) * probes))});
  rows_.clear();
  closed_.clear();
  if (near_) PetscCall(near_->Restore(checkpoint, cell_keys));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
