#include "vibrotherm/io/mesh_output.hpp"

#include <petscdmplex.h>
#include <petscviewerhdf5.h>

#include <filesystem>

#include "vibrotherm/io/atomic_file.hpp"
#include "vibrotherm/mesh/plex_access.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {
namespace {

struct MeshCounts {
  PetscInt vertices = 0, bulk = 0, cohesive = 0, corners = 0;
};

PetscErrorCode Count(DM dm, MeshCounts* n) {
  PetscFunctionBeginUser;
  std::vector<bool> ghost;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscInt chart0, vStart, vEnd, cStart, cEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  PetscCall(DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd));
  PetscInt local[4] = {0, 0, 0, 0};
  for (PetscInt v = vStart; v < vEnd; ++v) local[0] += !ghost[v - chart0];
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    PetscCall(mesh::IsCohesiveCell(dm, c, &cohesive));
    if (ghost[c - chart0]) continue;
    if (cohesive) ++local[2];
    else {
      ++local[1];
      PetscCall(DMPlexGetConeSize(dm, c, &local[3]));
    }
  }
  PetscInt global[4];
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscCallMPI(MPI_Allreduce(local, global, 3, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&local[3], &global[3], 1, MPIU_INT, MPI_MAX, comm));
  *n = {global[0], global[1], global[2], global[3]};
  PetscFunctionReturn(0);
}

void WriteGrid(std::ostream& out, const char* name, const std::string& h5, const char* dataset, PetscInt cells,
               PetscInt corners, PetscInt vertices) {
  const char* topology = corners == 3 ? "Triangle" : "Quadrilateral";
  out << "    <Grid Name=\"" << name << "\" GridType=\"Uniform\">\n"
      << "      <Topology TopologyType=\"" << topology << "\" NumberOfElements=\"" << cells << "\">\n"
      << "        <DataItem Format=\"HDF\" DataType=\"Int\" Dimensions=\"" << cells << " " << corners << "\">" << h5
      << ":" << dataset << "</DataItem>\n"
      << "      </Topology>\n"
      << "      <Geometry GeometryType=\"XY\">\n"
      << "        <DataItem Format=\"HDF\" DataType=\"Float\" Precision=\"8\" Dimensions=\"" << vertices
      << " 2\">" << h5 << ":/geometry/vertices</DataItem>\n"
      << "      </Geometry>\n"
      << "    </Grid>\n";
}

}  // namespace

PetscErrorCode WriteMesh(DM dm, const std::string& h5_path) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  MeshCounts n;
  PetscCall(Count(dm, &n));
  PetscViewer viewer;
  const std::string partial = AtomicFile::partial_name(h5_path);
  PetscCall(PetscViewerHDF5Open(comm, partial.c_str(), FILE_MODE_WRITE, &viewer));
  PetscCall(PetscViewerPushFormat(viewer, PETSC_VIEWER_HDF5_XDMF));
  PetscCall(DMView(dm, viewer));
  PetscCall(PetscViewerPopFormat(viewer));
  PetscCall(PetscViewerDestroy(&viewer));

  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  const std::string h5_name = std::filesystem::path(h5_path).filename().string();
  const std::string xmf_path = std::filesystem::path(h5_path).replace_extension(".xmf").string();
  VibrothermCallCpp(PETSC_COMM_SELF, {
    AtomicFile::publish(h5_path);
    AtomicFile xmf(xmf_path);
    std::ostream& out = xmf.stream();
    out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n  <Domain>\n";
    WriteGrid(out, "specimen", h5_name, "/viz/topology/cells", n.bulk, n.corners, n.vertices);
    if (n.cohesive > 0) WriteGrid(out, "cracks", h5_name, "/viz/topology_1/cells", n.cohesive, 4, n.vertices);
    out << "  </Domain>\n</Xdmf>\n";
    xmf.commit();
  });
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
