// The crack interface between the split faces (PHYSICS.md §3): one contact cell
// per + / − node pair, the crack law evaluated per cell, nodal forces into the
// wave solver, friction energy. Geometry comes from contact_geometry.hpp, the
// a0 profile from approach_profile.hpp, output rows are crack_record.hpp.
//
// For a cell with unit normal n (from the − face into the + body), tangent s
// ((s, n) right handed, along the crack from its first facet to its last),
// tributary length w and initial approach a0:
//   [u] = u⁺ − u⁻,  a = a0 − [u]·n / 2,  b = [u]·s / 2,
//   (N, T) = law(a, b),  f⁺ = w (N n − T s),  f⁻ = −f⁺.
// In 3D (contact_cells_3d.hpp) b and T have two components, on s = t1 and s2 = t2,
// f⁺ = w (N n − T₁ t1 − T₂ t2), and w is the tributary area.
// The force on the wave solver is a trial at every evaluation; Commit() advances
// the history once per accepted step and accounts w·ΔW and w·U.
#pragma once

#include <petscvec.h>

#include <array>
#include <memory>
#include <vector>

#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/interface/approach_profile.hpp"
#include "vibrotherm/interface/crack_record.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/mesh/crack_surface.hpp"
#include "vibrotherm/mesh/plex/point_origin.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::interface {

struct ContactCell {
  PetscInt plus, minus;   ///< + and − points carrying the node (vertices, or the faces' edge nodes)
  double n[3], s[3];      ///< normal and (first) tangent (third components 0 in 2D)
  double s2[3];           ///< 3D: the second tangent t2 = n × t1 (0 in 2D)
  double weight;          ///< tributary length [m] (3D: area [m²])
  double a0;
  double N0;              ///< N(a0): the contact force the pre-stress balances at rest
  PetscInt crack;         ///< crack index
  double xi;              ///< position along a 2D crack line, 0..1 (NaN on a 3D crack surface)
  double x, y;            ///< coordinates
  double z;               ///< 3D
};

class CrackInterface final : public wave::WaveInterface {
 public:
  CrackInterface() = default;
  CrackInterface(const CrackInterface&) = delete;
  CrackInterface& operator=(const CrackInterface&) = delete;
  ~CrackInterface() override;

  /// cracks: the crack surface of space's split mesh; law: the crack law (owned
  /// from here on); a0: the initial approach along the cracks.
  PetscErrorCode Setup(const fe::LagrangeSpace& space, const mesh::CrackSurface& cracks, Vec lumped_mass,
                       std::unique_ptr<contact::CrackLaw> law, const ApproachProfile& a0);

  PetscErrorCode AddAcceleration(Vec u, Vec a) override;
  PetscErrorCode Commit(Vec u, double dt) override;
  PetscErrorCode StartIn(Vec u) override;
  PetscErrorCode MarkDofs(Vec marker) override;
  PetscErrorCode MaxFrequencySquared(double* omega2, double extra_approach = -1.0) override;
  PetscErrorCode Energies(double* stored, double* dissipated) override;
  /// The friction energy dissipated on each crack so far, Σ weight · W over its cells [J/m; 3D: J]. Collective.
  PetscErrorCode DissipatedByCrack(std::vector<double>* by_crack) const;
  /// (w/2)(k_n n nᵀ + k_t s sᵀ) on each cell's ± dof pairs, the law's tangent stiffnesses at the cell's a.
  PetscErrorCode TangentStiffness(std::vector<PetscInt>* rows, std::vector<PetscInt>* cols,
                                  std::vector<double>* values) const override;


  /// The mesh's dimension: 2 (one slip component) or 3 (two).
  int dim() const { return dim_; }
  /// Owned cells (this rank evaluates them).
  const std::vector<ContactCell>& cells() const { return cells_; }
  PetscInt global_cells() const { return global_cells_; }
  /// Cumulative dissipated energy per owned cell [J/m²].
  const std::vector<double>& dissipated_per_area() const { return W_; }
  bool dissipative() const { return law_->can_dissipate(); }
  /// State of owned cell i in its last step.
  contact::ContactState state(std::size_t i) const { return last_[i].state; }
  /// Records of the owned cells `owned` (slots unset); with u (the displacement,
  /// global vector) the + node's displacement too. Collective when u is given.
  PetscErrorCode Records(const std::vector<PetscInt>& owned, Vec u, std::vector<CrackCellRecord>* records);
  /// The owned cell nearest to fraction xi along crack `crack` (-1 on every
  /// rank but the one owning the globally nearest cell). Collective.
  PetscErrorCode NearestCell(PetscInt crack, double xi, PetscInt* owned_index) const;
  /// Largest (|T| − μN)/(μN) over committed steps with N above rounding (≤ 0: Coulomb's bound held), global.
  PetscErrorCode MaxFrictionExcess(double* excess) const;
  /// Every cell's committed state (law memory, a, b, power, W, last step) and
  /// the accounts into a checkpoint, keyed by the + point's origin; and back (crack_interface_state.cpp).
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin);
  /// The periodic continuation: what accumulates (W of every owned cell, this rank's dissipated
  /// energy), and a jump ahead that adds increments of these.
  std::vector<double> Accumulated() const;
  void JumpAhead(const std::vector<double>& increments);
  /// Wall time spent evaluating and committing the interface (this rank).
  double seconds() const { return seconds_; }

 private:
  PetscErrorCode BuildCells(const fe::LagrangeSpace& space, const mesh::CrackSurface& cracks,
                            const ApproachProfile& a0);
  PetscErrorCode BuildTransfer(const std::vector<PetscInt>& dofs, Vec lumped_mass);
  void InitialState();
  /// ± displacements of every cell, [u⁺x u⁺y (u⁺z) u⁻x u⁻y (u⁻z)] per cell: *U points into
  /// u itself (all dofs owned here: no communication) or into u_local_.
  PetscErrorCode GatherBegin(Vec u, const PetscScalar** U);
  PetscErrorCode GatherEnd(Vec u, const PetscScalar** U);
  /// Index of value k of cell i in the array GatherBegin returned.
  PetscInt Slot(std::size_t i, int k) const {
    return direct_ ? owned_index_[stride() * i + k] : stride() * static_cast<PetscInt>(i) + k;
  }
  /// Values a cell gathers: its two nodes' displacements.
  int stride() const { return 2 * dim_; }
  void Kinematics(std::size_t i, const PetscScalar* U, double* a, contact::Tangential* b) const;

  MPI_Comm comm_ = MPI_COMM_NULL;
  int dim_ = 2;
  contact::Tangential zero_slip_;  ///< zero along the crack's dim − 1 tangent directions (set once)
  std::vector<std::array<double, 3>> centres_;  ///< each crack's centre, its cells' centroid (FindCentre)
  PetscErrorCode FindCentre();
  /// The cracks with contact cells: the highest crack index on any rank + 1. Collective.
  PetscErrorCode CrackCount(PetscInt* ncracks) const;
  std::vector<ContactCell> cells_;
  PetscInt global_cells_ = 0;
  std::unique_ptr<contact::CrackLaw> law_;
  VecScatter scatter_ = nullptr;  ///< global ↔ [u⁺x u⁺y u⁻x u⁻y] per cell (when some dofs live elsewhere)
  bool direct_ = false;            ///< every needed dof is owned by this rank
  std::vector<PetscInt> owned_index_;  ///< their positions in the owned block
  std::vector<double> inv_mass_;   ///< 1/m per needed dof
  Vec u_local_ = nullptr, f_local_ = nullptr;
  std::vector<double> a_, power_, W_;
  std::vector<contact::Tangential> b_;
  std::vector<PetscInt> cell_dofs_;  ///< [u⁺ u⁻] global dof numbers per cell (stride() of them)
  std::vector<double> initial_stored_;  ///< U of each cell in its initial state
  std::vector<contact::StepResult> last_;
  double dissipated_local_ = 0.0;
  double friction_excess_ = -1.0, largest_normal_ = 0.0;
  static constexpr double kNegligibleTraction = 1e-6;  ///< [Pa]
  PetscLogEvent force_event_ = 0, commit_event_ = 0;
  double seconds_ = 0.0;
};

}  // namespace vibrotherm::interface
