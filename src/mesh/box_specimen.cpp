#include "vibrotherm/mesh/box_specimen.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <string>

#include "vibrotherm/mesh/box_mesher.hpp"
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
                        !sizes.graded ? "the wave grid, unsplit" : geometry.cracks.size() > 1 ?
                        "layers graded across the crack planes" : "layers graded across the crack plane"));
  PetscInt crack_faces;
  PetscCall(CreateBoxPlex(comm, geometry, *grid, heat, &crack_faces));
  *heat_source = sizes.graded ? "graded" : "wave";
  PetscFunctionReturn(0);
}

/// ", breaking the front face" (and the left face ...) for a crack that breaks faces, else "".
std::string BrokenFacesText(const BoxGrid& grid, int k) {
  const std::vector<Side>& faces = grid.broken_faces(k);
  std::string text;
  for (std::size_t i = 0; i < faces.size(); ++i)
    text += std::string(i == 0 ? ", breaking the " : i + 1 == faces.size() ? " and the " : ", the ") + to_string(faces[i]);
  return faces.empty() ? text : text + (faces.size() > 1 ? " faces" : " face");
}

/// Each crack's faces, and how far an elliptical one's staircase is from its ellipse (the
/// part of it in the body).
PetscErrorCode PrintCracks(MPI_Comm comm, const SpecimenGeometry& geometry, const BoxGrid& grid, PetscInt faces) {
  PetscFunctionBeginUser;
  PetscInt counted = 0;
  for (int k = 0; k < grid.crack_count(); ++k) {
    const Crack& crack = geometry.cracks[k];
    const int n1 = grid.crack_cells(0, k), n2 = grid.crack_cells(1, k);
    const double area = grid.crack_area(k), outline = grid.outline_area(k);
    const PetscInt mine = grid.crack_faces(k);
    const std::string breaks = BrokenFacesText(grid, k);
    counted += mine;
    if (crack.shape == CrackShape::Ellipse)
      PetscCall(PetscPrintf(comm, "Meshing: crack %d: the elliptical crack is %" PetscInt_FMT " of its %d x %d "
                            "rectangle's faces: %.4g m2, %.4f of the ellipse's area%s%s\n", k + 1, mine, n1, n2, area,
                            area / outline, grid.broken_faces(k).empty() ? "" : " in the body", breaks.c_str()));
    else if (grid.crack_staircase(k))  // tilted and turned: a parallelogram in the grid's axes
      PetscCall(PetscPrintf(comm, "Meshing: crack %d: the tilted crack is %" PetscInt_FMT " of its %d x %d "
                            "bounding rectangle's faces (a staircase): %.4g m2, %.4f of its area in the body%s\n",
                            k + 1, mine, n1, n2, area, area / outline, breaks.c_str()));
    else if (std::abs(area / outline - 1.0) > 1e-9)  // an end moved onto another crack's line
      PetscCall(PetscPrintf(comm, "Meshing: crack %d: %d x %d faces, %.4g m2 (%+.3g %% of its area in the body: an "
                            "end shares a nearby crack's grid line)%s\n", k + 1, n1, n2, area,
                            100.0 * (area / outline - 1.0), breaks.c_str()));
    else
      PetscCall(PetscPrintf(comm, "Meshing: crack %d: %d x %d faces, %.4g m2%s\n", k + 1, n1, n2, area, breaks.c_str()));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &faces, 1, MPIU_INT, MPI_MAX, comm));  // the serial mesh is on rank 0
  PetscCheck(counted == faces, comm, PETSC_ERR_PLIB, "3D box: %" PetscInt_FMT " crack faces labelled, the grid has %"
             PetscInt_FMT, faces, counted);
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

int CrackFaceSubdivisions(const BoxGrid& wave, const BoxGrid& heat, bool* exact) {
  constexpr int kLeast = 4, kMost = 16;
  const auto nests = [&](int m) {  // every heat line on a crack at a multiple of 1/m of its wave cell
    for (int k = 0; k < wave.crack_count(); ++k)
      for (int along = 0; along < 2; ++along) {
        const std::vector<double> w = wave.crack_nodes(k, along), h = heat.crack_nodes(k, along);
        for (double x : h) {
          const std::size_t i = std::min<std::size_t>(
              std::max<std::ptrdiff_t>(std::upper_bound(w.begin(), w.end(), x) - w.begin(), 1) - 1, w.size() - 2);
          const double at = (x - w[i]) / (w[i + 1] - w[i]) * m;
          if (std::abs(at - std::round(at)) > 1e-6) return false;
        }
      }
    return true;
  };
  for (int m = kLeast; m <= kMost; ++m)
    if (nests(m)) return *exact = true, m;
  *exact = false;
  return kMost;
}

BoxGridSizes BoxHeatGridSizes(const SpecimenGeometry& geometry, const HeatMeshSizes& sizes) {
  return sizes.graded ? BoxGridSizes{sizes.h_along, sizes.h, sizes.grading, sizes.h_crack, sizes.growth}
                      : BoxGridSizes{geometry.h_crack, geometry.h, geometry.grading};
}

PetscErrorCode CreateBoxSpecimen(MPI_Comm comm, const SpecimenGeometry& geometry, const HeatMeshSizes& heat_sizes,
                                 DM* serial, Specimen* s) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  std::unique_ptr<BoxGrid> grid;
  VibrothermCallCpp(comm, grid = std::make_unique<BoxGrid>(geometry));
  if (geometry.cracks.empty())
    PetscCall(PetscPrintf(comm, "Meshing: a 3D box of %d x %d x %d hexahedra on rank 0 (no crack)\n", grid->cells(0),
                          grid->cells(1), grid->cells(2)));
  else
    PetscCall(PetscPrintf(comm, "Meshing: a 3D box of %d x %d x %d hexahedra on rank 0 (graded to the crack%s, sheared "
                          "into %s)\n", grid->cells(0), grid->cells(1), grid->cells(2),
                          grid->crack_count() > 1 ? "s" : "", grid->crack_count() > 1 ? "their planes" : "its plane"));
  for (const BoxGrid::PatchSnap& snap : grid->patch_snaps())
    PetscCall(PetscPrintf(comm, "vibrotherm: note: the patch's edge at %c = %g m stays on the grid line at %g m "
                          "(a fixed line within a third of a cell; summary.json mesh.source_area has the area)\n",
                          "xyz"[snap.axis], snap.bound, snap.line));
  PetscInt crack_faces;
  PetscCall(CreateBoxPlex(comm, geometry, *grid, serial, &crack_faces));
  PetscCall(PrintCracks(comm, geometry, *grid, crack_faces));
  for (int k = 0; k < grid->crack_count(); ++k) {
    std::vector<std::string> breaks;
    for (Side face : grid->broken_faces(k)) breaks.push_back(to_string(face));
    s->cracks.push_back(CrackInfo{"crack" + std::to_string(k + 1), geometry.cracks[k].length, breaks});
  }
  s->source = "generated";
  if (heat_sizes.graded && heat_sizes.h_along > geometry.h_crack * (1.0 + 1e-9) && !geometry.cracks.empty())
    PetscCall(PetscPrintf(comm, "vibrotherm: note: -heat_mesh_h_along %g m is coarser than -mesh_h_crack %g m: the 3D "
                          "heat grid's crack cells are the wave grid's (they nest in them)\n", heat_sizes.h_along,
                          geometry.h_crack));
  std::unique_ptr<BoxGrid> heat_grid;
  PetscCall(CreateBoxHeatPlex(comm, geometry, heat_sizes, &heat_grid, &s->heat, &s->heat_source));
  bool exact = true;
  if (grid->crack_count() > 0) s->crack_face_subdivisions = CrackFaceSubdivisions(*grid, *heat_grid, &exact);
  if (!exact)
    PetscCall(PetscPrintf(comm, "vibrotherm: note: the heat grid's crack faces do not nest in %d sub-squares a side "
                          "of the wave grid's: the friction heat's transfer is conservative but not exact (make "
                          "-mesh_h_crack a multiple of -heat_mesh_h_along)\n", s->crack_face_subdivisions));
  PetscCall(PetscPrintf(comm, "Meshing: %.2f s\n", MPI_Wtime() - t0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
