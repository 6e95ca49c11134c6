// Material damping C = α M with the lumped mass (PHYSICS.md §2): a force on every
// dof, applied like the dashpots to the mean velocity of a velocity-Verlet kick,
//   m a = F − α m (v + a h/2)   ⇒   a = (F/m − α v) / (1 + α h/2),
// so it never limits the step, and accounted exactly as h α Σ m v̄² per step
// (v̄ the step's mean velocity: the kick's for drift–kick–drift).
#include <utility>

#include "vibrotherm/wave/boundary_terms.hpp"

namespace vibrotherm::wave {
namespace {

class MaterialDamping final : public BoundaryTerm {
 public:
  MaterialDamping(double rate, std::vector<double> mass, bool account)
      : rate_(rate), mass_(std::move(mass)), v_prev_(mass_.size(), 0.0), account_(account) {}
  void Accelerate(const ForceState& s, PetscScalar* acc) override {
    for (std::size_t i = 0; i < mass_.size(); ++i) acc[i] = DampedAcceleration(acc[i], s.velocity[i], rate_, s.kick_dt);
  }
  void AddForce(const ForceState& s, PetscScalar* f) const override {
    for (std::size_t i = 0; i < mass_.size(); ++i) f[i] -= rate_ * s.mass[i] * s.velocity[i];
  }
  PetscErrorCode AddJacobian(PetscReal shift_v, PetscInt rstart, Mat J) const override {
    PetscFunctionBeginUser;
    for (std::size_t i = 0; i < mass_.size(); ++i)
      PetscCall(MatSetValue(J, rstart + static_cast<PetscInt>(i), rstart + static_cast<PetscInt>(i),
                            shift_v * rate_ * mass_[i], ADD_VALUES));
    PetscFunctionReturn(0);
  }
  void Account(const StepState& s, BoundaryEnergy* e) override {
    if (!account_) return;
    double work = 0.0;
    for (std::size_t i = 0; i < mass_.size(); ++i) {
      const double mean = 0.5 * (s.v[i] + v_prev_[i]);
      work += mass_[i] * mean * mean;
      if (!taken_.empty()) taken_[i] += s.h * rate_ * mass_[i] * mean * mean;
      v_prev_[i] = s.v[i];
    }
    e->damped += s.h * rate_ * work;
  }
  bool KeepDofEnergy() override {
    if (account_ && taken_.empty()) taken_.assign(mass_.size(), 0.0);
    return account_;
  }
  void TakeDofEnergy(PetscScalar* e) override {
    for (std::size_t i = 0; i < taken_.size(); ++i) e[i] += taken_[i], taken_[i] = 0.0;
  }
  void Resume(const StepState& s) override { v_prev_.assign(s.v, s.v + v_prev_.size()); }

 private:
  double rate_;
  std::vector<double> mass_, v_prev_;  ///< owned lumped masses, and velocities at the last step
  std::vector<double> taken_;          ///< per dof since the last TakeDofEnergy (empty: not kept)
  bool account_;
};

}  // namespace

PetscErrorCode CreateMaterialDamping(double rate, Vec mass, bool account, std::unique_ptr<BoundaryTerm>* term) {
  PetscFunctionBeginUser;
  const PetscScalar* m;
  PetscInt n;
  PetscCall(VecGetLocalSize(mass, &n));
  PetscCall(VecGetArrayRead(mass, &m));
  *term = std::make_unique<MaterialDamping>(rate, std::vector<double>(m, m + n), account);
  PetscCall(VecRestoreArrayRead(mass, &m));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
