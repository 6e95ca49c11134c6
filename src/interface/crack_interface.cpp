#include "vibrotherm/interface/crack_interface.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "vibrotherm/interface/contact_cells_3d.hpp"
#include "vibrotherm/interface/contact_geometry.hpp"
#include "vibrotherm/interface/contact_pairs.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::interface {
namespace {

ContactCell MakeCell(PetscInt plus, PetscInt minus, int crack, const Vec2& where, const NodeGeometry& node) {
  ContactCell cell{};
  cell.plus = plus;
  cell.minus = minus;
  cell.crack = crack;
  cell.x = where[0];
  cell.y = where[1];
  cell.weight = node.weight;
  cell.s[0] = node.tangent[0];
  cell.s[1] = node.tangent[1];
  const Vec2 n = ContactGeometry::normal(node.tangent);
  cell.n[0] = n[0];
  cell.n[1] = n[1];
  return cell;
}

}  // namespace

CrackInterface::~CrackInterface() {
  (void)VecScatterDestroy(&scatter_);
  for (Vec* v : {&u_local_, &f_local_}) (void)VecDestroy(v);
}

PetscErrorCode CrackInterface::Setup(const fe::LagrangeSpace& space, const mesh::CrackSurface& cracks, Vec lumped_mass,
                                     std::unique_ptr<contact::CrackLaw> law, const ApproachProfile& a0) {
  PetscFunctionBeginUser;
  comm_ = PetscObjectComm((PetscObject)space.dm());
  PetscClassId id;
  PetscCall(PetscClassIdRegister("vibrotherm interface", &id));
  PetscCall(PetscLogEventRegister("CrackForces", id, &force_event_));
  PetscCall(PetscLogEventRegister("CrackCommit", id, &commit_event_));
  law_ = std::move(law);
  dim_ = space.dim();
  zero_slip_ = contact::Tangential::zero(dim_ - 1);
  PetscCall(BuildCells(space, cracks, a0));
  PetscCall(FindCentre());
  PetscInt local_count = static_cast<PetscInt>(cells_.size());
  PetscCallMPI(MPI_Allreduce(&local_count, &global_cells_, 1, MPIU_INT, MPI_SUM, comm_));
  PetscSection global;
  PetscCall(DMGetGlobalSection(space.dm(), &global));
  std::vector<PetscInt> dofs;  // [u⁺ u⁻] per cell, dim_ components each
  for (const ContactCell& cell : cells_)
    for (PetscInt point : {cell.plus, cell.minus}) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(global, point, &off));
      if (off < 0) off = -(off + 1);
      for (int d = 0; d < dim_; ++d) dofs.push_back(off + d);
    }
  PetscCall(BuildTransfer(dofs, lumped_mass));
  cell_dofs_ = dofs;
  VibrothermCallCpp(comm_, InitialState());
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::BuildCells(const fe::LagrangeSpace& space, const mesh::CrackSurface& cracks,
                                          const ApproachProfile& a0) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  if (dim_ == 3) {  // planar cracks; no parameterisation along them (ξ: none; the a0 profile's middle)
    PetscCall(ContactCells3D(space, &cells_));
    for (ContactCell& cell : cells_) cell.xi = std::numeric_limits<double>::quiet_NaN(), cell.a0 = a0.at(0.5);
    PetscFunctionReturn(0);
  }
  const ContactGeometry geometry(cracks.facets(), static_cast<int>(space.degree()));
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm));
  std::map<PetscInt, const CrackFacetGeometry*> facet_of;  // cohesive cell → its facet
  for (const mesh::OwnedCrackFacet& owned : cracks.owned()) facet_of[owned.cell] = &cracks.facets()[owned.index];
  std::map<PetscInt, ContactCell> by_point;  // one cell per joining point (ForEachContactPair)
  const auto add = [&](PetscInt c, int plus, const ContactPair& pair) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const auto found = facet_of.find(c);
    PetscCheck(found != facet_of.end(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
               "cohesive cell %" PetscInt_FMT " is not in the crack surface", c);
    const CrackFacetGeometry& f = *found->second;
    const PetscInt p_plus = pair.side[plus], p_minus = pair.side[1 - plus];
    if (pair.vertex) {
      const Vec2 p = x(pair.side[0]);
      by_point[pair.key] = MakeCell(p_plus, p_minus, f.crack, p, geometry.vertex(p));
    } else {  // the facet's mid-side node (Q2)
      const Vec2 mid = {0.5 * (f.p0[0] + f.p1[0]), 0.5 * (f.p0[1] + f.p1[1])};
      by_point[pair.key] = MakeCell(p_plus, p_minus, f.crack, mid, geometry.middle(f));
    }
    PetscFunctionReturn(0);
  };
  PetscCall(ForEachContactPair(dm, geometry.degree(), add));
  cells_.clear();
  for (auto& [point, cell] : by_point) {
    cell.xi = geometry.xi(static_cast<int>(cell.crack), {cell.x, cell.y});
    cell.a0 = a0.at(cell.xi);
    cells_.push_back(cell);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::BuildTransfer(const std::vector<PetscInt>& dofs, Vec lumped_mass) {
  PetscFunctionBeginUser;
  // Direct access when every needed dof is owned here (always in serial, usually
  // with METIS); a scatter otherwise.
  PetscInt rstart, rend;
  PetscCall(VecGetOwnershipRange(lumped_mass, &rstart, &rend));
  int all_owned = std::all_of(dofs.begin(), dofs.end(), [&](PetscInt i) { return i >= rstart && i < rend; });
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &all_owned, 1, MPI_INT, MPI_MIN, comm_));
  direct_ = all_owned;
  const PetscInt n = static_cast<PetscInt>(dofs.size());
  IS is;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, dofs.data(), PETSC_COPY_VALUES, &is));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, n, &u_local_));
  PetscCall(VecDuplicate(u_local_, &f_local_));
  PetscCall(VecScatterCreate(lumped_mass, is, u_local_, nullptr, &scatter_));
  PetscCall(ISDestroy(&is));
  PetscCall(VecScatterBegin(scatter_, lumped_mass, f_local_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter_, lumped_mass, f_local_, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* m;
  PetscCall(VecGetArrayRead(f_local_, &m));
  inv_mass_.resize(n);
  for (PetscInt k = 0; k < n; ++k) inv_mass_[k] = 1.0 / PetscRealPart(m[k]);
  PetscCall(VecRestoreArrayRead(f_local_, &m));
  owned_index_.resize(n);
  for (PetscInt k = 0; k < n; ++k) owned_index_[k] = dofs[k] - rstart;
  PetscFunctionReturn(0);
}

void CrackInterface::InitialState() {
  const std::size_t n = cells_.size();
  a_.resize(n);
  b_.assign(n, zero_slip_);  // 2D: one tangential component, along s; 3D: two, along t1 and t2
  for (std::size_t i = 0; i < n; ++i) a_[i] = cells_[i].a0;
  law_->initialize(n, a_.data(), b_.data());
  power_.assign(n, 0.0);
  W_.assign(n, 0.0);
  last_.assign(n, contact::StepResult{});
  dissipated_local_ = 0.0;
  initial_stored_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    initial_stored_[i] = law_->stored_energy(i);
    cells_[i].N0 = law_->trial(i, cells_[i].a0, zero_slip_).N;
  }
}

void CrackInterface::Kinematics(std::size_t i, const PetscScalar* U, double* a, contact::Tangential* b) const {
  const ContactCell& c = cells_[i];
  double j[3];
  for (int d = 0; d < dim_; ++d) j[d] = PetscRealPart(U[Slot(i, d)] - U[Slot(i, dim_ + d)]);
  // Each dot product summed x, y(, z) from the first term (not from 0: −0 stays −0).
  const auto dot = [&](const double* e) {
    double sum = j[0] * e[0];
    for (int d = 1; d < dim_; ++d) sum += j[d] * e[d];
    return sum;
  };
  *a = c.a0 - 0.5 * dot(c.n);
  *b = zero_slip_;  // the crack's tangent directions: 1 in 2D, 2 in 3D (a copy: no check per cell and step)
  const double* tangents[2] = {c.s, c.s2};
  for (int k = 0; k < dim_ - 1; ++k) (*b)[k] = 0.5 * dot(tangents[k]);
}

PetscErrorCode CrackInterface::GatherBegin(Vec u, const PetscScalar** U) {
  PetscFunctionBeginUser;
  if (direct_) {
    PetscCall(VecGetArrayRead(u, U));
  } else {
    PetscCall(VecScatterBegin(scatter_, u, u_local_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecScatterEnd(scatter_, u, u_local_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(u_local_, U));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::GatherEnd(Vec u, const PetscScalar** U) {
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(direct_ ? u : u_local_, U));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::AddAcceleration(Vec u, Vec acc) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogEventBegin(force_event_, 0, 0, 0, 0));
  const PetscScalar* U;
  PetscScalar* F;
  PetscCall(GatherBegin(u, &U));
  PetscCall(VecGetArray(direct_ ? acc : f_local_, &F));
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const ContactCell& c = cells_[i];
    double a;
    contact::Tangential b;
    Kinematics(i, U, &a, &b);
    const contact::Traction t = law_->trial(i, a, b);
    // Only the change from the initial state: the pre-stress that holds a
    // pre-closed crack (a0 > 0) at rest balances N(a0).
    const double N = t.N - c.N0;
    double f[6];
    const double* tangents[2] = {c.s, c.s2};
    for (int d = 0; d < dim_; ++d) {
      double traction = N * c.n[d];  // f⁺ = w (N n − Σ_k T_k t_k)
      for (int k = 0; k < dim_ - 1; ++k) traction -= t.T[k] * tangents[k][d];
      f[d] = c.weight * traction;
      f[dim_ + d] = -f[d];
    }
    for (int k = 0; k < stride(); ++k) {
      const double value = f[k] * inv_mass_[stride() * i + k];
      if (direct_) F[Slot(i, k)] += value;
      else F[stride() * i + k] = value;
    }
  }
  PetscCall(GatherEnd(u, &U));
  PetscCall(VecRestoreArray(direct_ ? acc : f_local_, &F));
  if (!direct_) {
    PetscCall(VecScatterBegin(scatter_, f_local_, acc, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(scatter_, f_local_, acc, ADD_VALUES, SCATTER_REVERSE));
  }
  PetscCall(PetscLogEventEnd(force_event_, 0, 0, 0, 0));
  seconds_ += MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::MarkDofs(Vec marker) {
  PetscFunctionBeginUser;
  PetscScalar* F;
  PetscCall(VecGetArray(direct_ ? marker : f_local_, &F));
  for (std::size_t i = 0; i < cells_.size(); ++i)
    for (int k = 0; k < stride(); ++k) F[direct_ ? Slot(i, k) : stride() * i + k] = 1.0;
  PetscCall(VecRestoreArray(direct_ ? marker : f_local_, &F));
  if (!direct_) {
    PetscCall(VecScatterBegin(scatter_, f_local_, marker, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(scatter_, f_local_, marker, ADD_VALUES, SCATTER_REVERSE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::Commit(Vec u, double dt) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogEventBegin(commit_event_, 0, 0, 0, 0));
  const PetscScalar* U;
  PetscCall(GatherBegin(u, &U));
  const double mu = law_->friction_bound();
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    Kinematics(i, U, &a_[i], &b_[i]);
    last_[i] = law_->commit(i, a_[i], b_[i]);
    W_[i] += last_[i].dW;
    power_[i] = dt > 0 ? last_[i].dW / dt : 0.0;
    dissipated_local_ += cells_[i].weight * last_[i].dW;
    // Coulomb's bound, where the normal traction is physical: above 1 µPa and
    // above 1e-9 of the largest seen (a traction of 1e-28 Pa is rounding).
    const double N = last_[i].N;
    largest_normal_ = std::max(largest_normal_, N);
    if (std::isfinite(mu) && N > std::max(kNegligibleTraction, 1e-9 * largest_normal_))
      friction_excess_ = std::max(friction_excess_, (contact::norm(last_[i].T) - mu * N) / (mu * N));
  }
  PetscCall(GatherEnd(u, &U));
  PetscCall(PetscLogEventEnd(commit_event_, 0, 0, 0, 0));
  seconds_ += MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::StartIn(Vec u) {
  PetscFunctionBeginUser;
  // The law's memory follows the way from the rest state to u in one commit; what it dissipates on
  // that way built the saved state (the source's past work), so it is no friction heat of this run.
  PetscCall(Commit(u, 0.0));
  W_.assign(W_.size(), 0.0);
  dissipated_local_ = 0.0;
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::MaxFrequencySquared(double* omega2, double extra_approach) {
  PetscFunctionBeginUser;
  // A pair of nodes joined by a jump stiffness k (force per unit jump): ω² = k (1/m⁺ + 1/m⁻),
  // k = w · max(dN/da, dT/db) / 2 (a and b are half jumps).
  double local = 0.0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const double a = extra_approach >= 0.0 ? cells_[i].a0 + extra_approach : a_[i];
    const contact::CellStiffness k = law_->stiffness(i, a);
    const double kj = 0.5 * cells_[i].weight * std::max(k.normal, k.tangential);
    local = std::max(local, kj * (inv_mass_[stride() * i] + inv_mass_[stride() * i + dim_]));
  }
  PetscCallMPI(MPI_Allreduce(&local, omega2, 1, MPI_DOUBLE, MPI_MAX, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::Energies(double* stored, double* dissipated) {
  PetscFunctionBeginUser;
  // Stored energy relative to the initial, pre-stressed state: U − U0 − 2 N(a0)(a − a0).
  double local[2] = {0.0, dissipated_local_}, global[2];
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const ContactCell& c = cells_[i];
    local[0] += c.weight * (law_->stored_energy(i) - initial_stored_[i] - 2.0 * c.N0 * (a_[i] - c.a0));
  }
  PetscCallMPI(MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, comm_));
  *stored = global[0];
  *dissipated = global[1];
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::DissipatedByCrack(std::vector<double>* by_crack) const {
  PetscFunctionBeginUser;
  PetscInt ncracks;
  PetscCall(CrackCount(&ncracks));
  by_crack->assign(static_cast<std::size_t>(ncracks), 0.0);
  for (std::size_t i = 0; i < cells_.size(); ++i) (*by_crack)[static_cast<std::size_t>(cells_[i].crack)] += cells_[i].weight * W_[i];
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, by_crack->data(), static_cast<int>(ncracks), MPI_DOUBLE, MPI_SUM, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::NearestCell(PetscInt crack, double xi, PetscInt* owned_index) const {
  PetscFunctionBeginUser;
  struct {
    double distance;
    int rank;
  } mine{INFINITY, 0}, best;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  mine.rank = rank;
  *owned_index = -1;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    if (cells_[i].crack != crack) continue;
    const double d = std::abs(cells_[i].xi - xi);
    if (d < mine.distance) mine.distance = d, *owned_index = static_cast<PetscInt>(i);
  }
  PetscCallMPI(MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm_));
  PetscCheck(std::isfinite(best.distance), comm_, PETSC_ERR_USER_INPUT, "-crack_probe: crack %" PetscInt_FMT " has no contact cells",
             crack + 1);
  if (best.rank != rank) *owned_index = -1;
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::CrackCount(PetscInt* ncracks) const {
  PetscFunctionBeginUser;
  *ncracks = 0;  // the highest crack index holding a cell on any rank, + 1
  for (const ContactCell& c : cells_) *ncracks = std::max(*ncracks, c.crack + 1);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, ncracks, 1, MPIU_INT, MPI_MAX, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::FindCentre() {
  PetscFunctionBeginUser;
  PetscInt ncracks;
  PetscCall(CrackCount(&ncracks));
  // The area-weighted mean of each crack's cells: the centre of a rectangular crack
  // (its lattice of nodes is symmetric), the origin of crack_state.csv's s1, s2.
  std::vector<double> sums(4 * static_cast<std::size_t>(ncracks), 0.0);
  for (const ContactCell& c : cells_) {
    double* s = &sums[4 * static_cast<std::size_t>(c.crack)];
    s[0] += c.weight * c.x, s[1] += c.weight * c.y, s[2] += c.weight * c.z, s[3] += c.weight;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, comm_));
  centres_.assign(static_cast<std::size_t>(ncracks), {0.0, 0.0, 0.0});
  for (std::size_t k = 0; k < centres_.size(); ++k)
    for (int d = 0; d < 3; ++d) centres_[k][d] = sums[4 * k + 3] > 0.0 ? sums[4 * k + d] / sums[4 * k + 3] : 0.0;
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::Records(const std::vector<PetscInt>& owned, Vec u, std::vector<CrackCellRecord>* records) {
  PetscFunctionBeginUser;
  const PetscScalar* U = nullptr;
  if (u) PetscCall(GatherBegin(u, &U));  // collective when the dofs need a scatter
  records->clear();
  for (PetscInt i : owned) {
    const ContactCell& c = cells_[i];
    const contact::StepResult& s = last_[i];
    CrackCellRecord r;
    r.crack = static_cast<int>(c.crack);
    r.xi = c.xi, r.x = c.x, r.y = c.y, r.z = c.z;
    const std::array<double, 3>& centre = centres_[static_cast<std::size_t>(c.crack)];
    const double d[3] = {c.x - centre[0], c.y - centre[1], c.z - centre[2]};
    r.s1 = d[0] * c.s[0] + d[1] * c.s[1] + d[2] * c.s[2];  // t2 is 0 in 2D: s2 = 0
    r.s2 = d[0] * c.s2[0] + d[1] * c.s2[1] + d[2] * c.s2[2];
    r.a = a_[i], r.b = b_[i][0], r.b2 = b_[i][1], r.b0 = law_->slip_offset(i)[0];
    r.N = s.N, r.T = s.T[0], r.T2 = s.T[1], r.state = s.state;
    r.power = power_[i], r.W = W_[i];
    if (U) r.ux = PetscRealPart(U[Slot(i, 0)]), r.uy = PetscRealPart(U[Slot(i, 1)]);
    records->push_back(r);
  }
  if (u) PetscCall(GatherEnd(u, &U));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::MaxFrictionExcess(double* excess) const {
  PetscFunctionBeginUser;
  double local = std::isfinite(law_->friction_bound()) ? friction_excess_ : -1.0;
  PetscCallMPI(MPI_Allreduce(&local, excess, 1, MPI_DOUBLE, MPI_MAX, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::TangentStiffness(std::vector<PetscInt>* rows, std::vector<PetscInt>* cols,
                                                std::vector<double>* values) const {
  PetscFunctionBeginUser;
  // f⁺ = w(N n − T s), δa = −[δu]·n/2, δb = [δu]·s/2: K = (w/2)(k_n n nᵀ + k_t s sᵀ) ⊗ [[1, −1], [−1, 1]].
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const ContactCell& c = cells_[i];
    const contact::CellStiffness k = law_->stiffness(i, a_[i]);
    double block[3][3];
    for (int p = 0; p < dim_; ++p)
      for (int q = 0; q < dim_; ++q)
        block[p][q] = dim_ == 2 ? 0.5 * c.weight * (k.normal * c.n[p] * c.n[q] + k.tangential * c.s[p] * c.s[q])
                                : 0.5 * c.weight * (k.normal * c.n[p] * c.n[q] +
                                                    k.tangential * (c.s[p] * c.s[q] + c.s2[p] * c.s2[q]));
    for (int side_r = 0; side_r < 2; ++side_r)
      for (int side_c = 0; side_c < 2; ++side_c)
        for (int p = 0; p < dim_; ++p)
          for (int q = 0; q < dim_; ++q) {
            rows->push_back(cell_dofs_[stride() * i + dim_ * side_r + p]);
            cols->push_back(cell_dofs_[stride() * i + dim_ * side_c + q]);
            values->push_back((side_r == side_c ? 1.0 : -1.0) * block[p][q]);
          }
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface
