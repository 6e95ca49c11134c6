// Levels of clustered local time stepping (LTS): which cells step how often.
//
// Each cell gets an estimate of its own stable step, dt_e ∝ 1/ω_e with
// ω_e² = λ_max(M_e⁻¹ K_e) (the cell's stiffness against its own lumped mass:
// geometry, degree and material in one number). Cells are grouped into rate-2
// clusters (SeisSol's scheme): with r_e = dt_e / min dt, the cell goes to
// k_e = ⌊log2(r_e / λ)⌋ doublings above the finest step (λ: -wave_lts_wiggle,
// in (0.5, 1]), capped at -wave_lts_max_levels − 1. Levels are numbered from
// the coarsest: level 0 steps H, level l steps H / 2^l. Cells sharing a node
// are made at most one level apart (the finer one wins). The macro step H
// itself comes from each level's exact spectrum (lts_stepper.hpp), not from
// these estimates: they only decide the grouping.
#pragma once

#include <petscvec.h>

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/material.hpp"

namespace vibrotherm::wave {

struct LtsOptions {
  bool on = false;            ///< -wave_lts on|off
  PetscInt max_levels = 4;    ///< -wave_lts_max_levels
  double cfl = 0.7;           ///< -wave_lts_cfl: fraction of each level's own stability limit
  double wiggle = 1.0;        ///< -wave_lts_wiggle: SeisSol's λ
  double step_quantum = 0.0;  ///< the macro step divides it (WaveOptions::step_quantum)
};

struct LtsLevels {
  std::vector<PetscInt> cell_level;  ///< per index in space.cells(); 0 = coarsest
  PetscInt levels = 1;               ///< element levels (same on every rank)
};

/// ω_e of one cell: √λ_max(M_e⁻¹ K_e) with its own lumped mass.
double CellAngularFrequency(const fe::CellQuadrature& q, const ElasticMaterial& material, bool hrz);

/// The cells' levels (collective).
PetscErrorCode AssignCellLevels(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                const LtsOptions& options, LtsLevels* levels);

/// Per owned dof (index in the global vector's local part): the finest level of
/// the cells holding it, on any rank; touched[l][i]: dof i belongs to a cell of level l.
PetscErrorCode DofLevels(const fe::LagrangeSpace& space, const LtsLevels& levels, std::vector<PetscInt>* finest,
                         std::vector<std::vector<char>>* touched);

}  // namespace vibrotherm::wave
