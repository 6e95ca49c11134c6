#include "vibrotherm/fe/lagrange_space.hpp"

#include "vibrotherm/fe/cell_corners.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/fe/face_weights.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::fe {

LagrangeSpace::~LagrangeSpace() { (void)PetscFEDestroy(&fe_); }

namespace {

/// The dimension of the points of this type that carry unknowns, −1 for the
/// tensor (cohesive) points, which carry none.
PetscInt DofCarrierDimension(DMPolytopeType type) {
  switch (type) {
    case DM_POLYTOPE_POINT:
      return 0;
    case DM_POLYTOPE_SEGMENT:
      return 1;
    case DM_POLYTOPE_TRIANGLE:
    case DM_POLYTOPE_QUADRILATERAL:
      return 2;
    case DM_POLYTOPE_TETRAHEDRON:
    case DM_POLYTOPE_HEXAHEDRON:
      return 3;
    default:
      return -1;
  }
}

/// The bulk (non-cohesive) cells of this rank, and whether they are simplices
/// (dim + 1 vertices: triangles, tetrahedra). Collective: ranks without cells
/// still need to agree on the element type; any tensor cell anywhere decides.
PetscErrorCode BulkCells(DM dm, PetscInt dim, std::vector<PetscInt>* cells, bool* simplex) {
  PetscFunctionBeginUser;
  PetscInt cStart, cEnd;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  cells->clear();
  DMPolytopeType type = DM_POLYTOPE_UNKNOWN;
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    PetscCall(mesh::IsCohesiveCell(dm, c, &cohesive));
    if (cohesive) continue;
    cells->push_back(c);
    PetscCall(DMPlexGetCellType(dm, c, &type));
  }
  // 1: simplices, 0: tensor cells, 2: no cells here (neutral in the minimum).
  PetscInt shape = cells->empty() ? 2 : (DMPolytopeTypeGetNumVertices(type) == dim + 1 ? 1 : 0);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &shape, 1, MPIU_INT, MPI_MIN, PetscObjectComm((PetscObject)dm)));
  *simplex = shape == 1;
  PetscFunctionReturn(0);
}

/// The space's section on dm: dofs per point from the dual space, on every
/// point except the cohesive ones (tensor cells and their tensor edges).
/// Decided by cell type, not by "in the closure of a local bulk cell", so that a
/// point shared by two ranks has the same dofs on both even when the partition
/// cuts along a crack.
PetscErrorCode SetSpaceSection(DM dm, PetscFE fe, PetscInt components) {
  PetscFunctionBeginUser;
  PetscDualSpace dual;
  const PetscInt* per_dim;
  PetscCall(PetscFEGetDualSpace(fe, &dual));
  PetscCall(PetscDualSpaceGetNumDof(dual, &per_dim));
  PetscSection section;
  PetscInt pStart, pEnd;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &section));
  PetscCall(PetscSectionSetNumFields(section, 1));
  PetscCall(PetscSectionSetFieldComponents(section, 0, components));
  PetscCall(PetscSectionSetChart(section, pStart, pEnd));
  for (PetscInt p = pStart; p < pEnd; ++p) {
    DMPolytopeType type;
    PetscCall(DMPlexGetCellType(dm, p, &type));
    const PetscInt depth = DofCarrierDimension(type);
    if (depth < 0) continue;
    const PetscInt dofs = per_dim[depth] * components;
    PetscCall(PetscSectionSetDof(section, p, dofs));
    PetscCall(PetscSectionSetFieldDof(section, p, 0, dofs));
  }
  PetscCall(PetscSectionSetUp(section));
  PetscCall(DMSetLocalSection(dm, section));
  PetscCall(PetscSectionDestroy(&section));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode LagrangeSpace::Setup(DM dm, PetscInt degree, PetscInt components) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscCheck(degree == 1 || degree == 2, comm, PETSC_ERR_USER_INPUT, "degree must be 1 or 2, got %" PetscInt_FMT,
             degree);
  PetscInt dim, coordinate_dim;
  PetscCall(DMGetDimension(dm, &dim));
  PetscCall(DMGetCoordinateDim(dm, &coordinate_dim));
  // Embedded manifolds (a surface mesh in 3D) would need the pseudo-inverse Jacobian.
  PetscCheck((dim == 2 || dim == 3) && coordinate_dim == dim, comm, PETSC_ERR_SUP,
             "Lagrange space on a %" PetscInt_FMT "D mesh with %" PetscInt_FMT " coordinates: needs 2 or 3, equal", dim,
             coordinate_dim);
  dm_ = dm;
  dim_ = static_cast<int>(dim);
  degree_ = degree;
  components_ = components;
  PetscCall(BulkCells(dm, dim, &cells_, &simplex_));
  // Quadrature exact for the mass matrix on affine cells.
  PetscCall(PetscFECreateLagrange(PETSC_COMM_SELF, dim, 1, simplex_ ? PETSC_TRUE : PETSC_FALSE, degree, 2 * degree + 1,
                                  &fe_));
  PetscCall(PetscFEGetQuadrature(fe_, &quad_));
  PetscInt np;
  PetscCall(PetscQuadratureGetData(quad_, nullptr, nullptr, &np, nullptr, &qweights_));
  qpoints_ = static_cast<int>(np);
  PetscCall(PetscFEGetCellTabulation(fe_, 1, &tab_));
  nodes_ = static_cast<int>(tab_->Nb);
  PetscCall(SetSpaceSection(dm, fe_, components));
  PetscCall(DMSetMatType(dm, components > 1 ? MATBAIJ : MATAIJ));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::Evaluate(PetscInt cell, CellQuadrature* q) const {
  PetscFunctionBeginUser;
  const int Nq = qpoints_, Nb = nodes_, D = dim_;
  // v0: the physical coordinates of every quadrature point (the quadrature is given).
  constexpr int kMaxPoints = 216;  // Q2 hexahedra: PETSc's order-5 rule has 6³ points
  double v0[3 * kMaxPoints], J[9 * kMaxPoints], invJ[9 * kMaxPoints], detJ[kMaxPoints];
  PetscCheck(Nq <= kMaxPoints, PETSC_COMM_SELF, PETSC_ERR_SUP, "%d quadrature points, more than %d", Nq, kMaxPoints);
  PetscCall(DMPlexComputeCellGeometryFEM(dm_, cell, quad_, v0, J, invJ, detJ));
  q->points = Nq;
  q->nodes = Nb;
  q->dim = D;
  q->weight.resize(Nq);
  q->grad.resize(static_cast<std::size_t>(Nq) * Nb * D);
  q->value = tab_->T[0];
  const PetscReal* ref_grad = tab_->T[1];  // [q][b][c=1][dim]
  for (int p = 0; p < Nq; ++p) {
    q->weight[p] = qweights_[p] * std::abs(detJ[p]);
    const double* iJ = invJ + D * D * p;
    for (int b = 0; b < Nb; ++b) {
      const double* dref = ref_grad + (p * Nb + b) * D;
      double* g = &q->grad[(p * Nb + b) * D];
      // ∂φ/∂x_i = Σ_j ∂φ/∂ξ_j ∂ξ_j/∂x_i, invJ row-major as ∂ξ_j/∂x_i at [j][i].
      for (int i = 0; i < D; ++i) {
        g[i] = dref[0] * iJ[i];
        for (int j = 1; j < D; ++j) g[i] += dref[j] * iJ[j * D + i];
      }
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::NodePositions(std::vector<double>* coords) const {
  PetscFunctionBeginUser;
  const int D = dim_;
  PetscSection section;
  PetscInt size;
  PetscCall(DMGetLocalSection(dm_, &section));
  PetscCall(PetscSectionGetStorageSize(section, &size));
  coords->assign(static_cast<std::size_t>(size / components_) * D, 0.0);
  // Reference coordinates of the nodes: the points of the dual-space functionals.
  PetscDualSpace dual;
  PetscCall(PetscFEGetDualSpace(fe_, &dual));
  std::vector<double> ref(D * nodes_), real(D * nodes_);
  for (int b = 0; b < nodes_; ++b) {
    PetscQuadrature f;
    const PetscReal* pts;
    PetscCall(PetscDualSpaceGetFunctional(dual, b, &f));
    PetscCall(PetscQuadratureGetData(f, nullptr, nullptr, nullptr, &pts, nullptr));
    std::copy(pts, pts + D, &ref[D * b]);
  }
  CellCorners corners(dm_, D, simplex_);
  std::vector<double> x(static_cast<std::size_t>(corners.corners()) * D);
  for (PetscInt c : cells_) {
    PetscCall(corners.Read(c, x.data()));
    for (int b = 0; b < nodes_; ++b) {
      ReferencePoint r = {0.0, 0.0, 0.0};
      std::copy(&ref[D * b], &ref[D * b] + D, r.begin());
      const ReferencePoint p = MapToCell(x.data(), D, simplex_, r);
      std::copy(p.begin(), p.begin() + D, &real[D * b]);
    }
    PetscInt n, *indices = nullptr;
    PetscCall(DMPlexGetClosureIndices(dm_, section, section, c, PETSC_TRUE, &n, &indices, nullptr, nullptr));
    for (int b = 0; b < nodes_; ++b)
      std::copy(&real[D * b], &real[D * b] + D, &(*coords)[indices[b * components_] / components_ * D]);
    PetscCall(DMPlexRestoreClosureIndices(dm_, section, section, c, PETSC_TRUE, &n, &indices, nullptr, nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::NodeCoordinates(std::vector<std::array<double, 2>>* coords) const {
  PetscFunctionBeginUser;
  PetscCall(RequirePlanar("NodeCoordinates"));
  std::vector<double> flat;
  PetscCall(NodePositions(&flat));
  coords->resize(flat.size() / 2);
  for (std::size_t i = 0; i < coords->size(); ++i) (*coords)[i] = {flat[2 * i], flat[2 * i + 1]};
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::RequirePlanar(const char* what) const {
  PetscFunctionBeginUser;
  PetscCheck(dim_ == 2, PETSC_COMM_SELF, PETSC_ERR_SUP, "LagrangeSpace::%s is 2D only (mesh of dimension %d)", what,
             dim_);
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::FaceNodes(PetscInt face, std::vector<PetscInt>* offsets, std::vector<double>* weights,
                                        double* measure) const {
  PetscFunctionBeginUser;
  offsets->clear();
  weights->clear();
  if (dim_ == 3) {
    PetscCall(SurfaceFaceNodes(face, offsets, weights, measure));
    PetscFunctionReturn(0);
  }
  PetscSection section;
  PetscCall(DMGetLocalSection(dm_, &section));
  const PetscInt* cone;
  PetscCall(DMPlexGetCone(dm_, face, &cone));
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm_));
  const auto a = x(cone[0]), b = x(cone[1]);
  *measure = std::hypot(b[0] - a[0], b[1] - a[1]);
  // ∫φ ds on a straight edge: P1: L/2, L/2; P2 (Simpson): L/6, L/6 and 4L/6 at the middle.
  const double end_weight = degree_ == 1 ? 0.5 : 1.0 / 6.0;
  for (int k = 0; k < 2; ++k) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(section, cone[k], &off));
    offsets->push_back(off);
    weights->push_back(end_weight * *measure);
  }
  if (degree_ == 2) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(section, face, &off));
    offsets->push_back(off);
    weights->push_back(4.0 / 6.0 * *measure);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::SurfaceFaceNodes(PetscInt face, std::vector<PetscInt>* offsets,
                                               std::vector<double>* weights, double* area) const {
  PetscFunctionBeginUser;
  PetscSection section;
  PetscCall(DMGetLocalSection(dm_, &section));
  std::vector<PetscInt> corners, edges;
  PetscCall(mesh::FaceCycle(dm_, face, &corners, &edges));
  // The corners' coordinates read directly: copying every vertex a face would cost O(faces × vertices).
  Vec coordinates;
  PetscSection coordinate_section;
  const PetscScalar* xc;
  PetscCall(DMGetCoordinatesLocalSetUp(dm_));
  PetscCall(DMGetCoordinatesLocal(dm_, &coordinates));
  PetscCall(DMGetCoordinateSection(dm_, &coordinate_section));
  PetscCall(VecGetArrayRead(coordinates, &xc));
  std::vector<geometry::Vec3> points;
  for (PetscInt v : corners) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(coordinate_section, v, &off));
    points.push_back({PetscRealPart(xc[off]), PetscRealPart(xc[off + 1]), PetscRealPart(xc[off + 2])});
  }
  PetscCall(VecRestoreArrayRead(coordinates, &xc));
  const FaceNodeWeights w = FaceWeights(points, static_cast<int>(degree_));
  *area = w.area;
  const auto add = [&](PetscInt point, double weight) -> PetscErrorCode {
    PetscFunctionBeginUser;
    PetscInt off, dofs;
    PetscCall(PetscSectionGetDof(section, point, &dofs));
    if (dofs == 0) PetscFunctionReturn(0);  // no node here (P2 triangle faces)
    PetscCall(PetscSectionGetOffset(section, point, &off));
    offsets->push_back(off);
    weights->push_back(weight);
    PetscFunctionReturn(0);
  };
  for (std::size_t k = 0; k < corners.size(); ++k) PetscCall(add(corners[k], w.corner[k]));
  for (std::size_t k = 0; k < w.edge.size(); ++k) PetscCall(add(edges[k], w.edge[k]));
  if (degree_ == 2) PetscCall(add(face, w.interior));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::QuadraturePoints(PetscInt cell, std::vector<double>* xy) const {
  PetscFunctionBeginUser;
  // The cell geometry's points, not DMPlexReferenceToCoordinates: that one sorts the
  // cell-type label's strata on every call (PETSc 3.18), minutes over a 3D heat grid.
  const std::size_t n = static_cast<std::size_t>(qpoints_);
  std::vector<double> J(n * dim_ * dim_), detJ(n);
  xy->resize(dim_ * n);
  PetscCall(DMPlexComputeCellGeometryFEM(dm_, cell, quad_, xy->data(), J.data(), nullptr, detJ.data()));
  PetscFunctionReturn(0);
}

bool InReferenceCell(const double* r, int dim, bool simplex, double tol) {
  // Written as "not inside" so that a NaN (no inverse map) is outside.
  if (!simplex) {
    for (int d = 0; d < dim; ++d)
      if (!(std::abs(r[d]) <= 1 + tol)) return false;
    return true;
  }
  double sum = r[0];
  for (int d = 1; d < dim; ++d) sum += r[d];
  for (int d = 0; d < dim; ++d)
    if (!(r[d] >= -1 - tol)) return false;
  return sum <= (2 - dim) + tol;
}

PetscErrorCode LagrangeSpace::Locate(const double* point, PetscInt* cell, ReferencePoint* ref) const {
  PetscFunctionBeginUser;
  const int D = dim_;
  *cell = -1;
  // The inverse map is costly (~ms a cell in PETSc 3.18): try only the cells
  // whose bounding box holds the point.
  DM cdm;
  Vec coordinates;
  PetscSection csection;
  PetscCall(DMGetCoordinatesLocalSetUp(dm_));
  PetscCall(DMGetCoordinatesLocal(dm_, &coordinates));
  PetscCall(DMGetCoordinateDM(dm_, &cdm));
  PetscCall(DMGetLocalSection(cdm, &csection));
  for (PetscInt c : cells_) {
    PetscScalar* xc = nullptr;
    PetscInt n;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    PetscCall(DMPlexVecGetClosure(cdm, csection, coordinates, c, &n, &xc));
    for (PetscInt i = 0; i < n; ++i) {
      lo[i % D] = std::min(lo[i % D], PetscRealPart(xc[i]));
      hi[i % D] = std::max(hi[i % D], PetscRealPart(xc[i]));
    }
    PetscCall(DMPlexVecRestoreClosure(cdm, csection, coordinates, c, &n, &xc));
    double extent = hi[0] - lo[0];
    for (int d = 1; d < D; ++d) extent = std::max(extent, hi[d] - lo[d]);
    const double pad = 1e-9 * extent;
    bool outside = false;
    for (int d = 0; d < D; ++d) outside = outside || point[d] < lo[d] - pad || point[d] > hi[d] + pad;
    if (outside) continue;
    double r[3] = {0.0, 0.0, 0.0};
    PetscCall(DMPlexCoordinatesToReference(dm_, c, 1, point, r));
    if (InReferenceCell(r, D, simplex_, 1e-10)) {
      *cell = c;
      *ref = {r[0], r[1], r[2]};
      break;
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::Locate(double x, double y, PetscInt* cell, std::array<double, 2>* ref) const {
  PetscFunctionBeginUser;
  PetscCall(RequirePlanar("Locate"));
  const double point[2] = {x, y};
  ReferencePoint r;
  PetscCall(Locate(point, cell, &r));
  if (*cell >= 0) *ref = {r[0], r[1]};
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::BasisAt(const ReferencePoint& ref, std::vector<double>* phi) const {
  PetscFunctionBeginUser;
  PetscTabulation T;
  PetscCall(PetscFECreateTabulation(fe_, 1, 1, ref.data(), 0, &T));
  phi->assign(T->T[0], T->T[0] + nodes_);
  PetscCall(PetscTabulationDestroy(&T));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::BasisAt(const std::array<double, 2>& ref, std::vector<double>* phi) const {
  PetscFunctionBeginUser;
  PetscCall(RequirePlanar("BasisAt"));
  PetscCall(BasisAt(ReferencePoint{ref[0], ref[1], 0.0}, phi));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::BasisAndDerivativesAt(const ReferencePoint& ref, std::vector<double>* phi,
                                                    std::vector<double>* dphi) const {
  return BasisAndDerivativesAt(std::vector<ReferencePoint>{ref}, phi, dphi);
}

PetscErrorCode LagrangeSpace::BasisAndDerivativesAt(const std::vector<ReferencePoint>& refs, std::vector<double>* phi,
                                                    std::vector<double>* dphi) const {
  PetscFunctionBeginUser;
  const PetscInt n = static_cast<PetscInt>(refs.size());
  std::vector<double> packed;
  for (const ReferencePoint& r : refs) packed.insert(packed.end(), r.begin(), r.begin() + dim_);
  PetscTabulation T;
  PetscCall(PetscFECreateTabulation(fe_, 1, n, packed.data(), 1, &T));
  phi->assign(T->T[0], T->T[0] + n * nodes_);
  dphi->assign(T->T[1], T->T[1] + n * dim_ * nodes_);
  PetscCall(PetscTabulationDestroy(&T));
  PetscFunctionReturn(0);
}

PetscErrorCode LagrangeSpace::BasisAndDerivativesAt(const std::array<double, 2>& ref, std::vector<double>* phi,
                                                    std::vector<double>* dphi) const {
  PetscFunctionBeginUser;
  PetscCall(RequirePlanar("BasisAndDerivativesAt"));
  PetscCall(BasisAndDerivativesAt(ReferencePoint{ref[0], ref[1], 0.0}, phi, dphi));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::fe
