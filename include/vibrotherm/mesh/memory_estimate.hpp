// What a scene will allocate, estimated from its geometry before any mesh is
// made (a fine -mesh_h or a -dm_refine would otherwise allocate for minutes):
// cells from the size field (far field W·H/h², plus each crack's graded band
// ∫ (2L + 2πd) / h(d)² dd with h(d) = h_crack + grading·d), ×4 per -dm_refine;
// dofs per cell of the Lagrange degree; bytes per cell and per dof calibrated
// on the paper scene (mesh and topology ~2 kB/cell, matrix and vectors
// ~10 B per nonzero + 30 vectors). A rough estimate: within a factor 2–3.
// A 3D box (-specimen_depth): its wave and heat grids' cells exactly (the heat
// grid's sizes given), ~2 kB per heat dof (Q1: M, K, the Jacobian, BoomerAMG).
#pragma once

#include "vibrotherm/mesh/box_grid.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::mesh {

struct MemoryEstimate {
  double wave_cells = 0, wave_dofs = 0, heat_cells = 0, heat_dofs = 0;
  double bytes = 0;  ///< all ranks together, the libraries' own footprint included
};

/// heat_grid: the 3D heat grid's sizes (null: the heat mesh is not estimated in 3D).
MemoryEstimate EstimateMemory(const SpecimenGeometry& geometry, int refinements, int wave_degree, int ranks,
                              const BoxGridSizes* heat_grid = nullptr);

/// Bytes the machine can still give (MemAvailable of /proc/meminfo); 0 if unknown.
double AvailableMemory();

}  // namespace vibrotherm::mesh
