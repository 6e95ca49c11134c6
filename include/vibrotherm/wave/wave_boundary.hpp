// Boundary terms of the wave problem, built from the face labels (edges in 2D,
// faces in 3D):
//   absorbing  Lysmer–Kuhlemeyer dashpots: per node the D×D block
//              Σ_faces w ρ (c_p n nᵀ + c_s (I − n nᵀ))  (w = ∫φ dA; 2D: c_s s sᵀ)
//   source     the prescribed component (displacement source) or the load
//              shape ∫φ d ds (traction source), d = tangent or outward normal
//              (3D tangential: x projected onto the face, z on a face normal to x)
//   roller     zero normal displacement (symmetry plane);  antisymmetric  zero
//              tangential displacement (antisymmetry plane);  fixed  zero displacement
// A node where faces of one kind meet at an angle gets one constrained
// direction per distinct normal (3D: two on an edge, three at a corner; 2D: one).
// Nodes are owned dofs of the global vector (component k of node: dof D·node + k).
#pragma once

#include <petscvec.h>

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/dashpot_blocks.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/material.hpp"

namespace vibrotherm::wave {

/// One prescribed displacement component: u_node · d = target.
struct Constraint {
  PetscInt node;      ///< owned node index (x dof = D·node in the owned array)
  double d[3];        ///< unit direction (2D: d[2] = 0)
  bool source;        ///< target from the source signal, else zero
};

struct WaveBoundary {
  int dim = 2;  ///< the mesh's: D components a node
  std::vector<Constraint> constraints;
  DashpotBlocks dashpots;
  Vec traction_shape = nullptr;  ///< global: ∫φ d ds on the source edge (traction source only)
  double source_length = 0.0, absorbing_length = 0.0;  ///< total length (2D) or area (3D)
  WaveBoundary() = default;
  WaveBoundary(const WaveBoundary&) = delete;  // owns traction_shape
  WaveBoundary& operator=(const WaveBoundary&) = delete;
  ~WaveBoundary() { (void)VecDestroy(&traction_shape); }
};

PetscErrorCode BuildWaveBoundary(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                 const Excitation& excitation, WaveBoundary* boundary);

}  // namespace vibrotherm::wave
