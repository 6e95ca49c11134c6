// Boundary terms of the wave problem, built from the edge labels:
//   absorbing  Lysmer–Kuhlemeyer dashpots: per node the 2x2 block
//              Σ_faces w ρ (c_p n nᵀ + c_s s sᵀ)  (w = ∫φ ds)
//   source     the prescribed component (displacement source) or the load
//              shape ∫φ d ds (traction source), d = tangent or outward normal
//   roller     zero normal displacement (symmetry plane);  antisymmetric  zero
//              tangential displacement (antisymmetry plane);  fixed  zero displacement
// Nodes are owned dofs of the global vector (x dof = 2·node, y dof = 2·node+1).
#pragma once

#include <petscvec.h>

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/material.hpp"

namespace vibrotherm::wave {

/// One prescribed displacement component: u_node · d = target.
struct Constraint {
  PetscInt node;      ///< owned node index (x dof = 2·node in the owned array)
  double d[2];        ///< unit direction
  bool source;        ///< target from the source signal, else zero
};

/// A node's dashpot: the symmetric block [[xx, xy], [xy, yy]].
struct Dashpot {
  PetscInt node;
  double xx, xy, yy;
};

struct WaveBoundary {
  std::vector<Constraint> constraints;
  std::vector<Dashpot> dashpots;
  Vec traction_shape = nullptr;  ///< global: ∫φ d ds on the source edge (traction source only)
  double source_length = 0.0, absorbing_length = 0.0;
  WaveBoundary() = default;
  WaveBoundary(const WaveBoundary&) = delete;  // owns traction_shape
  WaveBoundary& operator=(const WaveBoundary&) = delete;
  ~WaveBoundary() { (void)VecDestroy(&traction_shape); }
};

PetscErrorCode BuildWaveBoundary(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                 const Excitation& excitation, WaveBoundary* boundary);

}  // namespace vibrotherm::wave
