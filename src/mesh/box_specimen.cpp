#include "vibrotherm/mesh/box_specimen.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include "vibrotherm/mesh/box_mesher.hpp"
#include "vibrotherm/mesh/plex/crack_split.hpp"
#include "vibrotherm/mesh/plex/distribute.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::mesh {
namespace {

/// The serial heat mesh: the box again, unsplit (temperature is continuous across
/// the crack), on its own grid: -heat_mesh_h_along on the crack, layers from
/// -heat_mesh_h_crack growing by -heat_mesh_growth across its plane, up to
/// -heat_mesh_h away (-heat_mesh wave: the wave grid's sizes).
PetscErrorCode CreateBoxHeatPlex(MPI_Comm comm, const SpecimenGeometry& geometry, const HeatMeshSizes& sizes,
                                 std::unique_ptr<BoxGrid>* heat_grid, DM* heat, std::string* heat_source) {
  PetscFunctionBeginUser;
  std::unique_ptr<BoxGrid>& grid = *heat_grid;
  VibrothermCallCpp(comm, grid = std::make_unique<BoxGrid>(geometry, BoxHeatGridSizes(geometry, sizes)));
  PetscCall(PetscPrintf(comm, "Meshing: the heat box of %d x %d x %d hexahedra (%s)\n", grid->cells(0),
                        grid->cells(1), grid->cells(2),
                        sizes.graded ? "layers graded across the crack plane" : "the wave grid, unsplit"));
  PetscInt crack_faces;
  PetscCall(CreateBoxPlex(comm, geometry, *grid, heat, &crack_faces));
  *heat_source = sizes.graded ? "graded" : "wave";
  PetscFunctionReturn(0);
}

}  // namespace

int CrackFaceSubdivisions(const std::array<int, 2>& wave_cells, const std::array<int, 2>& heat_cells, bool* exact) {
  constexpr int kLeast = 4, kMost = 16;
  int nest = 1;
  for (int side = 0; side < 2; ++side)
    nest = std::lcm(nest, heat_cells[side] / std::gcd(heat_cells[side], wave_cells[side]));
  const int subdivisions = nest * ((kLeast + nest - 1) / nest);
  *exact = subdivisions <= kMost;
  return std::min(subdivisions, kMost);
}

BoxGridSizes BoxHeatGridSizes(const SpecimenGeometry& geometry, const HeatMeshSizes& sizes) {
  return sizes.graded ? BoxGridSizes{sizes.h_along, sizes.h, sizes.grading, sizes.h_crack, sizes.growth}
                      : BoxGridSizes{geometry.h_crack, geometry.h, geometry.grading};
}

PetscErrorCode CreateBoxSpecimen(MPI_Comm comm, const SpecimenGeometry& geometry, double exchange_length,
                                 Specimen* s) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  std::unique_ptr<BoxGrid> grid;
  VibrothermCallCpp(comm, grid = std::make_unique<BoxGrid>(geometry));
  HeatMeshSizes heat_sizes;
  PetscCall(ReadHeatMeshSizes(comm, geometry, exchange_length, &heat_sizes));
  if (geometry.cracks.empty())
    PetscCall(PetscPrintf(comm, "Meshing: a 3D box of %d x %d x %d hexahedra on rank 0 (no crack)\n", grid->cells(0),
                          grid->cells(1), grid->cells(2)));
  else
    PetscCall(PetscPrintf(comm,
                          "Meshing: a 3D box of %d x %d x %d hexahedra on rank 0 (graded to the crack, sheared "
                          "into its plane: %d x %d crack faces)\n",
                          grid->cells(0), grid->cells(1), grid->cells(2), grid->crack_cells(0), grid->crack_cells(1)));
  for (const BoxGrid::PatchSnap& snap : grid->patch_snaps())
    PetscCall(PetscPrintf(comm, "vibrotherm: note: the patch's edge at %c = %g m stays on the grid line at %g m "
                          "(a fixed line within a third of a cell; summary.json mesh.source_area has the area)\n",
                          "xyz"[snap.axis], snap.bound, snap.line));
  DM serial;
  PetscInt crack_faces;
  PetscCall(CreateBoxPlex(comm, geometry, *grid, &serial, &crack_faces));
  const bool cracked = !geometry.cracks.empty();
  if (cracked && geometry.cracks.front().shape == CrackShape::Ellipse) {
    const Crack& crack = geometry.cracks.front();
    const int n1 = grid->crack_cells(0), n2 = grid->crack_cells(1);
    const double area = grid->crack_area();
    const double ellipse = 0.25 * M_PI * crack.length * crack.width;
    PetscCall(PetscPrintf(comm, "Meshing: the elliptical crack is %" PetscInt_FMT " of its %d x %d rectangle's faces: "
                          "%.4g m2, %.4f of the ellipse's area\n", crack_faces, n1, n2, area, area / ellipse));
  }
  if (cracked) s->cracks = {CrackInfo{"crack1", geometry.cracks.front().length}};
  s->source = "generated";
  // SplitCracks puts the front (edges with one crack face, their vertices) in the
  // boundary label and checks one cohesive cell per crack face.
  PetscCall(SplitCracks(serial, &s->wave));
  PetscCall(DMDestroy(&serial));
  std::unique_ptr<BoxGrid> heat_grid;
  PetscCall(CreateBoxHeatPlex(comm, geometry, heat_sizes, &heat_grid, &s->heat, &s->heat_source));
  bool exact = true;
  if (cracked)
    s->crack_face_subdivisions = CrackFaceSubdivisions({grid->crack_cells(0), grid->crack_cells(1)},
                                                       {heat_grid->crack_cells(0), heat_grid->crack_cells(1)}, &exact);
  if (!exact)
    PetscCall(PetscPrintf(comm, "vibrotherm: note: the heat grid's crack faces do not nest in %d sub-squares a side "
                          "of the wave grid's: the friction heat's transfer is conservative but not exact (make "
                          "-mesh_h_crack a multiple of -heat_mesh_h_along)\n", s->crack_face_subdivisions));
  PetscCall(DistributeMesh(&s->wave, "wave_mesh", &s->wave_origin));
  PetscCall(DistributeMesh(&s->heat, "heat_mesh", &s->heat_origin));
  PetscCall(PetscPrintf(comm, "Meshing: %.2f s\n", MPI_Wtime() - t0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
