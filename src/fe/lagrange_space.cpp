#include "vibrotherm/fe/lagrange_space.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::fe {

LagrangeSpace::~LagrangeSpace() { (void)PetscFEDestroy(&fe_); }

PetscErrorCode LagrangeSpace::Setup(DM dm, PetscInt degree, PetscInt components) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscCheck(degree == 1 || degree == 2, comm, PETSC_ERR_USER_INPUT, "degree must be 1 or 2, got %" PetscInt_FMT, degree);
  dm_ = dm;
  degree_ = degree;
  components_ = components;
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  cells_.clear();
  PetscInt cone_size = 4;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    PetscCall(mesh::IsCohesiveCell(dm, c, &cohesive));
    if (cohesive) continue;
    cells_.push_back(c);
    PetscCall(DMPlexGetConeSize(dm, c, &cone_size));
  }
  // Ranks without cells still need to agree on the element type.
  PetscInt max_cone = cells_.empty() ? 0 : cone_size;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &max_cone, 1, MPIU_INT, MPI_MAX, comm));
  simplex_ = max_cone == 3;
  // Quadrature exact for the mass matrix on affine cells.
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, 2, 1, simplex_ ? PETSC_TRUE : PETSC_FALSE, degree, 2 * degree + 1, &fe_));
  PetscCall(PetscFEGetQuadrature(fe_, &quad_));
  PetscInt qdim, qnc, np;
  const PetscReal* points;
  PetscCall(PetscQuadratureGetData(quad_, &qdim, &qnc, &np, &points, &qweights_));
  qpoints_ = static_cast<int>(np);
  PetscCall(PetscFEGetCellTabulation(fe_, 1, &tab_));
  nodes_ = static_cast<int>(tab_->Nb);

  // Section: dofs per point from the dual space, on every point except the
  // cohesive ones (tensor cells and their tensor edges). Decided by cell type,
  // not by "in the closure of a local bulk cell", so that a point shared by two
  // ranks has the same dofs on both even when the partition cuts along a crack.
  PetscDualSpace dual;
  const PetscInt* per_dim;
  PetscCall(PetscFEGetDualSpace(fe_, &dual));
  PetscCall(PetscDualSpaceGetNumDof(dual, &per_dim));
  PetscSection section;
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(PetscSectionCreate(comm, &section));
  PetscCall(PetscSectionSetNumFields(section, 1));
  PetscCall(PetscSectionSetFieldComponents(section, 0, components));
  PetscCall(PetscSectionSetChart(section, pStart, pEnd));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    DMPolytopeType type;
    PetscCall(DMPlexGetCellType(dm, p, &type));
    PetscInt depth = -1;
    if (type == DM_POLYTOPE_POINT) depth = 0;
    else if (type == DM_POLYTOPE_SEGMENT) depth = 1;
    else if (type == DM_POLYTOPE_TRIANGLE || type == DM_POLYTOPE_QUADRILATERAL) depth = 2;
    if (depth < 0) continue;  // tensor (cohesive) points carry no unknowns
    const PetscInt dofs = per_dim[depth] * components;
    PetscCall(PetscSectionSetDof(section, p, dofs));
    PetscCall(PetscSectionSetFieldDof(section, p, 0, dofs));
  }
  PetscCall(PetscSectionSetUp(section));
  PetscCall(DMSetLocalSection(dm, section));
  PetscCall(PetscSectionDestroy(&section));
  PetscCall(DMSetMatType(dm, components > 1 ? MATBAIJ : MATAIJ));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::Evaluate(PetscInt cell, CellQuadrature* q) const {
  PetscFunctionBeginUser;
  const int Nq = qpoints_, Nb = nodes_;
  // For non-affine cells v0 holds the physical coordinates of every quadrature point.
  double v0[2 * 64], J[4 * 64], invJ[4 * 64], detJ[64];
  PetscCheck(Nq <= 64, PETSC_COMM_SELF, PETSC_ERR_SUP, "too many quadrature points");
  PetscCall(DMPlexComputeCellGeometryFEM(dm_, cell, quad_, v0, J, invJ, detJ));
  q->points = Nq;
  q->nodes = Nb;
  q->weight.resize(Nq);
  q->grad.resize(static_cast<std::size_t>(Nq) * Nb * 2);
  q->value = tab_->T[0];
  const PetscReal* D = tab_->T[1];  // [q][b][c=1][dim]
  for (int p = 0; p < Nq; ++p) {
    q->weight[p] = qweights_[p] * std::abs(detJ[p]);
    const double* iJ = invJ + 4 * p;
    for (int b = 0; b < Nb; ++b) {
      const double d0 = D[(p * Nb + b) * 2], d1 = D[(p * Nb + b) * 2 + 1];
      // ∂φ/∂x_i = Σ_j ∂φ/∂ξ_j ∂ξ_j/∂x_i, invJ row-major as ∂ξ_j/∂x_i at [j][i].
      q->grad[(p * Nb + b) * 2] = d0 * iJ[0] + d1 * iJ[2];
      q->grad[(p * Nb + b) * 2 + 1] = d0 * iJ[1] + d1 * iJ[3];
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::NodeCoordinates(std::vector<std::array<double, 2>>* coords) const {
  PetscFunctionBeginUser;
  PetscSection section;
  PetscInt size;
  PetscCall(DMGetLocalSection(dm_, &section));
  PetscCall(PetscSectionGetStorageSize(section, &size));
  coords->assign(size / components_, {0.0, 0.0});
  // Reference coordinates of the nodes: the points of the dual-space functionals.
  PetscDualSpace dual;
  PetscCall(PetscFEGetDualSpace(fe_, &dual));
  std::vector<double> ref(2 * nodes_), real(2 * nodes_);
  for (int b = 0; b < nodes_; ++b) {
    PetscQuadrature f;
    const PetscReal* pts;
    PetscInt np;
    PetscCall(PetscDualSpaceGetFunctional(dual, b, &f));
    PetscCall(PetscQuadratureGetData(f, nullptr, nullptr, &np, &pts, nullptr));
    ref[2 * b] = pts[0];
    ref[2 * b + 1] = pts[1];
  }
  for (PetscInt c : cells_) {
    PetscCall(DMPlexReferenceToCoordinates(dm_, c, nodes_, ref.data(), real.data()));
    PetscInt n, *indices = nullptr;
    PetscCall(DMPlexGetClosureIndices(dm_, section, section, c, PETSC_TRUE, &n, &indices, nullptr, nullptr));
    for (int b = 0; b < nodes_; ++b) (*coords)[indices[b * components_] / components_] = {real[2 * b], real[2 * b + 1]};
    PetscCall(DMPlexRestoreClosureIndices(dm_, section, section, c, PETSC_TRUE, &n, &indices, nullptr, nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::FaceNodes(PetscInt face, std::vector<PetscInt>* offsets, std::vector<double>* weights,
                                        double* length) const {
  PetscFunctionBeginUser;
  PetscSection section;
  PetscCall(DMGetLocalSection(dm_, &section));
  const PetscInt* cone;
  PetscCall(DMPlexGetCone(dm_, face, &cone));
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm_));
  const auto a = x(cone[0]), b = x(cone[1]);
  *length = std::hypot(b[0] - a[0], b[1] - a[1]);
  offsets->clear();
  weights->clear();
  // ∫φ ds on a straight edge: P1: L/2, L/2; P2 (Simpson): L/6, L/6 and 4L/6 at the middle.
  const double end_weight = degree_ == 1 ? 0.5 : 1.0 / 6.0;
  for (int k = 0; k < 2; ++k) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(section, cone[k], &off));
    offsets->push_back(off);
    weights->push_back(end_weight * *length);
  }
  if (degree_ == 2) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(section, face, &off));
    offsets->push_back(off);
    weights->push_back(4.0 / 6.0 * *length);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::QuadraturePoints(PetscInt cell, std::vector<double>* xy) const {
  PetscFunctionBeginUser;
  const PetscReal* ref;
  PetscCall(PetscQuadratureGetData(quad_, nullptr, nullptr, nullptr, &ref, nullptr));
  xy->resize(2 * qpoints_);
  PetscCall(DMPlexReferenceToCoordinates(dm_, cell, qpoints_, ref, xy->data()));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::Locate(double x, double y, PetscInt* cell, std::array<double, 2>* ref) const {
  PetscFunctionBeginUser;
  *cell = -1;
  const double tol = 1e-10, real[2] = {x, y};
  // The inverse map is costly (~ms a cell in PETSc 3.18): try only the cells
  // whose bounding box holds the point.
  mesh::VertexCoordinates xv;
  PetscCall(xv.Setup(dm_));
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm_, 0, &vStart, &vEnd));
  for (PetscInt c : cells_) {
    PetscInt* closure = nullptr;
    PetscInt n;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    PetscCall(DMPlexGetTransitiveClosure(dm_, c, PETSC_TRUE, &n, &closure));
    for (PetscInt i = 0; i < 2 * n; i += 2) {
      if (closure[i] < vStart || closure[i] >= vEnd) continue;
      const auto p = xv(closure[i]);
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm_, c, PETSC_TRUE, &n, &closure));
    const double pad = 1e-9 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
    if (x < lo[0] - pad || x > hi[0] + pad || y < lo[1] - pad || y > hi[1] + pad) continue;
    double r[2];
    PetscCall(DMPlexCoordinatesToReference(dm_, c, 1, real, r));
    // Reference cells: [-1,1]^2, or the triangle (-1,-1), (1,-1), (-1,1).
    const bool inside = simplex_ ? (r[0] >= -1 - tol && r[1] >= -1 - tol && r[0] + r[1] <= tol)
                                 : (std::abs(r[0]) <= 1 + tol && std::abs(r[1]) <= 1 + tol);
    if (inside) {
      *cell = c;
      *ref = {r[0], r[1]};
      break;
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::BasisAt(const std::array<double, 2>& ref, std::vector<double>* phi) const {
  PetscFunctionBeginUser;
  PetscTabulation T;
  const PetscReal point[2] = {ref[0], ref[1]};
  PetscCall(PetscFECreateTabulation(fe_, 1, 1, point, 0, &T));
  phi->assign(T->T[0], T->T[0] + nodes_);
  PetscCall(PetscTabulationDestroy(&T));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::BasisAndDerivativesAt(const std::array<double, 2>& ref, std::vector<double>* phi,
                                                    std::vector<double>* dphi) const {
  PetscFunctionBeginUser;
  PetscTabulation T;
  const PetscReal point[2] = {ref[0], ref[1]};
  PetscCall(PetscFECreateTabulation(fe_, 1, 1, point, 1, &T));
  phi->assign(T->T[0], T->T[0] + nodes_);
  dphi->assign(T->T[1], T->T[1] + 2 * nodes_);
  PetscCall(PetscTabulationDestroy(&T));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::fe
