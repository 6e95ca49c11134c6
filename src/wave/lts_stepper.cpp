#include "vibrotherm/wave/lts_stepper.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/wave/elastic_operator.hpp"
#include "vibrotherm/wave/stability.hpp"
#include "vibrotherm/wave/step_control.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::wave {

struct LtsStepper::Level {
  Mat A = nullptr;  ///< −M⁻¹K_l; null for a level of the contact alone
  BlockKernel kernel;
  std::vector<PetscInt> element_rows;  ///< owned dofs of its cells
  std::vector<PetscInt> kick_rows;     ///< element rows, and the contact's dofs at the contact level
  std::vector<PetscInt> contact_only;  ///< contact dofs that are not element rows (their force is the contact's alone)
  std::vector<PetscInt> drift;         ///< dofs moving at its rate
  Vec a = nullptr;                     ///< its acceleration at the current state
  std::unique_ptr<WaveBoundary> boundary;               ///< boundary nodes moving at its rate
  std::vector<std::unique_ptr<BoundaryTerm>> terms;     ///< acting in its kicks
  ~Level() {
    (void)MatDestroy(&A);
    (void)VecDestroy(&a);
  }
};

LtsStepper::LtsStepper() = default;
LtsStepper::~LtsStepper() {
  (void)VecDestroy(&scratch_);
  (void)VecDestroy(&work_);
}

PetscErrorCode LtsStepper::AddLevel() {
  PetscFunctionBeginUser;
  PetscCheck(level_.size() < 40, comm_, PETSC_ERR_NOT_CONVERGED,
             "local time stepping: the crack contact needs more than 40 levels (a step below H/2^40): the contact law is "
             "too stiff for an explicit step");
  level_.push_back(std::make_unique<Level>());
  PetscCall(VecDuplicate(mass_, &level_.back()->a));
  PetscCall(VecSet(level_.back()->a, 0.0));
  info_.emplace_back();
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::SetupLevel(PetscInt l, const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                      const LtsLevels& levels, const std::vector<char>& touched) {
  PetscFunctionBeginUser;
  Level& L = *level_[l];
  PetscCall(AssembleElasticStiffness(space, material,
                                     [&](std::size_t k) { return levels.cell_level[k] == l; }, &L.A));
  PetscCall(LargestAngularFrequency(L.A, mass_, &info_[l].omega));
  PetscCall(ScaleToAcceleration(L.A, mass_));
  PetscCall(L.kernel.Setup(L.A, true, true));
  for (std::size_t i = 0; i < touched.size(); ++i)
    if (touched[i]) L.element_rows.push_back(static_cast<PetscInt>(i));
  PetscInt cells = std::count(levels.cell_level.begin(), levels.cell_level.end(), l);
  PetscCallMPI(MPI_Allreduce(&cells, &info_[l].cells, 1, MPIU_INT, MPI_SUM, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::Setup(const fe::LagrangeSpace& space, const ElasticMaterial& material, Vec mass,
                                 const LtsLevels& levels, const WaveBoundary& boundary, const Excitation& excitation,
                                 double omega_dt_max, const LtsOptions& options) {
  PetscFunctionBeginUser;
  comm_ = PetscObjectComm((PetscObject)space.dm());
  components_ = space.components();
  mass_ = mass;
  excitation_ = excitation;
  omega_dt_max_ = omega_dt_max;
  cfl_ = options.cfl;
  damping_rate_ = material.damping_rate;
  element_levels_ = levels.levels;
  PetscCall(VecDuplicate(mass, &scratch_));
  PetscCall(VecDuplicate(mass, &work_));
  std::vector<std::vector<char>> touched;
  PetscCall(DofLevels(space, levels, &element_finest_, &touched));
  H_ = INFINITY;
  for (PetscInt l = 0; l < levels.levels; ++l) {
    PetscCall(AddLevel());
    PetscCall(SetupLevel(l, space, material, levels, touched[l]));
    if (info_[l].omega > 0.0) H_ = std::min(H_, std::ldexp(Limit() / info_[l].omega, static_cast<int>(l)));
  }
  H_ = StepControl::Quantized(H_, options.step_quantum);
  PetscCall(AssignContactDofs());
  PetscCall(SetupBoundary(boundary));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::SetupBoundary(const WaveBoundary& boundary) {
  PetscFunctionBeginUser;
  // Boundary nodes never hold contact dofs: their level is their cells' finest.
  for (std::size_t l = 0; l < level_.size(); ++l) {
    Level& L = *level_[l];
    L.boundary = std::make_unique<WaveBoundary>();
    const auto here = [&](PetscInt node) { return element_finest_[components_ * node] == static_cast<PetscInt>(l); };
    L.boundary->dim = L.boundary->dashpots.dim = boundary.dim;
    for (const Constraint& c : boundary.constraints)
      if (here(c.node)) L.boundary->constraints.push_back(c);
    const DashpotBlocks& dashpots = boundary.dashpots;
    for (std::size_t k = 0; k < dashpots.size(); ++k)
      if (here(dashpots.nodes[k])) L.boundary->dashpots.Add(dashpots.nodes[k], dashpots.block(k));
    bool loaded = false;  // a traction on nodes of this level, here
    if (boundary.traction_shape) {
      PetscCall(VecDuplicate(boundary.traction_shape, &L.boundary->traction_shape));
      PetscCall(VecCopy(boundary.traction_shape, L.boundary->traction_shape));
      PetscScalar* s;
      PetscInt n;
      PetscCall(VecGetLocalSize(L.boundary->traction_shape, &n));
      PetscCall(VecGetArray(L.boundary->traction_shape, &s));
      for (PetscInt i = 0; i < n; ++i)
        if (element_finest_[i] != static_cast<PetscInt>(l)) s[i] = 0.0;
        else loaded = loaded || s[i] != 0.0;
      PetscCall(VecRestoreArray(L.boundary->traction_shape, &s));
    }
    // Terms only where they act (kicks and drifts are local: no rank needs empty ones).
    if (L.boundary->constraints.empty() && L.boundary->dashpots.empty() && !loaded) continue;
    const bool displacement_source = excitation_.type == SourceType::Displacement;
    PetscCall(CreateBoundaryTerms(*L.boundary, mass_, displacement_source, &L.terms));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::AssignContactDofs() {
  PetscFunctionBeginUser;
  // Each dof drifts at the finest rate acting on it: its cells', or the contact's.
  std::vector<PetscInt>& rate = dof_level_;
  rate = element_finest_;
  for (PetscInt i : contact_dofs_) rate[i] = std::max(rate[i], contact_level_);
  for (std::size_t l = 0; l < level_.size(); ++l) {
    Level& L = *level_[l];
    L.drift.clear();
    L.contact_only.clear();
    L.kick_rows = L.element_rows;
    if (static_cast<PetscInt>(l) == contact_level_) {
      for (PetscInt i : contact_dofs_)
        if (!std::binary_search(L.element_rows.begin(), L.element_rows.end(), i)) L.contact_only.push_back(i);
      L.kick_rows.insert(L.kick_rows.end(), L.contact_only.begin(), L.contact_only.end());
      std::sort(L.kick_rows.begin(), L.kick_rows.end());
    }
  }
  for (std::size_t i = 0; i < rate.size(); ++i) level_[rate[i]]->drift.push_back(static_cast<PetscInt>(i));
  for (std::size_t l = 0; l < level_.size(); ++l) {
    PetscInt dofs = static_cast<PetscInt>(level_[l]->drift.size());
    PetscCallMPI(MPI_Allreduce(&dofs, &info_[l].dofs, 1, MPIU_INT, MPI_SUM, comm_));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::SetContact(WaveInterface* contact, double omega2) {
  PetscFunctionBeginUser;
  contact_ = contact;
  PetscCall(VecSet(scratch_, 0.0));
  PetscCall(contact->MarkDofs(scratch_));
  const PetscScalar* m;
  PetscInt n, local_level = 0;
  PetscCall(VecGetLocalSize(scratch_, &n));
  PetscCall(VecGetArrayRead(scratch_, &m));
  contact_dofs_.clear();
  for (PetscInt i = 0; i < n; ++i)
    if (PetscRealPart(m[i]) != 0.0) contact_dofs_.push_back(i), local_level = std::max(local_level, element_finest_[i]);
  PetscCall(VecRestoreArrayRead(scratch_, &m));
  PetscCallMPI(MPI_Allreduce(&local_level, &crack_level_, 1, MPIU_INT, MPI_MAX, comm_));
  // The coarsest level at least as fine as the crack's cells that holds the contact's stiffness.
  PetscCall(StableLevel(crack_level_, omega2, &contact_level_));
  PetscCall(TakeHalvings(nullptr));
  PetscCall(AssignContactDofs());
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::TakeHalvings(bool* halved) {
  PetscFunctionBeginUser;
  // The contact at most one level finer than the crack's cells: then the crack
  // cells' impulses come at most every 2 contact steps, h_c·ω_c ≤ 2·cfl·2 < 2π·…
  // below the first resonance of a contact mode (ω h = π). Deeper, the impulse
  // form rang and blew up (pre-closed crack, 17 µs): halve H instead (all pay).
  if (halved) *halved = false;
  const PetscInt excess = contact_level_ - (crack_level_ + 1);
  if (excess <= 0 || pending_level_ >= 0) PetscFunctionReturn(0);
  H_ = std::ldexp(H_, -static_cast<int>(excess));
  contact_level_ -= excess;
  TrimLevels(contact_level_);
  ++halvings_;
  if (halved) *halved = true;
  PetscCall(AssignContactDofs());
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::set_contact_state(PetscInt level, PetscInt refinements, double macro_step,
                                             PetscInt halvings) {
  PetscFunctionBeginUser;
  while (contact_ && levels() <= level) PetscCall(AddLevel());
  TrimLevels(level);
  contact_level_ = level;
  refinements_ = refinements;
  H_ = macro_step;
  halvings_ = halvings;
  PetscCall(AssignContactDofs());
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::Force(PetscInt l, double t, double h, Vec u) {
  PetscFunctionBeginUser;
  Level& L = *level_[l];
  if (L.A) PetscCall(L.kernel.Apply(u, L.a));  // writes its rows only
  if (l != contact_level_ || !contact_) PetscFunctionReturn(0);
  if (!L.contact_only.empty()) {
    PetscScalar* a;
    PetscCall(VecGetArray(L.a, &a));
    for (PetscInt i : L.contact_only) a[i] = 0.0;
    PetscCall(VecRestoreArray(L.a, &a));
  }
  PetscCall(contact_->AddAcceleration(u, L.a));
  if (h <= 0.0) PetscFunctionReturn(0);
  PetscCall(contact_->Commit(u, h));
  double omega2;
  PetscCall(contact_->MaxFrequencySquared(&omega2));
  const double w = info_[l].omega;
  if (h * std::sqrt(w * w + omega2) > Limit() * (1.0 + 1e-12)) PetscCall(RefineContact(omega2, t));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::StableLevel(PetscInt from, double omega2, PetscInt* level) {
  PetscFunctionBeginUser;
  for (*level = from;; ++*level) {
    if (*level >= levels()) PetscCall(AddLevel());
    const double h = std::ldexp(H_, -static_cast<int>(*level)), w = info_[*level].omega;
    if (h * std::sqrt(w * w + omega2) <= Limit()) break;
  }
  PetscFunctionReturn(0);
}

void LtsStepper::TrimLevels(PetscInt contact_level) {
  while (levels() > std::max(element_levels_, contact_level + 1)) {
    level_.pop_back();
    info_.pop_back();
  }
}

PetscErrorCode LtsStepper::RefineContact(double omega2, double t) {
  PetscFunctionBeginUser;
  // Finer until the level's step holds twice the current stiffness (headroom: a
  // contact that just started to bite keeps stiffening).
  PetscInt level;
  PetscCall(StableLevel(contact_level_ + 1, 2.0 * omega2, &level));
  if (refinements_ == 0)
    PetscCall(PetscPrintf(comm_,
                          "wave: the crack contact stiffened at t = %g s: the contact moved from level %" PetscInt_FMT
                          " to %" PetscInt_FMT " (step %g s; further moves are counted in summary.json)\n",
                          t, contact_level_, level, std::ldexp(H_, -static_cast<int>(level))));
  ++refinements_;
  pending_level_ = level;
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::MoveContact(Vec u) {
  PetscFunctionBeginUser;
  // At a synchronisation point of the old contact level, after its end kick.
  const PetscInt old = contact_level_;
  contact_level_ = pending_level_;
  pending_level_ = -1;
  PetscCall(AssignContactDofs());
  PetscCall(ForceWithoutCommit(old, u));
  PetscCall(ForceWithoutCommit(contact_level_, u));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::ForceWithoutCommit(PetscInt l, Vec u) {
  PetscFunctionBeginUser;
  Level& L = *level_[l];
  PetscCall(VecSet(L.a, 0.0));
  PetscCall(Force(l, 0.0, 0.0, u));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::Kick(PetscInt l, double t, double c, Vec v) {
  PetscFunctionBeginUser;
  Level& L = *level_[l];
  const PetscScalar* a;
  PetscScalar* V;
  PetscCall(VecGetArrayRead(L.a, &a));
  PetscCall(VecGetArray(v, &V));
  if (L.terms.empty() && damping_rate_ == 0.0) {  // interior rows only: straight from the level's force
    for (PetscInt i : L.kick_rows) V[i] += c * a[i];
  } else {
    PetscScalar* s;
    PetscCall(VecGetArray(scratch_, &s));
    // Material damping acts on a dof in the kicks of its own rate (coarser levels only add impulses).
    const double own_rate = damping_rate_;
    for (PetscInt i : L.kick_rows) s[i] = DampedAcceleration(a[i], V[i], dof_level_[i] == l ? own_rate : 0.0, c);
    ForceState state;
    state.signal = SignalValues::At(excitation_.signal, t);
    state.kick_dt = c;
    state.mass_factor = 1.0 + 0.5 * damping_rate_ * c;  // the terms act on their nodes' own level
    state.velocity = V;
    PetscCall(VecGetArrayRead(mass_, &state.mass));
    for (auto& term : L.terms) term->Accelerate(state, s);
    double damped = 0.0;
    for (PetscInt i : L.kick_rows) {
      const double mean = V[i] + 0.5 * c * s[i];
      if (dof_level_[i] == l) damped += state.mass[i] * mean * mean;
      V[i] += c * s[i];
    }
    damped_ += c * damping_rate_ * damped;
    PetscCall(VecRestoreArrayRead(mass_, &state.mass));
    PetscCall(VecRestoreArray(scratch_, &s));
  }
  PetscCall(VecRestoreArray(v, &V));
  PetscCall(VecRestoreArrayRead(L.a, &a));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::Drift(PetscInt l, double t, double h, Vec u, Vec v) {
  PetscFunctionBeginUser;
  Level& L = *level_[l];
  PetscScalar *U, *V;
  PetscCall(VecGetArray(u, &U));
  PetscCall(VecGetArray(v, &V));
  for (PetscInt i : L.drift) U[i] += h * V[i];
  if (!L.terms.empty()) {
    const SignalValues signal = SignalValues::At(excitation_.signal, t + h);
    for (const auto& term : L.terms) term->Impose(signal, U, V);
  }
  PetscCall(VecRestoreArray(v, &V));
  PetscCall(VecRestoreArray(u, &U));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::Advance(PetscInt l, double t, double h, Vec u, Vec v) {
  PetscFunctionBeginUser;
  PetscCall(Kick(l, t, 0.5 * h, v));
  PetscCall(Drift(l, t, h, u, v));
  if (l + 1 < levels()) {
    PetscCall(Advance(l + 1, t, 0.5 * h, u, v));
    PetscCall(Advance(l + 1, t + 0.5 * h, 0.5 * h, u, v));
  }
  PetscCall(Force(l, t + h, h, u));
  PetscCall(Kick(l, t + h, 0.5 * h, v));
  if (pending_level_ >= 0 && l == contact_level_) PetscCall(MoveContact(u));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::Start(Vec u) {
  PetscFunctionBeginUser;
  for (PetscInt l = 0; l < levels(); ++l) PetscCall(ForceWithoutCommit(l, u));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::Step(double t, double h, Vec u, Vec v) {
  PetscFunctionBeginUser;
  PetscCall(Advance(0, t, h, u, v));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::InteriorAcceleration(Vec a) const {
  PetscFunctionBeginUser;
  PetscCall(VecSet(a, 0.0));
  for (const auto& L : level_) PetscCall(VecAXPY(a, 1.0, L->a));
  PetscFunctionReturn(0);
}

PetscErrorCode LtsStepper::IntegratorTerm(Vec u, double* term) const {
  PetscFunctionBeginUser;
  *term = 0.0;
  Vec a = scratch_, ma = work_;  // scratch: free between macro steps
  for (PetscInt l = 0; l < element_levels_; ++l) {
    PetscCall(VecSet(a, 0.0));
    PetscCall(level_[l]->kernel.Apply(u, a));
    PetscCall(VecPointwiseMult(ma, a, mass_));
    PetscScalar ama;
    PetscCall(VecDot(ma, a, &ama));
    const double h = std::ldexp(H_, -static_cast<int>(l));
    *term -= h * h / 8.0 * PetscRealPart(ama);
  }
  PetscFunctionReturn(0);
}

double LtsStepper::speedup_bound() const {
  // Cell updates per macro step: all cells at the finest element rate, against each at its own.
  double global = 0.0, local = 0.0;
  for (PetscInt l = 0; l < element_levels_; ++l) {
    global += info_[l].cells * std::ldexp(1.0, static_cast<int>(element_levels_ - 1));
    local += info_[l].cells * std::ldexp(1.0, static_cast<int>(l));
  }
  return local > 0.0 ? global / local : 1.0;
}

PetscErrorCode LtsStepper::View(MPI_Comm comm) const {
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "wave: local time stepping, macro step %g s, %" PetscInt_FMT " levels (speed-up bound %.2f):\n",
                        macro_step(), levels(), speedup_bound()));
  for (PetscInt l = 0; l < levels(); ++l) {
    const LtsLevelInfo& level = info()[l];
    PetscCall(PetscPrintf(comm, "  level %" PetscInt_FMT ": step %g s, %" PetscInt_FMT " cells, %" PetscInt_FMT
                          " dofs, omega %g rad/s%s\n", l, std::ldexp(macro_step(), -static_cast<int>(l)),
                          level.cells, level.dofs, level.omega, l == contact_level() ? " (contact)" : ""));
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
