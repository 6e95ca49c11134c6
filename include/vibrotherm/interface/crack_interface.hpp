// The crack interface between the split faces (PHYSICS.md §3): one contact cell
// per + / − node pair, the crack law evaluated per cell, nodal forces into the
// wave solver, friction power and energies.
//
// For a cell with unit normal n (from the − face into the + body), tangent s
// ((s, n) right handed, along the crack from its first facet to its last),
// tributary length w and initial approach a0:
//   [u] = u⁺ − u⁻,  a = a0 − [u]·n / 2,  b = [u]·s / 2,
//   (N, T) = law(a, b),  f⁺ = w (N n − T s),  f⁻ = −f⁺.
// The force on the wave solver is a trial at every evaluation; Commit() advances
// the history once per accepted step and accounts w·ΔW and w·U.
#pragma once

#include <petscvec.h>

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::interface {

/// Initial approach along the cracks: -crack_a0 VALUE (uniform), plus either
/// -crack_a0_profile elliptic -crack_a0_max VALUE (a0_max √(1 − (2ξ − 1)²)) or
/// -crack_a0_profile file -crack_a0_file F (CSV xi,a0, linear in ξ), ξ ∈ [0, 1]
/// along the crack; plus -contact_a0.
struct ApproachProfile {
  double uniform = 0.0, max = 0.0;
  bool elliptic = false;
  std::vector<std::pair<double, double>> table;  ///< (ξ, a0), increasing ξ
  double at(double xi) const;
};
PetscErrorCode ReadApproachProfile(MPI_Comm comm, ApproachProfile* profile);

struct ContactCell {
  PetscInt plus, minus;   ///< vertices
  double n[2], s[2];
  double weight;          ///< tributary length [m]
  double a0;
  double N0;              ///< N(a0): the contact force the pre-stress balances at rest
  PetscInt crack;         ///< crack index
  double xi;              ///< position along the crack, 0..1
  double x, y;            ///< coordinates (of the + vertex)
};

class CrackInterface final : public wave::WaveInterface {
 public:
  ~CrackInterface() override;
  PetscErrorCode Setup(const fe::LagrangeSpace& space, Vec lumped_mass, const contact::ContactParameters& params,
                       const ApproachProfile& a0);

  PetscErrorCode AddAcceleration(Vec u, Vec a) override;
  PetscErrorCode Commit(Vec u, double dt) override;
  PetscErrorCode MaxFrequencySquared(double* omega2, double extra_approach = -1.0) override;
  PetscErrorCode Energies(double* stored, double* dissipated) override;

  /// Owned cells (this rank evaluates them).
  const std::vector<ContactCell>& cells() const { return cells_; }
  PetscInt global_cells() const { return global_cells_; }
  /// Last committed step per owned cell.
  const std::vector<contact::StepResult>& last_step() const { return last_; }
  /// Friction power per owned cell in the last step [W/m²].
  const std::vector<double>& power() const { return power_; }
  /// Cumulative dissipated energy per owned cell [J/m²].
  const std::vector<double>& dissipated_per_area() const { return W_; }
  /// Current (a, b) of owned cell i.
  double a(std::size_t i) const { return a_[i]; }
  double b(std::size_t i) const { return b_[i]; }
  double slip_offset(std::size_t i) const { return law_->slip_offset(i); }
  bool dissipative() const { return law_->can_dissipate(); }
  /// State of owned cell i in its last step: 0 loss, 1 slide, 2 partial, 3 stick.
  double state_code(std::size_t i) const;
  /// One row of crack data per requested cell, reduced onto rank 0:
  /// x, y, a, b, b0, N, T, state code (0 loss, 1 slide, 2 partial, 3 stick), power, W, and
  /// the + node's ux, uy. `cells` are global cell choices from NearestCell.
  static constexpr int kRowValues = 12;
  PetscErrorCode Rows(const std::vector<PetscInt>& owned_index, Vec u, std::vector<double>* rows) const;
  /// The owned cell nearest to fraction xi along crack `crack` (-1 on every
  /// rank but the one owning the globally nearest cell).
  PetscErrorCode NearestCell(PetscInt crack, double xi, PetscInt* owned_index) const;
  /// All cells' state on rank 0 (others get nothing): per cell crack, xi, x, y, a, b, N, T, state, power, W.
  PetscErrorCode GatherState(std::vector<double>* table) const;

  /// Largest (|T| − μN)/(μN + ε) seen in any committed step (≤ 0: Coulomb's bound held), global.
  PetscErrorCode MaxFrictionExcess(double* excess) const;

 private:
  /// ± displacements of every cell, [u⁺x u⁺y u⁻x u⁻y] per cell: *U points into
  /// u itself (all dofs owned here: no communication) or into u_local_.
  PetscErrorCode GatherBegin(Vec u, const PetscScalar** U);
  PetscErrorCode GatherEnd(Vec u, const PetscScalar** U);
  /// Index of value k of cell i in the array GatherBegin returned.
  PetscInt Slot(std::size_t i, int k) const { return direct_ ? owned_index_[4 * i + k] : 4 * static_cast<PetscInt>(i) + k; }
  void Kinematics(std::size_t i, const PetscScalar* U, double* a, double* b) const;

  std::vector<ContactCell> cells_;
  std::unique_ptr<contact::CrackLaw> law_;
  VecScatter scatter_ = nullptr;  ///< global ↔ [u⁺x u⁺y u⁻x u⁻y] per cell (when some dofs live elsewhere)
  bool direct_ = false;            ///< every needed dof is owned by this rank
  std::vector<PetscInt> owned_index_;  ///< their positions in the owned block
  std::vector<double> inv_mass_;   ///< 1/m per needed dof
  Vec u_local_ = nullptr, f_local_ = nullptr, inv_mass_local_ = nullptr;
  std::vector<double> a_, b_, power_, W_;
  std::vector<double> initial_stored_;  ///< U of each cell in its initial state
  std::vector<contact::StepResult> last_;
  double dissipated_local_ = 0.0;
  double friction_excess_ = -1.0, mu_ = 0.0;
  PetscLogEvent force_event_ = 0, commit_event_ = 0;
  double seconds_ = 0.0;  ///< time spent in the interface on this rank

 public:
  /// Wall time spent evaluating and committing the interface (this rank).
  double seconds() const { return seconds_; }
  PetscInt global_cells_ = 0;
  MPI_Comm comm_ = MPI_COMM_NULL;
};

}  // namespace vibrotherm::interface
