#include "vibrotherm/mesh/memory_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "vibrotherm/mesh/box_grid.hpp"

namespace vibrotherm::mesh {
namespace {

/// Cells of the graded band around one crack beyond what the far-field size would give.
double CrackBandCells(const SpecimenGeometry& g, const Crack& c) {
  const double d_max = std::max(0.0, (g.h - g.h_crack) / g.grading);
  const int n = 200;
  double cells = 0.0;
  for (int i = 0; i < n; ++i) {  // midpoint rule over the distance from the crack
    const double d = (i + 0.5) * d_max / n, h = g.h_crack + g.grading * d;
    cells += (2.0 * c.length + 2.0 * M_PI * d) * (1.0 / (h * h) - 1.0 / (g.h * g.h)) * d_max / n;
  }
  return cells;
}

/// A 3D box: its structured grid's hexahedra exactly; Q2 elasticity has ~192 nonzeros a row (3D-NOTES §5).
MemoryEstimate EstimateBox(const SpecimenGeometry& g, int wave_degree, int ranks, const BoxGridSizes* heat_grid) {
  const BoxGrid grid(g);
  MemoryEstimate e;
  e.wave_cells = static_cast<double>(grid.total_cells());
  e.wave_dofs = 3.0;
  for (int a = 0; a < 3; ++a) e.wave_dofs *= wave_degree * grid.cells(a) + 1.0;
  const double nonzeros_per_row = wave_degree == 2 ? 192.0 : 54.0;
  e.bytes = 4e3 * e.wave_cells + e.wave_dofs * (10.0 * nonzeros_per_row + 30.0 * 8.0) + 1e8 * ranks;
  if (heat_grid) {
    const BoxGrid heat(g, *heat_grid);
    e.heat_cells = static_cast<double>(heat.total_cells());
    e.heat_dofs = 1.0;
    for (int a = 0; a < 3; ++a) e.heat_dofs *= heat.cells(a) + 1.0;
    e.bytes += 4e3 * e.heat_cells + 2e3 * e.heat_dofs;
  }
  return e;
}

}  // namespace

MemoryEstimate EstimateMemory(const SpecimenGeometry& g, int refinements, int wave_degree, int ranks,
                              const BoxGridSizes* heat_grid) {
  if (g.depth > 0.0) return EstimateBox(g, wave_degree, ranks, heat_grid);
  MemoryEstimate e;
  double cells = g.width * g.height / (g.h * g.h);
  for (const Crack& c : g.cracks) cells += CrackBandCells(g, c);
  if (!g.quads) cells *= 2.3;  // triangles of the same size
  cells *= std::pow(4.0, refinements);
  e.wave_cells = cells;
  const double nodes_per_cell = wave_degree == 2 ? 4.0 : 1.0, nonzeros_per_row = wave_degree == 2 ? 50.0 : 18.0;
  e.wave_dofs = 2.0 * nodes_per_cell * cells;
  e.heat_cells = 3.5 * cells / std::pow(4.0, refinements);  // the heat mesh ignores -dm_refine
  e.heat_dofs = e.heat_cells;
  const double mesh_bytes = 2e3 * (e.wave_cells + e.heat_cells);
  const double wave_bytes = e.wave_dofs * (10.0 * nonzeros_per_row + 30.0 * 8.0);
  const double heat_bytes = e.heat_dofs * 500.0;  // matrix, Cholesky factor, vectors
  e.bytes = mesh_bytes + wave_bytes + heat_bytes + 1e8 * ranks;  // + PETSc, MPI, HDF5 per process
  return e;
}

double AvailableMemory() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kb;
  std::string unit;
  while (meminfo >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024.0;
  return 0.0;
}

}  // namespace vibrotherm::mesh
