#include "vibrotherm/interface/crack_interface.hpp"

#include "vibrotherm/contact/csv_rows.hpp"

#include <petscdmplex.h>
#include <petscsf.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "vibrotherm/mesh/labels.hpp"
#include "vibrotherm/mesh/plex_access.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::interface {

double ApproachProfile::at(double xi) const {
  double profile = elliptic ? max * std::sqrt(std::max(0.0, 1.0 - (2.0 * xi - 1.0) * (2.0 * xi - 1.0))) : 0.0;
  if (!table.empty()) {
    const auto it = std::lower_bound(table.begin(), table.end(), std::make_pair(xi, -1e300));
    if (it == table.begin()) profile = table.front().second;
    else if (it == table.end()) profile = table.back().second;
    else {
      const auto& [x1, y1] = *it;
      const auto& [x0, y0] = *(it - 1);
      profile = y0 + (y1 - y0) * (xi - x0) / (x1 - x0);
    }
  }
  return uniform + profile;
}

PetscErrorCode ReadApproachProfile(MPI_Comm comm, ApproachProfile* p) {
  PetscFunctionBeginUser;
  char profile[32] = "uniform", file[PETSC_MAX_PATH_LEN] = "";
  PetscOptionsBegin(comm, nullptr, "Initial approach of the crack faces", nullptr);
  PetscCall(PetscOptionsReal("-crack_a0", "Uniform initial approach a0 [m] (> 0: pre-closed)", nullptr, p->uniform,
                             &p->uniform, nullptr));
  PetscCall(PetscOptionsString("-crack_a0_profile", "uniform|elliptic", nullptr, profile, profile, sizeof(profile),
                               nullptr));
  PetscCall(PetscOptionsReal("-crack_a0_max", "Elliptic profile: a0 at the crack centre [m]", nullptr, p->max, &p->max,
                             nullptr));
  PetscCall(PetscOptionsString("-crack_a0_file", "file profile: CSV with columns xi,a0 (xi in [0,1] along the crack)",
                               nullptr, file, file, sizeof(file), nullptr));
  PetscOptionsEnd();
  const std::string name(profile);
  PetscCheck(name == "uniform" || name == "elliptic" || name == "file", comm, PETSC_ERR_USER_INPUT,
             "-crack_a0_profile: unknown value '%s' (known: uniform|elliptic|file)", profile);
  p->elliptic = name == "elliptic";
  if (name == "file") {
    PetscCheck(file[0], comm, PETSC_ERR_USER_INPUT, "-crack_a0_profile file needs -crack_a0_file FILE");
    VibrothermCallCpp(comm, {
      for (const contact::CsvRow& r : contact::read_csv_rows(file, "-crack_a0_file", 2, "xi,a0")) {
        if (!p->table.empty() && !(r.values[0] > p->table.back().first))
          throw contact::InputError(std::string("-crack_a0_file ") + file + " line " + std::to_string(r.line) +
                                    ": xi must increase");
        p->table.emplace_back(r.values[0], r.values[1]);
      }
      if (p->table.empty()) throw contact::InputError(std::string("-crack_a0_file ") + file + ": no data rows");
    });
  }
  PetscFunctionReturn(0);
}

namespace {

/// A crack facet as every rank needs to know it: orientation, position and the
/// tributary lengths of its end nodes (a node's facets may live on other ranks).
struct FacetInfo {
  PetscInt id, crack;
  double mx, my, length;
  double x0, y0, x1, y1;  ///< end points
};

}  // namespace

CrackInterface::~CrackInterface() {
  (void)VecScatterDestroy(&scatter_);
  for (Vec* v : {&u_local_, &f_local_, &inv_mass_local_}) (void)VecDestroy(v);
}

PetscErrorCode CrackInterface::Setup(const fe::LagrangeSpace& space, Vec lumped_mass,
                                     const contact::ContactParameters& params, const ApproachProfile& a0) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  comm_ = PetscObjectComm((PetscObject)dm);
  PetscClassId id;
  PetscCall(PetscClassIdRegister("vibrotherm interface", &id));
  PetscCall(PetscLogEventRegister("CrackForces", id, &force_event_));
  PetscCall(PetscLogEventRegister("CrackCommit", id, &commit_event_));
  VibrothermCallCpp(comm_, law_ = contact::create_crack_law(params));
  mu_ = params.crack_law == "clapping" || params.crack_law == "linear" ? INFINITY : params.mu;
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm));
  DMLabel crack_label, facet_label;
  PetscCall(DMGetLabel(dm, mesh::labels::crack, &crack_label));
  PetscCall(DMGetLabel(dm, mesh::labels::crack_face, &facet_label));
  std::vector<bool> ghost;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscInt chart0, cStart, cEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));

  // Every rank learns every facet (a few hundred): orientation and position along each crack.
  std::vector<PetscInt> cohesive;
  std::vector<FacetInfo> mine;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool is_cohesive;
    PetscCall(mesh::IsCohesiveCell(dm, c, &is_cohesive));
    if (!is_cohesive) continue;
    cohesive.push_back(c);
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    PetscInt id, crack;
    PetscCall(DMLabelGetValue(facet_label, cone[0], &id));
    PetscCall(DMLabelGetValue(crack_label, cone[0], &crack));
    const PetscInt* fv;
    PetscCall(DMPlexGetCone(dm, cone[0], &fv));
    const auto p = x(fv[0]), q = x(fv[1]);
    mine.push_back({id, crack - 1, 0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), std::hypot(q[0] - p[0], q[1] - p[1]), p[0],
                    p[1], q[0], q[1]});
  }
  int nbytes = static_cast<int>(mine.size() * sizeof(FacetInfo)), size;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&nbytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<FacetInfo> all((displs.back() + counts.back()) / sizeof(FacetInfo));
  PetscCallMPI(MPI_Allgatherv(mine.data(), nbytes, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, comm_));
  // Per crack: direction from its first facet to its last, centre and length.
  struct CrackFrame {
    PetscInt first = PETSC_MAX_INT, last = -1;
    double fx = 0, fy = 0, lx = 0, ly = 0, length = 0, dx = 1, dy = 0, cx = 0, cy = 0;
  };
  std::map<PetscInt, CrackFrame> frames;
  for (const FacetInfo& f : all) {
    CrackFrame& fr = frames[f.crack];
    fr.length += f.length;
    if (f.id < fr.first) fr.first = f.id, fr.fx = f.mx, fr.fy = f.my;
    if (f.id > fr.last) fr.last = f.id, fr.lx = f.mx, fr.ly = f.my;
  }
  for (auto& [c, fr] : frames) {
    const double L = std::hypot(fr.lx - fr.fx, fr.ly - fr.fy);
    if (L > 0) fr.dx = (fr.lx - fr.fx) / L, fr.dy = (fr.ly - fr.fy) / L;
    fr.cx = 0.5 * (fr.fx + fr.lx);
    fr.cy = 0.5 * (fr.fy + fr.ly);
  }

  // Lumped face weights ∫φ ds: degree 1 L/2 per end; degree 2 (Simpson) L/6 per
  // end and 4L/6 for the mid-side node, which is a contact cell of its own.
  const bool quadratic = space.degree() == 2;
  const double end_weight = quadratic ? 1.0 / 6.0 : 0.5, mid_weight = 4.0 / 6.0;
  // Tributary length and mean tangent of every crack node, from all facets (by
  // node coordinates: both faces of a split node share them).
  struct NodeSum {
    double weight = 0, sx = 0, sy = 0;
  };
  std::map<std::pair<double, double>, NodeSum> nodes;
  for (const FacetInfo& f : all) {
    const CrackFrame& fr = frames[f.crack];
    double sx = (f.x1 - f.x0) / f.length, sy = (f.y1 - f.y0) / f.length;
    if (sx * fr.dx + sy * fr.dy < 0) sx = -sx, sy = -sy;
    for (const auto& end : {std::make_pair(f.x0, f.y0), std::make_pair(f.x1, f.y1)}) {
      NodeSum& node = nodes[end];
      node.weight += end_weight * f.length;
      node.sx += end_weight * f.length * sx;
      node.sy += end_weight * f.length * sy;
    }
  }

  // Contact cells: one per owned tensor edge with distinct vertices.
  struct Accumulator {
    ContactCell cell{};
    double sx = 0, sy = 0;
  };
  std::map<PetscInt, Accumulator> by_edge;
  for (PetscInt c : cohesive) {
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, c, &cone));
    PetscInt crack;
    PetscCall(DMLabelGetValue(crack_label, cone[0], &crack));
    const CrackFrame& fr = frames[crack - 1];
    // Facet tangent along the crack's direction; n = s rotated by +90°.
    const PetscInt* fv;
    PetscCall(DMPlexGetCone(dm, cone[0], &fv));
    const auto p = x(fv[0]), q = x(fv[1]);
    double sx = q[0] - p[0], sy = q[1] - p[1];
    const double L = std::hypot(sx, sy);
    sx /= L, sy /= L;
    if (sx * fr.dx + sy * fr.dy < 0) sx = -sx, sy = -sy;
    const double nx = -sy, ny = sx;
    // Which face is +: the side whose bulk cell lies along +n.
    int plus_face = -1;
    for (int side = 0; side < 2 && plus_face < 0; ++side) {
      const PetscInt* support;
      PetscInt ns;
      PetscCall(DMPlexGetSupportSize(dm, cone[side], &ns));
      PetscCall(DMPlexGetSupport(dm, cone[side], &support));
      for (PetscInt k = 0; k < ns; ++k) {
        if (support[k] == c) continue;
        const auto g = mesh::CellCentroid(dm, x, support[k]);
        const bool along_n = (g[0] - 0.5 * (p[0] + q[0])) * nx + (g[1] - 0.5 * (p[1] + q[1])) * ny > 0;
        plus_face = along_n ? side : 1 - side;
      }
    }
    PetscCheck(plus_face >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cohesive cell %" PetscInt_FMT " has no local bulk neighbour", c);
    if (quadratic) {  // the mid-side pair: the two faces' edge nodes (cohesive cells are never ghosts)
      Accumulator& acc = by_edge[c];
      acc.cell.plus = cone[plus_face];
      acc.cell.minus = cone[1 - plus_face];
      acc.cell.weight = mid_weight * L;
      acc.cell.crack = crack - 1;
      acc.sx = sx;
      acc.sy = sy;
      acc.cell.x = 0.5 * (p[0] + q[0]);
      acc.cell.y = 0.5 * (p[1] + q[1]);
    }
    for (int k = 2; k < 4; ++k) {
      const PetscInt* pair;
      PetscCall(DMPlexGetCone(dm, cone[k], &pair));
      if (pair[0] == pair[1] || ghost[cone[k] - chart0]) continue;  // buried tip, or another rank's cell
      Accumulator& acc = by_edge[cone[k]];
      const auto xv = x(pair[0]);
      const NodeSum& node = nodes.at({xv[0], xv[1]});
      acc.cell.plus = plus_face == 0 ? pair[0] : pair[1];
      acc.cell.minus = plus_face == 0 ? pair[1] : pair[0];
      acc.cell.weight = node.weight;
      acc.cell.crack = crack - 1;
      acc.sx = node.sx;
      acc.sy = node.sy;
      acc.cell.x = xv[0];
      acc.cell.y = xv[1];
    }
  }
  cells_.clear();
  for (auto& [edge, acc] : by_edge) {
    ContactCell cell = acc.cell;
    const double norm = std::hypot(acc.sx, acc.sy);
    cell.s[0] = acc.sx / norm;
    cell.s[1] = acc.sy / norm;
    cell.n[0] = -cell.s[1];
    cell.n[1] = cell.s[0];
    const CrackFrame& fr = frames[cell.crack];
    cell.xi = std::clamp(0.5 + ((cell.x - fr.cx) * fr.dx + (cell.y - fr.cy) * fr.dy) / fr.length, 0.0, 1.0);
    cell.a0 = a0.at(cell.xi) + params.a0;
    cells_.push_back(cell);
  }
  PetscInt local_count = static_cast<PetscInt>(cells_.size());
  PetscCallMPI(MPI_Allreduce(&local_count, &global_cells_, 1, MPIU_INT, MPI_SUM, comm_));

  // Scatter global ↔ [u⁺x u⁺y u⁻x u⁻y] per cell.
  PetscSection global;
  PetscCall(DMGetGlobalSection(dm, &global));
  std::vector<PetscInt> indices;
  for (const ContactCell& cell : cells_)
    for (PetscInt point : {cell.plus, cell.minus}) {
      PetscInt off;
      PetscCall(PetscSectionGetOffset(global, point, &off));
      if (off < 0) off = -(off + 1);
      indices.push_back(off);
      indices.push_back(off + 1);
    }
  // Direct access when every needed dof is owned here (always in serial, usually
  // with METIS); a scatter otherwise.
  PetscInt rstart, rend;
  PetscCall(VecGetOwnershipRange(lumped_mass, &rstart, &rend));
  int all_owned = std::all_of(indices.begin(), indices.end(), [&](PetscInt i) { return i >= rstart && i < rend; });
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &all_owned, 1, MPI_INT, MPI_MIN, comm_));
  direct_ = all_owned;
  IS is;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(indices.size()), indices.data(), PETSC_COPY_VALUES, &is));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(indices.size()), &u_local_));
  PetscCall(VecDuplicate(u_local_, &f_local_));
  PetscCall(VecDuplicate(u_local_, &inv_mass_local_));
  PetscCall(VecScatterCreate(lumped_mass, is, u_local_, nullptr, &scatter_));
  PetscCall(ISDestroy(&is));
  PetscCall(VecScatterBegin(scatter_, lumped_mass, inv_mass_local_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter_, lumped_mass, inv_mass_local_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecReciprocal(inv_mass_local_));
  const PetscScalar* minv;
  PetscCall(VecGetArrayRead(inv_mass_local_, &minv));
  inv_mass_.assign(minv, minv + indices.size());
  PetscCall(VecRestoreArrayRead(inv_mass_local_, &minv));
  owned_index_.resize(indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k) owned_index_[k] = indices[k] - rstart;

  const std::size_t n = cells_.size();
  a_.resize(n);
  b_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) a_[i] = cells_[i].a0;
  VibrothermCallCpp(comm_, law_->initialize(n, a_.data(), b_.data()));
  power_.assign(n, 0.0);
  W_.assign(n, 0.0);
  last_.assign(n, contact::StepResult{});
  dissipated_local_ = 0.0;
  initial_stored_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    initial_stored_[i] = law_->stored_energy(i);
    cells_[i].N0 = law_->trial(i, cells_[i].a0, 0.0).N;
  }
  PetscFunctionReturn(0);
}

void CrackInterface::Kinematics(std::size_t i, const PetscScalar* U, double* a, double* b) const {
  const ContactCell& c = cells_[i];
  const double jx = PetscRealPart(U[Slot(i, 0)] - U[Slot(i, 2)]), jy = PetscRealPart(U[Slot(i, 1)] - U[Slot(i, 3)]);
  *a = c.a0 - 0.5 * (jx * c.n[0] + jy * c.n[1]);
  *b = 0.5 * (jx * c.s[0] + jy * c.s[1]);
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
  if (direct_) {
    PetscCall(VecGetArray(acc, &F));
  } else {
    PetscCall(VecGetArray(f_local_, &F));
  }
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const ContactCell& c = cells_[i];
    double a, b;
    Kinematics(i, U, &a, &b);
    const contact::Traction t = law_->trial(i, a, b);
    // Only the change from the initial state: the pre-stress that holds a
    // pre-closed crack (a0 > 0) at rest balances N(a0).
    const double N = t.N - c.N0;
    const double fx = c.weight * (N * c.n[0] - t.T * c.s[0]), fy = c.weight * (N * c.n[1] - t.T * c.s[1]);
    const double f[4] = {fx, fy, -fx, -fy};
    for (int k = 0; k < 4; ++k) {
      const double value = f[k] * inv_mass_[4 * i + k];
      if (direct_) F[Slot(i, k)] += value;
      else F[4 * i + k] = value;
    }
  }
  PetscCall(GatherEnd(u, &U));
  if (direct_) {
    PetscCall(VecRestoreArray(acc, &F));
  } else {
    PetscCall(VecRestoreArray(f_local_, &F));
    PetscCall(VecScatterBegin(scatter_, f_local_, acc, ADD_VALUES, SCATTER_REVERSE));
    PetscCall(VecScatterEnd(scatter_, f_local_, acc, ADD_VALUES, SCATTER_REVERSE));
  }
  PetscCall(PetscLogEventEnd(force_event_, 0, 0, 0, 0));
  seconds_ += MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::Commit(Vec u, double dt) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogEventBegin(commit_event_, 0, 0, 0, 0));
  const PetscScalar* U;
  PetscCall(GatherBegin(u, &U));
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    Kinematics(i, U, &a_[i], &b_[i]);
    last_[i] = law_->commit(i, a_[i], b_[i]);
    W_[i] += last_[i].dW;
    power_[i] = dt > 0 ? last_[i].dW / dt : 0.0;
    dissipated_local_ += cells_[i].weight * last_[i].dW;
    if (last_[i].N > 0.0)
      friction_excess_ = std::max(friction_excess_, (std::abs(last_[i].T) - mu_ * last_[i].N) / (mu_ * last_[i].N + 1e-300));
  }
  PetscCall(GatherEnd(u, &U));
  PetscCall(PetscLogEventEnd(commit_event_, 0, 0, 0, 0));
  seconds_ += MPI_Wtime() - t0;
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
    local = std::max(local, kj * (inv_mass_[4 * i] + inv_mass_[4 * i + 2]));
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

namespace {
double StateCode(contact::ContactState s) {
  switch (s) {
    case contact::ContactState::Loss: return 0;
    case contact::ContactState::Slide: return 1;
    case contact::ContactState::Partial: return 2;
    case contact::ContactState::Stick: return 3;
  }
  return -1;
}
}  // namespace

double CrackInterface::state_code(std::size_t i) const { return StateCode(last_[i].state); }

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

PetscErrorCode CrackInterface::Rows(const std::vector<PetscInt>& owned_index, Vec u, std::vector<double>* rows) const {
  PetscFunctionBeginUser;
  const PetscScalar* U;
  PetscCall(const_cast<CrackInterface*>(this)->GatherBegin(u, &U));
  std::vector<double> local(kRowValues * owned_index.size(), 0.0);
  for (std::size_t p = 0; p < owned_index.size(); ++p) {
    const PetscInt i = owned_index[p];
    if (i < 0) continue;
    const ContactCell& c = cells_[i];
    const contact::StepResult& r = last_[i];
    const double row[kRowValues] = {c.x,  c.y,  a_[i],          b_[i],     law_->slip_offset(i), r.N, r.T,
                                    StateCode(r.state), power_[i], W_[i], PetscRealPart(U[Slot(i, 0)]),
                                    PetscRealPart(U[Slot(i, 1)])};
    std::copy(row, row + kRowValues, local.begin() + kRowValues * p);
  }
  PetscCall(const_cast<CrackInterface*>(this)->GatherEnd(u, &U));
  rows->assign(local.size(), 0.0);
  PetscCallMPI(MPI_Reduce(local.data(), rows->data(), static_cast<int>(local.size()), MPI_DOUBLE, MPI_SUM, 0, comm_));
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::GatherState(std::vector<double>* table) const {
  PetscFunctionBeginUser;
  constexpr int kValues = 11;
  std::vector<double> local;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const ContactCell& c = cells_[i];
    const contact::StepResult& r = last_[i];
    const double row[kValues] = {double(c.crack + 1), c.xi, c.x, c.y, a_[i], b_[i], r.N, r.T, StateCode(r.state),
                                 power_[i], W_[i]};
    local.insert(local.end(), row, row + kValues);
  }
  int n = static_cast<int>(local.size()), size, rank;
  PetscCallMPI(MPI_Comm_size(comm_, &size));
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm_));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  table->assign(rank == 0 ? displs.back() + counts.back() : 0, 0.0);
  PetscCallMPI(MPI_Gatherv(local.data(), n, MPI_DOUBLE, table->data(), counts.data(), displs.data(), MPI_DOUBLE, 0, comm_));
  // Rank 0 sorts by crack and position so the table reads along each crack.
  if (rank == 0) {
    std::vector<std::array<double, kValues>> rows(table->size() / kValues);
    for (std::size_t k = 0; k < rows.size(); ++k) std::copy_n(table->begin() + kValues * k, kValues, rows[k].begin());
    std::sort(rows.begin(), rows.end(), [](const auto& x, const auto& y) { return x[0] != y[0] ? x[0] < y[0] : x[1] < y[1]; });
    for (std::size_t k = 0; k < rows.size(); ++k) std::copy(rows[k].begin(), rows[k].end(), table->begin() + kValues * k);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CrackInterface::MaxFrictionExcess(double* excess) const {
  PetscFunctionBeginUser;
  double local = std::isfinite(mu_) ? friction_excess_ : -1.0;
  PetscCallMPI(MPI_Allreduce(&local, excess, 1, MPI_DOUBLE, MPI_MAX, comm_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface
