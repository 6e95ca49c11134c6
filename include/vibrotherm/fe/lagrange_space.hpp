// A Lagrange finite-element space (degree 1 or 2, any number of components) on
// the bulk cells of a DMPlex: its section (set on the DM), the element
// tabulation and quadrature, and physical node coordinates.
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
  std::vector<double> grad;    ///< [q][node][d]: ∂φ_node/∂x_d
  const double* value = nullptr;  ///< [q][node]: φ_node (reference tabulation)
  int points = 0, nodes = 0;
};

class LagrangeSpace {
 public:
  LagrangeSpace() = default;
  LagrangeSpace(const LagrangeSpace&) = delete;
  LagrangeSpace& operator=(const LagrangeSpace&) = delete;
  ~LagrangeSpace();

  /// Builds the space on dm and sets its local section on dm.
  PetscErrorCode Setup(DM dm, PetscInt degree, PetscInt components);

  DM dm() const { return dm_; }
  PetscInt degree() const { return degree_; }
  PetscInt components() const { return components_; }
  bool simplex() const { return simplex_; }
  int nodes_per_cell() const { return nodes_; }
  /// Bulk cells of this rank (cohesive cells excluded).
  const std::vector<PetscInt>& cells() const { return cells_; }

  /// Quadrature data of cell c (reuses q's buffers).
  PetscErrorCode Evaluate(PetscInt cell, CellQuadrature* q) const;

  /// Physical coordinates of every local node: nodes × 2, indexed by local
  /// node = local dof offset / components.
  PetscErrorCode NodeCoordinates(std::vector<std::array<double, 2>>* coords) const;

  /// Local dof offsets of the nodes on a face (vertex nodes and, for degree 2,
  /// the edge node) with their 1D lumped weights ∫φ ds (exact, sum = length).
  PetscErrorCode FaceNodes(PetscInt face, std::vector<PetscInt>* offsets, std::vector<double>* weights,
                           double* length) const;

  /// Physical coordinates of cell's quadrature points (x, y per point).
  PetscErrorCode QuadraturePoints(PetscInt cell, std::vector<double>* xy) const;
  /// The local bulk cell containing (x, y) and the reference coordinates there;
  /// cell = -1 when no local cell contains it.
  PetscErrorCode Locate(double x, double y, PetscInt* cell, std::array<double, 2>* ref) const;
  /// Basis values at a reference point (nodes_per_cell values).
  PetscErrorCode BasisAt(const std::array<double, 2>& ref, std::vector<double>* phi) const;
  /// Basis values and reference-coordinate derivatives ([node][2]) at a reference point.
  PetscErrorCode BasisAndDerivativesAt(const std::array<double, 2>& ref, std::vector<double>* phi,
                                       std::vector<double>* dphi) const;

 private:
  DM dm_ = nullptr;
  PetscFE fe_ = nullptr;  ///< scalar Lagrange element
  PetscInt degree_ = 1, components_ = 1;
  bool simplex_ = false;
  int nodes_ = 0, qpoints_ = 0;
  std::vector<PetscInt> cells_;
  PetscQuadrature quad_ = nullptr;
  const PetscReal* qweights_ = nullptr;
  PetscTabulation tab_ = nullptr;
};

}  // namespace vibrotherm::fe
