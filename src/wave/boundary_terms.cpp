#include "vibrotherm/wave/boundary_terms.hpp"

namespace vibrotherm::wave {

SignalValues SignalValues::At(const SourceTimeFunction& signal, double t) {
  SignalValues s;
  signal.evaluate(t, &s.g, &s.dg, &s.ddg);
  return s;
}

namespace {

/// A traction source: the load g(t) ∫φ d ds on the source edge's dofs.
class TractionLoad final : public BoundaryTerm {
 public:
  TractionLoad(Vec shape, Vec mass) : shape_(shape), mass_(mass) {}
  PetscErrorCode Setup() {
    PetscFunctionBeginUser;
    const PetscScalar *S, *M;
    PetscInt n;
    PetscCall(VecGetLocalSize(shape_, &n));
    PetscCall(VecGetArrayRead(shape_, &S));
    PetscCall(VecGetArrayRead(mass_, &M));
    for (PetscInt i = 0; i < n; ++i) {
      if (S[i] == 0.0) continue;
      dofs_.push_back(i);
      load_.push_back(S[i]);
      acceleration_.push_back(S[i] * (1.0 / M[i]));
    }
    PetscCall(VecRestoreArrayRead(mass_, &M));
    PetscCall(VecRestoreArrayRead(shape_, &S));
    u_prev_.assign(dofs_.size(), 0.0);
    PetscFunctionReturn(0);
  }
  void Accelerate(const ForceState& s, PetscScalar* acc) override {
    if (s.signal.g == 0.0) return;
    const double g = s.signal.g / s.mass_factor;  // a damped kick moves the mass m (1 + α h/2)
    for (std::size_t k = 0; k < dofs_.size(); ++k) acc[dofs_[k]] += g * acceleration_[k];
  }
  void AddForce(const ForceState& s, PetscScalar* f) const override {
    if (s.signal.g == 0.0) return;
    for (std::size_t k = 0; k < dofs_.size(); ++k) f[dofs_[k]] += s.signal.g * load_[k];
  }
  void Account(const StepState& s, BoundaryEnergy* e) override {  // g(t_mid) f · Δu
    for (std::size_t k = 0; k < dofs_.size(); ++k) {
      const PetscInt i = dofs_[k];
      e->work_source += s.middle.g * load_[k] * (s.u[i] - u_prev_[k]);
      u_prev_[k] = s.u[i];
    }
  }
  void Resume(const StepState& s) override {
    for (std::size_t k = 0; k < dofs_.size(); ++k) u_prev_[k] = s.u[dofs_[k]];
  }

 private:
  Vec shape_, mass_;  // not owned
  std::vector<PetscInt> dofs_;
  std::vector<double> load_, acceleration_, u_prev_;
};

/// Lysmer–Kuhlemeyer dashpots of the absorbing edges: f = −C v per node.
class Dashpots final : public BoundaryTerm {
 public:
  explicit Dashpots(std::vector<Dashpot> dashpots) : dashpots_(std::move(dashpots)), v_prev_(2 * dashpots_.size()) {}
  void Accelerate(const ForceState& s, PetscScalar* acc) override {
    for (const Dashpot& d : dashpots_) {
      const PetscInt i = 2 * d.node;
      const double m = s.mass[i] * s.mass_factor, vx = s.velocity[i], vy = s.velocity[i + 1];
      const double fx = m * acc[i] - (d.xx * vx + d.xy * vy), fy = m * acc[i + 1] - (d.xy * vx + d.yy * vy);
      if (s.kick_dt > 0.0) {
        // (m I + h/2 C) acc = F − C v: the dashpot acts on the mean velocity of the kick,
        // so absorbing edges never limit the step.
        const double h = 0.5 * s.kick_dt;
        const double a11 = m + h * d.xx, a12 = h * d.xy, a22 = m + h * d.yy, det = a11 * a22 - a12 * a12;
        acc[i] = (a22 * fx - a12 * fy) / det;
        acc[i + 1] = (a11 * fy - a12 * fx) / det;
      } else {
        acc[i] = fx / m;
        acc[i + 1] = fy / m;
      }
    }
  }
  void AddForce(const ForceState& s, PetscScalar* f) const override {
    for (const Dashpot& d : dashpots_) {
      const PetscInt i = 2 * d.node;
      f[i] -= d.xx * s.velocity[i] + d.xy * s.velocity[i + 1];
      f[i + 1] -= d.xy * s.velocity[i] + d.yy * s.velocity[i + 1];
    }
  }
  PetscErrorCode AddJacobian(PetscReal shift_v, PetscInt rstart, Mat J) const override {
    PetscFunctionBeginUser;
    for (const Dashpot& d : dashpots_) {
      const PetscInt rows[2] = {rstart + 2 * d.node, rstart + 2 * d.node + 1};
      const PetscScalar block[4] = {shift_v * d.xx, shift_v * d.xy, shift_v * d.xy, shift_v * d.yy};
      PetscCall(MatSetValues(J, 2, rows, 2, rows, block, ADD_VALUES));
    }
    PetscFunctionReturn(0);
  }
  void Account(const StepState& s, BoundaryEnergy* e) override {  // h v̄ᵀ C v̄ with the mean velocity of the step
    for (std::size_t k = 0; k < dashpots_.size(); ++k) {
      const Dashpot& d = dashpots_[k];
      const PetscInt i = 2 * d.node;
      const double vx = 0.5 * (s.v[i] + v_prev_[2 * k]), vy = 0.5 * (s.v[i + 1] + v_prev_[2 * k + 1]);
      e->radiated += s.h * (d.xx * vx * vx + 2.0 * d.xy * vx * vy + d.yy * vy * vy);
      v_prev_[2 * k] = s.v[i];
      v_prev_[2 * k + 1] = s.v[i + 1];
    }
  }
  void Resume(const StepState& s) override {
    for (std::size_t k = 0; k < dashpots_.size(); ++k) {
      v_prev_[2 * k] = s.v[2 * dashpots_[k].node];
      v_prev_[2 * k + 1] = s.v[2 * dashpots_[k].node + 1];
    }
  }

 private:
  std::vector<Dashpot> dashpots_;
  std::vector<double> v_prev_;  ///< velocities of the dashpot nodes at the last step
};

/// Prescribed components (displacement source, roller, antisymmetry, fixed):
/// imposed on the acceleration, reset exactly after each step; the support's
/// force is what the source works with.
class Constraints final : public BoundaryTerm {
 public:
  Constraints(std::vector<Constraint> constraints, bool source)
      : constraints_(std::move(constraints)), reaction_(constraints_.size(), 0.0), source_(source) {}
  void Accelerate(const ForceState& s, PetscScalar* acc) override {
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
      const Constraint& c = constraints_[k];
      const PetscInt i = 2 * c.node;
      const double target = c.source ? s.signal.ddg : 0.0, along = acc[i] * c.d[0] + acc[i + 1] * c.d[1];
      reaction_[k] = s.mass[i] * s.mass_factor * (target - along);  // what the support adds along d
      acc[i] += (target - along) * c.d[0];
      acc[i + 1] += (target - along) * c.d[1];
    }
  }
  void ConstrainResidual(const ForceState& s, const PetscScalar* acc, PetscScalar* r) const override {
    for (const Constraint& c : constraints_) {
      const PetscInt i = 2 * c.node;
      const double target = c.source ? s.signal.ddg : 0.0, along = r[i] * c.d[0] + r[i + 1] * c.d[1];
      const double want = s.mass[i] * ((acc[i] * c.d[0] + acc[i + 1] * c.d[1]) - target);
      r[i] += (want - along) * c.d[0];
      r[i + 1] += (want - along) * c.d[1];
    }
  }
  PetscErrorCode ConstrainJacobian(PetscReal shift_a, PetscInt rstart, const PetscScalar* mass, Mat J) const override;
  void Impose(const SignalValues& s, PetscScalar* U, PetscScalar* V) const override {
    for (const Constraint& c : constraints_) {
      const PetscInt i = 2 * c.node;
      const double tu = c.source ? s.g : 0.0, tv = c.source ? s.dg : 0.0;
      const double au = U[i] * c.d[0] + U[i + 1] * c.d[1], av = V[i] * c.d[0] + V[i + 1] * c.d[1];
      U[i] += (tu - au) * c.d[0];
      U[i + 1] += (tu - au) * c.d[1];
      V[i] += (tv - av) * c.d[0];
      V[i + 1] += (tv - av) * c.d[1];
    }
  }
  bool needs_end_state_forces() const override { return source_; }
  void Account(const StepState& s, BoundaryEnergy* e) override {
    if (!source_) return;
    if (s.reactions_from_kick) {  // the kick's support force times the prescribed displacement increment
      for (std::size_t k = 0; k < constraints_.size(); ++k)
        if (constraints_[k].source) e->work_source += reaction_[k] * (s.end.g - s.start.g);
      return;
    }
    double power = 0.0;  // trapezoid of the support power, the force evaluated at the end state
    for (std::size_t k = 0; k < constraints_.size(); ++k)
      if (constraints_[k].source) power += reaction_[k] * s.end.dg;
    e->work_source += 0.5 * s.h * (power_prev_ + power);
    power_prev_ = power;
  }
  std::vector<double> SavedAccount() const override { return {power_prev_}; }
  void RestoreAccount(const std::vector<double>& values) override { power_prev_ = values.at(0); }

 private:
  std::vector<Constraint> constraints_;
  std::vector<double> reaction_;  ///< per constraint: force the support applies (last Accelerate)
  bool source_;                   ///< a displacement source prescribes some of them (on some rank)
  double power_prev_ = 0.0;       ///< this rank's support power at the last step (trapezoid)
};

PetscErrorCode Constraints::ConstrainJacobian(PetscReal shift_a, PetscInt rstart, const PetscScalar* mass,
                                              Mat J) const {
  PetscFunctionBeginUser;
  // Rows along x or y only (alpha2 refuses inclined constraints at setup).
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> diag;
  for (const Constraint& c : constraints_) {
    const PetscInt comp = std::abs(c.d[0]) > 0.5 ? 0 : 1;
    rows.push_back(rstart + 2 * c.node + comp);
    diag.push_back(mass[2 * c.node] * shift_a);
  }
  PetscCall(MatZeroRows(J, static_cast<PetscInt>(rows.size()), rows.data(), 0.0, nullptr, nullptr));
  for (std::size_t k = 0; k < rows.size(); ++k) PetscCall(MatSetValue(J, rows[k], rows[k], diag[k], INSERT_VALUES));
  PetscCall(MatAssemblyBegin(J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode CreateBoundaryTerms(const WaveBoundary& boundary, Vec mass, bool displacement_source,
                                   std::vector<std::unique_ptr<BoundaryTerm>>* terms) {
  PetscFunctionBeginUser;
  // Every rank holds every kind (possibly empty): some calls are collective.
  terms->clear();
  if (boundary.traction_shape) {
    auto load = std::make_unique<TractionLoad>(boundary.traction_shape, mass);
    PetscCall(load->Setup());
    terms->push_back(std::move(load));
  }
  terms->push_back(std::make_unique<Dashpots>(boundary.dashpots));
  terms->push_back(std::make_unique<Constraints>(boundary.constraints, displacement_source));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
