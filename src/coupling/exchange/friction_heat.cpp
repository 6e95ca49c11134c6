#include "vibrotherm/coupling/exchange/friction_heat.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <cmath>

#include "vibrotherm/coupling/exchange/crack_face_quadrature.hpp"
#include "vibrotherm/coupling/exchange/surface_transfer.hpp"
#include "vibrotherm/util/all_gather.hpp"

namespace vibrotherm::coupling {
namespace {

/// A contact cell as every rank sees it: crack, position and global index.
struct CellPlace {
  double crack, x, y, index;
};

/// All contact cells of all ranks (4 doubles each), and this rank's first global index.
PetscErrorCode GatherCells(const interface::CrackInterface& crack, MPI_Comm comm, std::vector<CellPlace>* all,
                           PetscInt* first) {
  PetscFunctionBeginUser;
  const PetscInt mine = static_cast<PetscInt>(crack.cells().size());
  PetscCallMPI(MPI_Exscan(&mine, first, 1, MPIU_INT, MPI_SUM, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) *first = 0;
  std::vector<double> local;
  for (std::size_t i = 0; i < crack.cells().size(); ++i) {
    const interface::ContactCell& c = crack.cells()[i];
    local.insert(local.end(), {double(c.crack), c.x, c.y, double(*first + static_cast<PetscInt>(i))});
  }
  std::vector<double> flat;
  PetscCall(util::AllGather(comm, local, &flat));
  all->resize(flat.size() / 4);
  for (std::size_t k = 0; k < all->size(); ++k) (*all)[k] = {flat[4 * k], flat[4 * k + 1], flat[4 * k + 2], flat[4 * k + 3]};
  PetscFunctionReturn(0);
}

/// Contact cells of one crack by ξ, to find the cell at a node.
class CellsAlong {
 public:
  CellsAlong(const std::vector<CellPlace>& all, const mesh::CrackLine& line, PetscInt crack) {
    for (const CellPlace& c : all)
      if (std::lround(c.crack) == crack) by_xi_.emplace_back(line.XiOf(c.x, c.y), std::lround(c.index));
    std::sort(by_xi_.begin(), by_xi_.end());
    tol_ = 1e-9;
  }
  /// The cell at ξ, or −1 (a buried tip carries none).
  long At(double xi) const {
    auto it = std::lower_bound(by_xi_.begin(), by_xi_.end(), std::make_pair(xi - tol_, -1L));
    return it != by_xi_.end() && std::abs(it->first - xi) <= tol_ ? it->second : -1;
  }

 private:
  std::vector<std::pair<double, long>> by_xi_;
  double tol_;
};

}  // namespace

FrictionHeat::~FrictionHeat() {
  (void)MatDestroy(&transfer_);
  (void)VecDestroy(&rate_);
}

PetscErrorCode FrictionHeat::BuildWaveElements(const interface::CrackInterface& crack,
                                               const fe::LagrangeSpace& wave_space,
                                               const mesh::CrackSurface& wave_cracks) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)wave_space.dm());
  std::vector<CellPlace> cells;
  PetscCall(GatherCells(crack, comm, &cells, &first_cell_));
  wave_elements_.clear();
  crack_vertices_.clear();
  for (PetscInt k = 0; k < wave_cracks.crack_count(); ++k) {
    const mesh::CrackLine& line = wave_cracks.line(k);
    const CellsAlong along(cells, line, k);
    for (std::size_t j = 0; j <= line.facet_ids().size(); ++j)
      crack_vertices_.push_back({double(k), line.vertex_xi(j), line.vertex(j)[0], line.vertex(j)[1]});
    for (std::size_t j = 0; j < line.facet_ids().size(); ++j) {
      CrackElement e;
      e.crack = static_cast<int>(k);
      e.xi0 = line.vertex_xi(j);
      e.xi1 = line.vertex_xi(j + 1);
      e.length = std::hypot(line.vertex(j + 1)[0] - line.vertex(j)[0], line.vertex(j + 1)[1] - line.vertex(j)[1]);
      e.degree = static_cast<int>(wave_space.degree());
      e.node = {along.At(e.xi0), along.At(e.xi1), e.degree == 2 ? along.At(0.5 * (e.xi0 + e.xi1)) : -1};
      wave_elements_.push_back(e);
    }
  }
  // Every contact cell must be a node of some element, or its energy would be lost.
  std::vector<char> seen(cells.size(), 0);
  for (const CrackElement& e : wave_elements_)
    for (long n : e.node)
      if (n >= 0) seen[n] = 1;
  PetscCheck(std::all_of(seen.begin(), seen.end(), [](char s) { return s != 0; }), comm, PETSC_ERR_PLIB,
             "friction heat: a contact cell lies on no crack facet");
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeat::SetupTransfer(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                                           const fe::LagrangeSpace& heat_space, const CrackFaceSplit& split) {
  PetscFunctionBeginUser;
  SurfacePoints points;
  Mat basis;
  PetscCall(BuildCrackFaceQuadrature(crack, wave_space, split, &points, &basis));
  SurfaceHeatTransfer psi;
  PetscCall(psi.Setup(heat_space, points));
  PetscCall(MatMatMult(psi.matrix(), basis, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &transfer_));
  PetscCall(MatDestroy(&basis));
  PetscCall(MatCreateVecs(transfer_, &rate_, nullptr));
  // Conservation: Σ_h T_hc = Σ_p A_p φ_c(x_p) must be the cell's tributary area ∫φ_c dA.
  Vec ones, area;
  PetscCall(MatCreateVecs(transfer_, nullptr, &ones));
  PetscCall(VecSet(ones, 1.0));
  PetscCall(VecDuplicate(rate_, &area));
  PetscCall(MatMultTranspose(transfer_, ones, area));
  const PetscScalar* a;
  PetscCall(VecGetArrayRead(area, &a));
  double worst = 0.0;
  for (std::size_t i = 0; i < crack.cells().size(); ++i)
    worst = std::max(worst, std::abs(PetscRealPart(a[i]) - crack.cells()[i].weight) / crack.cells()[i].weight);
  PetscCall(VecRestoreArrayRead(area, &a));
  PetscCall(VecDestroy(&ones));
  PetscCall(VecDestroy(&area));
  MPI_Comm comm = PetscObjectComm((PetscObject)heat_space.dm());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCheck(worst < 1e-10, comm, PETSC_ERR_PLIB,
             "friction heat: the crack faces' quadrature gives a contact cell %g of its area wrong", worst);
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeat::Setup(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                                   const mesh::CrackSurface& wave_cracks, const fe::LagrangeSpace& heat_space,
                                   const mesh::CrackSurface& heat_cracks, int face_subdivisions) {
  PetscFunctionBeginUser;
  const PetscInt owned = static_cast<PetscInt>(crack.cells().size());
  // Crack lines (2D) keep their elements for the records and the near field; the
  // transfer itself is the faces' quadrature in both dimensions.
  if (wave_cracks.crack_count() > 0) PetscCall(BuildWaveElements(crack, wave_space, wave_cracks));
  PetscCall(SetupTransfer(crack, wave_space, heat_space, {face_subdivisions, CrackLineVertices(heat_cracks)}));
  previous_.assign(owned, 0.0);
  density_.assign(owned, 0.0);
  cell_places_.clear();
  for (const interface::ContactCell& c : crack.cells()) cell_places_.insert(cell_places_.end(), {c.x, c.y, c.z, c.weight});
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeat::AddRates(const std::vector<double>& rates, Vec Q) {
  PetscFunctionBeginUser;
  PetscScalar* q;
  PetscCall(VecGetArray(rate_, &q));
  std::copy(rates.begin(), rates.end(), q);
  PetscCall(VecRestoreArray(rate_, &q));
  PetscCall(MatMultAdd(transfer_, rate_, Q, Q));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeat::AddLoad(const std::vector<double>& W, double interval, Vec Q) {
  PetscFunctionBeginUser;
  PetscCheck(W.size() == previous_.size(), PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "%zu energies for %zu contact cells",
             W.size(), previous_.size());
  PetscScalar* q;
  PetscCall(VecGetArray(rate_, &q));
  for (std::size_t i = 0; i < W.size(); ++i) {
    density_[i] = interval > 0.0 ? (W[i] - previous_[i]) / interval : 0.0;
    q[i] = density_[i];
    previous_[i] = W[i];
  }
  PetscCall(VecRestoreArray(rate_, &q));
  PetscCall(MatMultAdd(transfer_, rate_, Q, Q));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeat::CellResponse(Vec w, std::vector<double>* per_cell) const {
  PetscFunctionBeginUser;
  Vec r;
  PetscCall(VecDuplicate(rate_, &r));
  PetscCall(MatMultTranspose(transfer_, w, r));
  const PetscScalar* x;
  PetscInt n;
  PetscCall(VecGetLocalSize(r, &n));
  PetscCall(VecGetArrayRead(r, &x));
  per_cell->assign(x, x + n);
  PetscCall(VecRestoreArrayRead(r, &x));
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
