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

/// Lysmer–Kuhlemeyer dashpots of the absorbing faces: f = −C v per node (C: D×D).
class Dashpots final : public BoundaryTerm {
 public:
  explicit Dashpots(DashpotBlocks dashpots)
      : dashpots_(std::move(dashpots)), D_(dashpots_.dim), v_prev_(D_ * dashpots_.size()) {}
  void Accelerate(const ForceState& s, PetscScalar* acc) override {
    for (std::size_t k = 0; k < dashpots_.size(); ++k) {
      const PetscInt i = D_ * dashpots_.nodes[k];
      const double m = s.mass[i] * s.mass_factor;
      // (m I + h/2 C) acc = F − C v with h the kick: the dashpot acts on the mean
      // velocity of the kick, so absorbing faces never limit the step.
      const double h = s.kick_dt > 0.0 ? 0.5 * s.kick_dt : 0.0;
      if (D_ == 2)
        AcceleratePlanar(dashpots_.block(k), m, h, s.velocity + i, acc + i);
      else
        AccelerateSpatial(k, m, h, s.velocity + i, acc + i);
    }
  }
  void AddForce(const ForceState& s, PetscScalar* f) const override {
    for (std::size_t k = 0; k < dashpots_.size(); ++k) {
      const PetscInt i = D_ * dashpots_.nodes[k];
      for (int r = 0; r < D_; ++r) {
        double Cv = dashpots_.at(k, r, 0) * s.velocity[i];
        for (int c = 1; c < D_; ++c) Cv += dashpots_.at(k, r, c) * s.velocity[i + c];
        f[i + r] -= Cv;
      }
    }
  }
  PetscErrorCode AddJacobian(PetscReal shift_v, PetscInt rstart, Mat J) const override {
    PetscFunctionBeginUser;
    for (std::size_t k = 0; k < dashpots_.size(); ++k) {
      PetscInt rows[3];
      PetscScalar block[9];
      for (int r = 0; r < D_; ++r) {
        rows[r] = rstart + D_ * dashpots_.nodes[k] + r;
        for (int c = 0; c < D_; ++c) block[r * D_ + c] = shift_v * dashpots_.at(k, r, c);
      }
      PetscCall(MatSetValues(J, D_, rows, D_, rows, block, ADD_VALUES));
    }
    PetscFunctionReturn(0);
  }
  void Account(const StepState& s, BoundaryEnergy* e) override {  // h v̄ᵀ C v̄ with the mean velocity of the step
    for (std::size_t k = 0; k < dashpots_.size(); ++k) {
      const PetscInt i = D_ * dashpots_.nodes[k];
      double v[3];
      for (int c = 0; c < D_; ++c) v[c] = 0.5 * (s.v[i + c] + v_prev_[D_ * k + c]);
      e->radiated += s.h * Dissipation(dashpots_.block(k), v);
      for (int c = 0; c < D_; ++c) v_prev_[D_ * k + c] = s.v[i + c];
    }
  }
  void Resume(const StepState& s) override {
    for (std::size_t k = 0; k < dashpots_.size(); ++k)
      for (int c = 0; c < D_; ++c) v_prev_[D_ * k + c] = s.v[D_ * dashpots_.nodes[k] + c];
  }

 private:
  /// 2D: the 2×2 solve by Cramer's rule (h = 0: no kick, acc = F / m).
  static void AcceleratePlanar(const double* C, double m, double h, const PetscScalar* v, PetscScalar* acc) {
    const double xx = C[0], xy = C[1], yy = C[2], vx = v[0], vy = v[1];
    const double fx = m * acc[0] - (xx * vx + xy * vy), fy = m * acc[1] - (xy * vx + yy * vy);
    if (h > 0.0) {
      const double a11 = m + h * xx, a12 = h * xy, a22 = m + h * yy, det = a11 * a22 - a12 * a12;
      acc[0] = (a22 * fx - a12 * fy) / det;
      acc[1] = (a11 * fy - a12 * fx) / det;
    } else {
      acc[0] = fx / m;
      acc[1] = fy / m;
    }
  }
  /// 3D: the 3×3 solve by Cramer's rule.
  void AccelerateSpatial(std::size_t k, double m, double h, const PetscScalar* v, PetscScalar* acc) const {
    double A[3][3], f[3];
    for (int r = 0; r < 3; ++r) {
      f[r] = m * acc[r];
      for (int c = 0; c < 3; ++c) {
        f[r] -= dashpots_.at(k, r, c) * v[c];
        A[r][c] = (r == c ? m : 0.0) + h * dashpots_.at(k, r, c);
      }
    }
    const auto det3 = [](const double (&a)[3][3]) {
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const double det = det3(A);
    for (int c = 0; c < 3; ++c) {
      double Ac[3][3];
      for (int r = 0; r < 3; ++r)
        for (int j = 0; j < 3; ++j) Ac[r][j] = j == c ? f[r] : A[r][j];
      acc[c] = det3(Ac) / det;
    }
  }
  /// vᵀ C v (2D: the expression the 2D code has always used).
  double Dissipation(const double* C, const double* v) const {
    if (D_ == 2) return C[0] * v[0] * v[0] + 2.0 * C[1] * v[0] * v[1] + C[2] * v[1] * v[1];
    double q = 0.0;
    for (int r = 0; r < 3; ++r)
      for (int c = r; c < 3; ++c) q += (r == c ? 1.0 : 2.0) * C[UpperIndex(r, c, 3)] * v[r] * v[c];
    return q;
  }
  DashpotBlocks dashpots_;
  int D_;
  std::vector<double> v_prev_;  ///< velocities of the dashpot nodes at the last step
};

/// Prescribed components (displacement source, roller, antisymmetry, fixed):
/// imposed on the acceleration, reset exactly after each step; the support's
/// force is what the source works with.
class Constraints final : public BoundaryTerm {
 public:
  Constraints(std::vector<Constraint> constraints, int dim, bool source)
      : constraints_(std::move(constraints)), reaction_(constraints_.size(), 0.0), D_(dim), source_(source) {}
  void Accelerate(const ForceState& s, PetscScalar* acc) override {
    for (std::size_t k = 0; k < constraints_.size(); ++k) {
      const Constraint& c = constraints_[k];
      const PetscInt i = D_ * c.node;
      const double target = c.source ? s.signal.ddg : 0.0, along = Along(acc + i, c.d);
      reaction_[k] = s.mass[i] * s.mass_factor * (target - along);  // what the support adds along d
      Shift(target - along, c.d, acc + i);
    }
  }
  void ConstrainResidual(const ForceState& s, const PetscScalar* acc, PetscScalar* r) const override {
    for (const Constraint& c : constraints_) {
      const PetscInt i = D_ * c.node;
      const double target = c.source ? s.signal.ddg : 0.0, along = Along(r + i, c.d);
      const double want = s.mass[i] * (Along(acc + i, c.d) - target);
      Shift(want - along, c.d, r + i);
    }
  }
  PetscErrorCode ConstrainJacobian(PetscReal shift_a, PetscInt rstart, const PetscScalar* mass, Mat J) const override;
  void Impose(const SignalValues& s, PetscScalar* U, PetscScalar* V) const override {
    for (const Constraint& c : constraints_) {
      const PetscInt i = D_ * c.node;
      const double tu = c.source ? s.g : 0.0, tv = c.source ? s.dg : 0.0;
      const double au = Along(U + i, c.d), av = Along(V + i, c.d);
      Shift(tu - au, c.d, U + i);
      Shift(tv - av, c.d, V + i);
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
  /// a · d of the D components of a node (summed in index order: the 2D bits).
  double Along(const PetscScalar* a, const double* d) const {
    double along = a[0] * d[0];
    for (int k = 1; k < D_; ++k) along += a[k] * d[k];
    return along;
  }
  /// a += amount d.
  void Shift(double amount, const double* d, PetscScalar* a) const {
    for (int k = 0; k < D_; ++k) a[k] += amount * d[k];
  }
  std::vector<double> reaction_;  ///< per constraint: force the support applies (last Accelerate)
  int D_;
  bool source_;                   ///< a displacement source prescribes some of them (on some rank)
  double power_prev_ = 0.0;       ///< this rank's support power at the last step (trapezoid)
};

PetscErrorCode Constraints::ConstrainJacobian(PetscReal shift_a, PetscInt rstart, const PetscScalar* mass,
                                              Mat J) const {
  PetscFunctionBeginUser;
  // Rows along a coordinate axis only (alpha2 refuses inclined constraints at setup).
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> diag;
  for (const Constraint& c : constraints_) {
    PetscInt comp = 0;
    while (comp + 1 < D_ && !(std::abs(c.d[comp]) > 0.5)) ++comp;
    rows.push_back(rstart + D_ * c.node + comp);
    diag.push_back(mass[D_ * c.node] * shift_a);
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
  terms->push_back(std::make_unique<Constraints>(boundary.constraints, boundary.dim, displacement_source));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
