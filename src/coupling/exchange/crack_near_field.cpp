#include "vibrotherm/coupling/exchange/crack_near_field.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace vibrotherm::coupling {
namespace {

/// Distance from x to the segment [a, b].
double SegmentDistance(const std::array<double, 2>& x, const std::array<double, 2>& a, const std::array<double, 2>& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
  const double s = l2 > 0 ? std::clamp(((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
  return std::hypot(x[0] - a[0] - s * dx, x[1] - a[1] - s * dy);
}

}  // namespace

CrackNearField::~CrackNearField() {
  for (Probe& p : probes_) (void)VecDestroy(&p.phi);
}

bool CrackNearField::any() const {
  return std::any_of(probes_.begin(), probes_.end(), [](const Probe& p) { return p.active; });
}

PetscErrorCode CrackNearField::Setup(const interface::CrackInterface& crack, const FrictionHeat& friction,
                                     heat::HeatSolver* heat, const heat::HeatProbes& probes, PetscInt steps,
                                     double heat_step) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventRegister("NearFieldSetup", TS_CLASSID, &setup_event_));
  PetscCall(PetscLogEventRegister("NearFieldStep", TS_CLASSID, &step_event_));
  PetscCall(PetscLogEventRegister("NearFieldExact", TS_CLASSID, &exact_event_));
  PetscCall(PetscLogEventRegister("NearFieldRespond", TS_CLASSID, &response_event_));
  PetscCall(PetscLogEventBegin(setup_event_, 0, 0, 0, 0));
  crack_ = &crack;
  friction_ = &friction;
  heat_ = heat;
  steps_ = steps;
  alpha_ = heat->material().diffusivity();
  rho_c_ = heat->material().density * heat->material().capacity;
  owned_cells_ = crack.cells().size();
  // The oldest age a row meets is K heat steps; room for steps that grow.
  tau_max_ = 2.0 * static_cast<double>(steps + 1) * heat_step;
  // exp(−reach²/(4ατ_max)) = exp(−25): the continuum heat of cells beyond is below rounding.
  const double reach = 10.0 * std::sqrt(alpha_ * tau_max_);
  const std::vector<double>& xy = probes.coordinates();  // 2D: x, y pairs
  probes_.resize(xy.size() / 2);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    const std::array<double, 2> x = {xy[2 * p], xy[2 * p + 1]};
    PetscCall(FindNearCells(p, x, reach));
    bool clear = false;
    if (probes_[p].active) PetscCall(ClearOfEdges(x, reach, &clear));
    probes_[p].active = probes_[p].active && clear;
    if (!probes_[p].active) continue;
    PetscCall(DMCreateGlobalVector(heat->space().dm(), &probes_[p].phi));
    PetscCall(probes.Functional(p, probes_[p].phi));
  }
  ends_ = {heat->time()};
  fine_ = {{heat->time(), std::vector<double>(owned_cells_, 0.0)}};
  density_.clear();
  equal_step_ = 0.0;
  PetscCall(PetscLogEventEnd(setup_event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackNearField::FindNearCells(std::size_t p, const std::array<double, 2>& x, double reach) {
  PetscFunctionBeginUser;
  std::map<std::pair<int, double>, std::array<double, 2>> where;  // (crack, ξ) → vertex
  for (const auto& v : friction_->crack_vertices()) where[{static_cast<int>(v[0]), v[1]}] = {v[2], v[3]};
  const long first = friction_->first_cell(), last = first + static_cast<long>(owned_cells_);
  Probe& probe = probes_[p];
  std::vector<KernelSegment> segments;
  long near = 0;
  for (const CrackElement& e : friction_->wave_elements()) {
    KernelSegment g;
    g.p0 = where.at({e.crack, e.xi0});
    g.p1 = where.at({e.crack, e.xi1});
    g.degree = e.degree;
    if (SegmentDistance(x, g.p0, g.p1) > reach) continue;
    ++near;
    for (int n = 0; n < 3; ++n) {
      if (e.node[n] < first || e.node[n] >= last) continue;  // another rank's cell (or none)
      const int owned = static_cast<int>(e.node[n] - first);
      const auto known = std::find(probe.cells.begin(), probe.cells.end(), owned);
      g.cell[n] = static_cast<int>(known - probe.cells.begin());
      if (known == probe.cells.end()) probe.cells.push_back(owned);
    }
    segments.push_back(g);
  }
  // Every rank sees every element: `near` is the same everywhere.
  probe.active = near > 0;
  if (probe.active)
    probe.kernel.Build(x, segments, static_cast<int>(probe.cells.size()), alpha_, rho_c_, tau_max_);
  PetscFunctionReturn(0);
}

PetscErrorCode CrackNearField::ClearOfEdges(const std::array<double, 2>& x, double reach, bool* clear) const {
  PetscFunctionBeginUser;
  // The continuum kernel is the infinite plate's: no outer edge may be within reach.
  double distance;
  PetscCall(heat::DistanceToOuterEdges(PetscObjectComm((PetscObject)heat_->space().dm()), heat_->boundary(), x[0], x[1],
                                       &distance));
  *clear = distance > reach;
  PetscFunctionReturn(0);
}

void CrackNearField::AfterWaveStep(double t) { SampleEnergies(t, crack_->dissipated_per_area()); }

void CrackNearField::SampleEnergies(double t, const std::vector<double>& W) {
  if (any() && !paused_) fine_.push_back({t, W});
}

void CrackNearField::Pause(double t) {
  paused_ = true;
  ends_ = {t};
  density_.clear();
  fine_.clear();
  for (Probe& p : probes_) p.terms.clear(), p.jumps.clear();
}

void CrackNearField::Restart(double t) {
  if (!paused_) return;
  Pause(t);
  paused_ = false;
  fine_.push_back({t, crack_->dissipated_per_area()});
}

PetscErrorCode CrackNearField::AfterHeatStep(double t) {
  PetscFunctionBeginUser;
  if (!any() || paused_) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(step_event_, 0, 0, 0, 0));
  ends_.push_back(t);
  density_.push_back(friction_->density());
  Prune();
  PetscCall(Terms());
  Jumps();
  if (t - ends_.front() > tau_max_) {  // steps grew beyond the kernels' range
    tau_max_ *= 2.0;
    for (Probe& p : probes_)
      if (p.active) p.kernel.Rebuild(tau_max_);
  }
  PetscCall(PetscLogEventEnd(step_event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

void CrackNearField::Prune() {
  while (ends_.size() > static_cast<std::size_t>(steps_) + 1) ends_.pop_front();
  while (density_.size() > static_cast<std::size_t>(steps_)) density_.pop_front();
  // The window's energies start from the last sample at or before its start.
  while (fine_.size() > 1 && fine_[1].t <= ends_.front()) fine_.pop_front();
}

PetscErrorCode CrackNearField::Terms() {
  PetscFunctionBeginUser;
  std::vector<double> lengths;  // h_n, h_{n−1}, ... of the window, newest first
  for (std::size_t i = ends_.size() - 1; i > 0; --i) lengths.push_back(ends_[i] - ends_[i - 1]);
  const double h = lengths.front();
  const bool equal = std::all_of(lengths.begin(), lengths.end(), [h](double x) { return std::abs(x - h) <= 1e-10 * h; });
  if (equal && std::abs(h - equal_step_) > 1e-10 * h) PetscCall(EqualStepResponses(h));
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    Probe& probe = probes_[p];
    if (!probe.active) continue;
    std::vector<std::vector<double>> own;  // a window of unequal steps: its own responses
    if (!equal) {
      std::vector<Vec> w;
      bool supported;
      PetscCall(PetscLogEventBegin(response_event_, 0, 0, 0, 0));
      PetscCall(heat_->StepResponses(probe.phi, lengths, &w, &supported));
      own.resize(w.size());
      for (std::size_t k = 0; k < w.size(); ++k) {
        PetscCall(friction_->CellResponse(w[k], &own[k]));
        PetscCall(VecDestroy(&w[k]));
      }
      PetscCall(PetscLogEventEnd(response_event_, 0, 0, 0, 0));
    }
    const std::vector<std::vector<double>>& g = equal ? probe.g : own;
    std::vector<double> terms(lengths.size(), 0.0);
    for (std::size_t k = 0; k < lengths.size() && k < g.size(); ++k) {
      const std::vector<double>& q = density_[density_.size() - 1 - k];
      for (std::size_t c = 0; c < q.size(); ++c) terms[k] += g[k][c] * q[c];
    }
    probe.terms.push_back(std::move(terms));
    if (probe.terms.size() > 3) probe.terms.pop_front();
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CrackNearField::EqualStepResponses(double h) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(response_event_, 0, 0, 0, 0));
  equal_step_ = h;
  const std::vector<double> lengths(static_cast<std::size_t>(steps_), h);
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    Probe& probe = probes_[p];
    if (!probe.active) continue;
    std::vector<Vec> w;
    bool supported;
    PetscCall(heat_->StepResponses(probe.phi, lengths, &w, &supported));
    if (!supported) {  // the same on every rank
      PetscCall(PetscPrintf(PetscObjectComm((PetscObject)probe.phi),
                            "vibrotherm: warning: -heat_ts_type is not of the theta family: the crack probes read the "
                            "heat field without the near-field correction\n"));
      for (Probe& q : probes_) q.active = false;
      break;
    }
    probe.g.resize(w.size());
    for (std::size_t k = 0; k < w.size(); ++k) {
      PetscCall(friction_->CellResponse(w[k], &probe.g[k]));
      PetscCall(VecDestroy(&w[k]));
    }
  }
  PetscCall(PetscLogEventEnd(response_event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

std::array<double, 3> CrackNearField::Discrete(std::size_t p) const {
  // D at t_{n−j} for the window (t_{n−K}, ·]: the terms of step n − j with lag below K − j.
  std::array<double, 3> d = {0.0, 0.0, 0.0};
  const std::deque<std::vector<double>>& terms = probes_[p].terms;
  for (std::size_t j = 0; j < 3 && j < terms.size(); ++j) {
    const std::vector<double>& t = terms[terms.size() - 1 - j];
    for (std::size_t k = 0; k < t.size() && k + j < static_cast<std::size_t>(steps_); ++k) d[j] += t[k];
  }
  return d;
}

void CrackNearField::Jumps() {
  for (Probe& probe : probes_) {
    if (!probe.active) continue;
    const std::size_t n = probe.cells.size();
    probe.jumps.assign(n * (fine_.size() > 0 ? fine_.size() - 1 : 0), 0.0);
    std::vector<double> previous(n, 0.0);  // q before the window: its heat is the mesh's
    for (std::size_t b = 0; b + 1 < fine_.size(); ++b) {
      const double rate = 1.0 / (fine_[b + 1].t - fine_[b].t);
      for (std::size_t c = 0; c < n; ++c) {
        const int i = probe.cells[c];
        const double q = (fine_[b + 1].W[i] - fine_[b].W[i]) * rate;
        probe.jumps[b * n + c] = q - previous[c];
        previous[c] = q;
      }
    }
  }
}

PetscErrorCode CrackNearField::Exact(std::size_t p, const std::vector<double>& times, std::vector<double>* e) const {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(exact_event_, 0, 0, 0, 0));
  // Σ_j q_j [Φ(t − t_{j−1}) − Φ(t − t_j)] = Σ_b (q_{b+1} − q_b) Φ(t − t_b) over the wave
  // steps ending by t (summation by parts; Φ(0) = 0).
  const Probe& probe = probes_[p];
  const std::size_t n = probe.cells.size();
  e->assign(times.size(), 0.0);
  for (std::size_t r = 0; r < times.size(); ++r) {
    const double t = times[r];
    for (std::size_t b = 0; b + 1 < fine_.size() && fine_[b + 1].t <= t + 1e-12 * std::abs(t); ++b)
      (*e)[r] += probe.kernel.Combine(&probe.jumps[b * n], t - fine_[b].t);
  }
  PetscCall(PetscLogEventEnd(exact_event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
