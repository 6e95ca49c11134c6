// A Lagrange finite-element space (degree 1 or 2, any number of components) on
// the bulk cells of a DMPlex: its section (set on the DM), the element
// tabulation and quadrature, and physical node coordinates. The dimension (2 or
// 3) and the cell shape (simplex or tensor) are the DM's.
//
// Cohesive (crack) cells carry no unknowns: the space lives on the bulk cells,
// whose closures hold every vertex, so split crack faces get independent dofs.
// Element dofs are ordered as the cell closure: node-major, components
// interleaved (dof = node * Nc + component), the order DMPlexVecGetClosure and
// DMPlexMatSetClosure use.
#pragma once

#include <petscdmplex.h>
#include <petscfe.h>

#include <array>
#include <vector>

namespace vibrotherm::fe {

/// Geometry of one cell at the quadrature points.
struct CellQuadrature {
  std::vector<double> weight;  ///< w_q |det J_q| (physical measure)
  std::vector<double> grad;    ///< [q][node][d]: ∂φ_node/∂x_d, d < dim
  const double* value = nullptr;  ///< [q][node]: φ_node (reference tabulation)
  int points = 0, nodes = 0, dim = 2;
};

/// A point in reference coordinates: the first dim of them are used (2D: z = 0).
using ReferencePoint = std::array<double, 3>;

/// Whether reference coordinates r (dim of them) lie in PETSc's reference cell
/// within tol: [-1,1]^dim, or the simplex with vertices (-1,…,-1) and the unit
/// vectors from it (Σ r ≤ 2 − dim). NaN coordinates are outside.
bool InReferenceCell(const double* r, int dim, bool simplex, double tol);

/// ∇φ_a·∇φ_b of two gradients of `dim` entries, summed in the order x, y, z
/// (the 2D sum is the same expression as a·b = a0 b0 + a1 b1, bit for bit).
inline double GradientDot(const double* ga, const double* gb, int dim) {
  double dot = ga[0] * gb[0];
  for (int d = 1; d < dim; ++d) dot += ga[d] * gb[d];
  return dot;
}

class LagrangeSpace {
 public:
  LagrangeSpace() = default;
  LagrangeSpace(const LagrangeSpace&) = delete;
  LagrangeSpace& operator=(const LagrangeSpace&) = delete;
  ~LagrangeSpace();

  /// Builds the space on dm and sets its local section on dm.
  PetscErrorCode Setup(DM dm, PetscInt degree, PetscInt components);

  DM dm() const { return dm_; }
  /// The DM's topological dimension (= its coordinate dimension).
  int dim() const { return dim_; }
  PetscInt degree() const { return degree_; }
  PetscInt components() const { return components_; }
  bool simplex() const { return simplex_; }
  int nodes_per_cell() const { return nodes_; }
  /// Bulk cells of this rank (cohesive cells excluded).
  const std::vector<PetscInt>& cells() const { return cells_; }

  /// Quadrature data of cell c (reuses q's buffers).
  PetscErrorCode Evaluate(PetscInt cell, CellQuadrature* q) const;

  /// Physical coordinates of every local node: nodes × 2, indexed by local
  /// node = local dof offset / components. 2D only; refused in 3D.
  PetscErrorCode NodeCoordinates(std::vector<std::array<double, 2>>* coords) const;
  /// The same for any dimension: dim() coordinates per local node, node-major.
  PetscErrorCode NodePositions(std::vector<double>* coords) const;

  /// Local dof offsets of the nodes on a boundary face with their lumped
  /// weights ∫φ dA (sum = *measure). 2D: an edge, its vertex nodes and (degree
  /// 2) its middle node, weights ∫φ ds, measure its length. 3D: a quadrilateral
  /// or triangle, its corner, edge and interior nodes, measure its area.
  PetscErrorCode FaceNodes(PetscInt face, std::vector<PetscInt>* offsets, std::vector<double>* weights,
                           double* measure) const;

  /// Physical coordinates of cell's quadrature points (dim() per point).
  PetscErrorCode QuadraturePoints(PetscInt cell, std::vector<double>* xy) const;
  /// The local bulk cell containing point (dim() coordinates) and the
  /// reference coordinates there (the first dim() of ref); cell = -1 when no
  /// local cell contains it.
  PetscErrorCode Locate(const double* point, PetscInt* cell, ReferencePoint* ref) const;
  /// The same in 2D; refused in 3D.
  PetscErrorCode Locate(double x, double y, PetscInt* cell, std::array<double, 2>* ref) const;
  /// Basis values at a reference point (nodes_per_cell values; its first dim() coordinates).
  PetscErrorCode BasisAt(const ReferencePoint& ref, std::vector<double>* phi) const;
  /// The same in 2D; refused in 3D.
  PetscErrorCode BasisAt(const std::array<double, 2>& ref, std::vector<double>* phi) const;
  /// Basis values and reference-coordinate derivatives ([node][dim()]) at a
  /// reference point (its first dim() coordinates).
  PetscErrorCode BasisAndDerivativesAt(const ReferencePoint& ref, std::vector<double>* phi,
                                       std::vector<double>* dphi) const;
  /// The same at several reference points in one tabulation (one call per point costs a
  /// dense product each): phi [point][node], dphi [point][node][dim()].
  PetscErrorCode BasisAndDerivativesAt(const std::vector<ReferencePoint>& refs, std::vector<double>* phi,
                                       std::vector<double>* dphi) const;
  /// The same in 2D; refused in 3D.
  PetscErrorCode BasisAndDerivativesAt(const std::array<double, 2>& ref, std::vector<double>* phi,
                                       std::vector<double>* dphi) const;

 private:
  /// Refuses the 2D-only members on a 3D mesh (what: the member's name).
  PetscErrorCode RequirePlanar(const char* what) const;
  /// FaceNodes on a 3D mesh (see fe/face_weights.hpp).
  PetscErrorCode SurfaceFaceNodes(PetscInt face, std::vector<PetscInt>* offsets, std::vector<double>* weights,
                                  double* area) const;
  DM dm_ = nullptr;
  PetscFE fe_ = nullptr;  ///< scalar Lagrange element
  PetscInt degree_ = 1, components_ = 1;
  int dim_ = 2;
  bool simplex_ = false;
  int nodes_ = 0, qpoints_ = 0;
  std::vector<PetscInt> cells_;
  PetscQuadrature quad_ = nullptr;
  const PetscReal* qweights_ = nullptr;
  PetscTabulation tab_ = nullptr;
};

}  // namespace vibrotherm::fe
