// The assembled operators of elastodynamics (plane strain in 2D) on a
// LagrangeSpace with one component per mesh dimension D (read from the DM):
// stiffness K (BAIJ, block size D, assembled once) and the lumped mass M (a
// vector; all components of a node share its mass).
//
//   K_ab^ij = ∫ λ ∂_i φ_a ∂_j φ_b + G (δ_ij ∇φ_a·∇φ_b + ∂_j φ_a ∂_i φ_b)
//   M_a     = ∫ ρ φ_a            (row-sum lumping: P1, Q1, and Q2 where the row
//                                 sums are the Gauss–Lobatto weights, all > 0)
//   M_a     = M_aa^cons · m_e / Σ_b M_bb^cons   (HRZ for P2 triangles and
//                                 tetrahedra, whose row sums vanish (triangles)
//                                 or go negative (tetrahedra) at vertices)
#pragma once

#include <petscmat.h>

#include <functional>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/material.hpp"

namespace vibrotherm::wave {

/// The element stiffness of one cell (D·nodes square, D = q.dim, node-major,
/// components interleaved as the cell closure), from its quadrature data.
void ElementStiffness(const fe::CellQuadrature& q, double lambda, double G, double* Ke);
/// The lumped mass of one cell (D·nodes entries, all components of a node
/// share its mass): row sums, or HRZ (hrz: P2 simplices).
void ElementLumpedMass(const fe::CellQuadrature& q, double rho, bool hrz, double* me);
/// Creates and assembles the stiffness of the cells `include` accepts (by index
/// in space.cells(); null: all) on the DM's full pattern (unused entries dropped at assembly).
PetscErrorCode AssembleElasticStiffness(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                        const std::function<bool(std::size_t)>& include, Mat* K);
/// K → A = −M⁻¹K in place (rows scaled by −1/m_i): the explicit steps' operator,
/// of the whole stiffness or of one LTS level's.
PetscErrorCode ScaleToAcceleration(Mat K, Vec lumped_mass);
/// Creates and assembles K (global, from DMCreateMatrix) and the lumped mass (global vector).
PetscErrorCode AssembleElasticOperators(const fe::LagrangeSpace& space, const ElasticMaterial& material, Mat* K,
                                        Vec* lumped_mass);

}  // namespace vibrotherm::wave
