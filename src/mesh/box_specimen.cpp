#include "vibrotherm/mesh/box_specimen.hpp"

#include <memory>

#include "vibrotherm/mesh/box_mesher.hpp"
#include "vibrotherm/mesh/plex/crack_split.hpp"
#include "vibrotherm/mesh/plex/distribute.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::mesh {

PetscErrorCode CreateBoxSpecimen(MPI_Comm comm, const SpecimenGeometry& geometry, Specimen* s) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  std::unique_ptr<BoxGrid> grid;
  VibrothermCallCpp(comm, grid = std::make_unique<BoxGrid>(geometry));
  PetscCall(PetscPrintf(comm,
                        "Meshing: a 3D box of %d x %d x %d hexahedra on rank 0 (graded to the crack, sheared "
                        "into its plane: %d x %d crack faces)\n",
                        grid->cells(0), grid->cells(1), grid->cells(2), grid->crack_cells(0), grid->crack_cells(1)));
  DM serial;
  PetscInt crack_faces;
  PetscCall(CreateBoxPlex(comm, geometry, *grid, &serial, &crack_faces));
  s->cracks = {CrackInfo{"crack1", geometry.cracks.front().length}};
  s->source = "generated";
  s->heat_source = "none";
  // SplitCracks puts the front (edges with one crack face, their vertices) in the
  // boundary label and checks one cohesive cell per crack face.
  PetscCall(SplitCracks(serial, &s->wave));
  PetscCall(DMDestroy(&serial));
  PetscCall(DistributeMesh(&s->wave, "wave_mesh", &s->wave_origin));
  PetscCall(PetscPrintf(comm, "Meshing: %.2f s\n", MPI_Wtime() - t0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
