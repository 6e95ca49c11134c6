#include "vibrotherm/coupling/continuation/periodic_detector.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {
namespace {

/// ‖x − y‖_M / ‖x‖_M in the lumped-mass norm (0 when both vanish): the kinetic energy of the
/// difference for velocities. Unweighted, the many small cells at the crack, where the contact
/// sheds high-frequency noise, would dominate the bulk field.
PetscErrorCode RelativeDifference(Vec x, Vec y, Vec mass, double* change) {
  PetscFunctionBeginUser;
  Vec d, md;
  PetscScalar dd, xx;
  PetscCall(VecDuplicate(x, &d));
  PetscCall(VecDuplicate(x, &md));
  PetscCall(VecWAXPY(d, -1.0, y, x));
  PetscCall(VecPointwiseMult(md, mass, d));
  PetscCall(VecDot(md, d, &dd));
  PetscCall(VecPointwiseMult(md, mass, x));
  PetscCall(VecDot(md, x, &xx));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&md));
  const double nd = std::sqrt(PetscRealPart(dd)), nx = std::sqrt(PetscRealPart(xx));
  *change = nx > 0.0 ? nd / nx : (nd > 0.0 ? INFINITY : 0.0);
  PetscFunctionReturn(0);
}

const char* kHeader = "t,multiple,change,state,memory,cells,energies\n";

}  // namespace

PeriodicDetector::~PeriodicDetector() { Reset(); }

PetscErrorCode PeriodicDetector::Open(MPI_Comm comm, const PeriodicOptions& options, const std::string& csv) {
  return Resume(comm, options, csv, -1);
}

PetscErrorCode PeriodicDetector::Resume(MPI_Comm comm, const PeriodicOptions& options, const std::string& csv,
                                        long long bytes) {
  PetscFunctionBeginUser;
  comm_ = comm;
  options_ = options;
  mean_window_ = MeanWindow(options.window);
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    VibrothermCallCpp(PETSC_COMM_SELF, file_ = store::OpenAtomicFile(csv, bytes));
    if (bytes < 0) file_->stream() << kHeader;
  }
  PetscFunctionReturn(0);
}

void PeriodicDetector::Free(Snapshot& s) const {
  VecDestroy(&s.u);
  VecDestroy(&s.v);
}

void PeriodicDetector::Reset() {
  for (Snapshot& s : samples_) Free(s);
  samples_.clear();  // last_change_ stays: the summary reports the change the last sample saw
  mean_window_.Reset();
}

PetscErrorCode PeriodicDetector::Take(ContinuedWaves& waves, const io::EnergyRow& row, Snapshot* s) const {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = waves.solver();
  Vec u, v;
  PetscCall(solver.GetFields(&u, &v));
  PetscCall(VecDuplicate(u, &s->u));
  PetscCall(VecDuplicate(v, &s->v));
  PetscCall(VecCopy(u, s->u));
  PetscCall(VecCopy(v, s->v));
  PetscCall(solver.RestoreFields(&u, &v));
  s->t = solver.time();
  s->energy = row;
  if (interface::CrackInterface* crack = waves.crack()) {
    std::vector<PetscInt> owned(crack->cells().size());
    for (std::size_t i = 0; i < owned.size(); ++i) owned[i] = static_cast<PetscInt>(i);
    std::vector<interface::CrackCellRecord> records;
    PetscCall(crack->Records(owned, nullptr, &records));
    for (const interface::CrackCellRecord& r : records) {
      s->W.push_back(r.W);
      s->T.push_back(r.T);
      s->b0.push_back(r.b0);
      s->b.push_back(r.b);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicDetector::Change(std::size_t m, const std::vector<double>& weights, double parts[4]) const {
  PetscFunctionBeginUser;
  const std::size_t k = samples_.size() - 1, span = m * static_cast<std::size_t>(window());
  const Snapshot &now = samples_[k], &back = samples_[k - m];
  double du, dv;
  PetscCall(RelativeDifference(now.u, back.u, mass_, &du));
  PetscCall(RelativeDifference(now.v, back.v, mass_, &dv));
  parts[0] = std::max(du * du, dv * dv);
  // Memory: the changes of T and b0 over the crack (squared, length-weighted), against T and b.
  double local[4] = {0.0, 0.0, 0.0, 0.0};  // Σ w ΔT², Σ w T², Σ w Δb0², Σ w b²: relative energies, as the state's
  for (std::size_t i = 0; i < now.T.size(); ++i) {
    local[0] += weights[i] * (now.T[i] - back.T[i]) * (now.T[i] - back.T[i]);
    local[1] += weights[i] * now.T[i] * now.T[i];
    local[2] += weights[i] * (now.b0[i] - back.b0[i]) * (now.b0[i] - back.b0[i]);
    local[3] += weights[i] * now.b[i] * now.b[i];
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, local, 4, MPI_DOUBLE, MPI_SUM, comm_));
  parts[1] = std::max(local[1] > 0.0 ? local[0] / local[1] : 0.0, local[3] > 0.0 ? local[2] / local[3] : 0.0);
  // Cells and energies over the last window against the window before (2 windows of samples).
  parts[2] = parts[3] = INFINITY;
  if (k < 2 * span) PetscFunctionReturn(0);
  const Snapshot &start = samples_[k - span], &before = samples_[k - 2 * span];
  double sums[2] = {0.0, 0.0};  // Σ w |ΔW − ΔW_before|, Σ w ΔW
  for (std::size_t i = 0; i < now.W.size(); ++i) {
    const double recent = now.W[i] - start.W[i], earlier = start.W[i] - before.W[i];
    sums[0] += weights[i] * std::abs(recent - earlier);
    sums[1] += weights[i] * recent;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, comm_));
  parts[2] = sums[1] > 0.0 ? sums[0] / sums[1] : 0.0;
  const auto over = [](const io::EnergyRow& a, const io::EnergyRow& b, double io::EnergyRow::*column) {
    return a.*column - b.*column;
  };
  parts[3] = 0.0;
  for (double io::EnergyRow::*column : {&io::EnergyRow::work_source, &io::EnergyRow::radiated,
                                        &io::EnergyRow::dissipated, &io::EnergyRow::damped}) {
    const double recent = over(now.energy, start.energy, column);
    const double change = std::abs(recent - over(start.energy, before.energy, column));
    if (change > 0.0) parts[3] = std::max(parts[3], recent != 0.0 ? change / std::abs(recent) : INFINITY);
  }
  // A steady state's energy flow balances over the window: what the source works, the losses take.
  const double work = over(now.energy, start.energy, &io::EnergyRow::work_source) +
                      over(now.energy, start.energy, &io::EnergyRow::work_thermal);
  const double losses = over(now.energy, start.energy, &io::EnergyRow::radiated) +
                        over(now.energy, start.energy, &io::EnergyRow::dissipated) +
                        over(now.energy, start.energy, &io::EnergyRow::damped);
  if (work != 0.0) parts[3] = std::max(parts[3], std::abs(work - losses) / std::abs(work));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicDetector::Sample(ContinuedWaves& waves, const io::EnergyRow& row, PetscInt* multiple) {
  PetscFunctionBeginUser;
  *multiple = 0;
  samples_.emplace_back();
  PetscCall(Take(waves, row, &samples_.back()));
  // Every multiple's two windows; a widened mean window (at most 4 x) fits in the same.
  const PetscInt keep = std::max(2 * window() + 1, 2 * options_.window * options_.max_multiple + 1);
  while (samples_.size() > static_cast<std::size_t>(keep)) {
    Free(samples_.front());
    samples_.pop_front();
  }
  std::vector<double> weights;
  if (interface::CrackInterface* crack = waves.crack())
    for (const interface::ContactCell& c : crack->cells()) weights.push_back(c.weight);
  last_change_ = INFINITY;
  // A statistically steady state (mean) has no period: windows of single periods, their means only.
  const std::size_t longest = options_.mean ? 1 : static_cast<std::size_t>(options_.max_multiple);
  for (std::size_t m = 1; m <= longest && m < samples_.size(); ++m) {
    double parts[4];
    PetscCall(Change(m, weights, parts));
    // The contact's cell by cell quantities against their own tolerance (their noise floor is higher).
    const double scale = options_.tol / options_.tol_cells;
    if (options_.mean) parts[3] = MeanChange();
    const double change = options_.mean ? parts[3]
                                        : std::max({parts[0], parts[1] * scale, parts[3], parts[2] * scale});
    last_change_ = std::min(last_change_, change);
    if (file_)
      file_->stream() << samples_.back().t << ',' << m << ',' << change << ',' << parts[0] << ',' << parts[1] << ','
                      << parts[2] << ',' << parts[3] << '\n';
    if (change < options_.tol) {
      *multiple = static_cast<PetscInt>(m);
      break;
    }
  }
  if (options_.mean) PetscCall(WidenMeanWindow(*multiple > 0));
  PetscFunctionReturn(0);
}

PetscErrorCode PeriodicDetector::WidenMeanWindow(bool passed) {
  PetscFunctionBeginUser;
  if (mean_window_.After(std::isfinite(last_change_), passed))
    PetscCall(PetscPrintf(comm_, "periodic (mean): the heat per period scatters by %.2g of its mean over windows of "
                          "%ld periods: windows of %ld periods from here\n",
                          last_change_, mean_window_.window() / 2, mean_window_.window()));
  PetscFunctionReturn(0);
}

double PeriodicDetector::MeanChange() const {
  const std::size_t n = static_cast<std::size_t>(window()), k = samples_.size() - 1;
  if (n < 2 || k < 2 * n) return INFINITY;
  double change = 0.0;
  std::vector<double> per_period(2 * n);  // newest first
  for (double io::EnergyRow::*column : {&io::EnergyRow::dissipated, &io::EnergyRow::damped}) {
    for (std::size_t j = 0; j < 2 * n; ++j)
      per_period[j] = samples_[k - j].energy.*column - samples_[k - j - 1].energy.*column;
    change = std::max(change, MeanWindowChange(per_period, n, options_.tol));
  }
  return change;
}

void PeriodicDetector::FrictionDrift(PetscInt m, double* slope, double* error) const {
  *slope = *error = 0.0;
  std::vector<double> F;  // oldest first
  for (std::ptrdiff_t k = static_cast<std::ptrdiff_t>(samples_.size()) - 1; k >= m; k -= m)
    F.insert(F.begin(), samples_[k].energy.dissipated - samples_[k - m].energy.dissipated);
  const std::size_t n = F.size();
  if (n < 4) return;
  double mean = 0.0, x_mean = 0.5 * static_cast<double>(n - 1);
  for (double f : F) mean += f / static_cast<double>(n);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    sxx += (j - x_mean) * (j - x_mean);
    sxy += (j - x_mean) * (F[j] - mean);
  }
  const double b = sxy / sxx;
  double residual = 0.0;
  for (std::size_t j = 0; j < n; ++j) residual += std::pow(F[j] - mean - b * (j - x_mean), 2);
  if (mean <= 0.0) return;
  *slope = b / mean / static_cast<double>(m);
  *error = std::sqrt(residual / static_cast<double>(n - 2) / sxx) / mean / static_cast<double>(m);
}

PetscErrorCode PeriodicDetector::Finish() {
  PetscFunctionBeginUser;
  if (file_) VibrothermCallIo(PETSC_COMM_SELF, file_->commit());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
