// A 3D box specimen (-specimen_depth > 0), one of SpecimenCreate's sources: the graded
// hexahedral grid with its cracks (box_grid.hpp, box_mesher.hpp), serial and unsplit here;
// SpecimenCreate splits and distributes it as every specimen.
// The heat mesh is the box again, unsplit, on a grid with layers across the crack
// plane (box_specimen.cpp). No crack surface gathers (wave_cracks, heat_cracks
// empty: they are 2D; the friction heat finds the crack from the contact cells).
#pragma once

#include <array>

#include "vibrotherm/mesh/box_grid.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::mesh {

/// The heat grid's sizes from the -heat_mesh* options (-heat_mesh wave: the wave grid's).
BoxGridSizes BoxHeatGridSizes(const SpecimenGeometry& geometry, const HeatMeshSizes& sizes);

/// Sub-squares per side of a wave crack face for the friction heat's quadrature (3 × 3
/// Gauss points each), given the cells both grids put along the crack's two sides (each
/// grid splits the crack evenly): a multiple of n_heat / gcd(n_heat, n_wave) on every
/// side, so the heat grid's lines are sub-square edges and the heat basis is one
/// polynomial on each (exact); at least 4 (a Q2 wave face), at most 16 (exact false:
/// then accurate, not exact).
int CrackFaceSubdivisions(const std::array<int, 2>& wave_cells, const std::array<int, 2>& heat_cells, bool* exact);
/// The same from the two grids' lines on every crack (cracks whose extents overlap along
/// an axis have uneven cells): the least m in [4, 16] for which every heat line lies at a
/// multiple of 1/m of its wave cell (exact), else 16 (exact false).
int CrackFaceSubdivisions(const BoxGrid& wave, const BoxGrid& heat, bool* exact);

/// The serial box, unsplit, in *serial; its heat grid in specimen->heat, its cracks, source and
/// crack-face subdivisions. geometry: checked by ReadSpecimenOptions (depth > 0); heat_sizes: the
/// heat grid's (HeatMeshSizesFor). Collective.
PetscErrorCode CreateBoxSpecimen(MPI_Comm comm, const SpecimenGeometry& geometry, const HeatMeshSizes& heat_sizes,
                                 DM* serial, Specimen* specimen);

}  // namespace vibrotherm::mesh
