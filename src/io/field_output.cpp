#include "vibrotherm/io/field_output.hpp"

#include <petscdmplex.h>
#include <petscviewerhdf5.h>

#include <filesystem>

#include "vibrotherm/io/atomic_file.hpp"
#include "vibrotherm/mesh/plex_access.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

FieldFile::~FieldFile() { (void)PetscViewerDestroy(&viewer_); }

PetscErrorCode FieldFile::Open(MPI_Comm comm, const std::string& h5_path) {
  PetscFunctionBeginUser;
  comm_ = comm;
  path_ = h5_path;
  PetscCall(PetscViewerHDF5Open(comm, AtomicFile::partial_name(h5_path).c_str(), FILE_MODE_WRITE, &viewer_));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::AddMesh(const std::string& name, const fe::LagrangeSpace& space) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  Mesh m;
  m.space = &space;
  PetscCall(DMPlexGetVertexNumbering(dm, &m.numbering));
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  const PetscInt* number;
  PetscCall(ISGetIndices(m.numbering, &number));
  std::vector<PetscInt> rows;
  std::vector<double> xy;
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm));
  for (PetscInt v = vStart; v < vEnd; ++v) {
    if (number[v - vStart] < 0) continue;  // owned by another rank
    rows.push_back(number[v - vStart]);
    const auto p = x(v);
    xy.insert(xy.end(), {p[0], p[1]});
  }
  m.owned = static_cast<PetscInt>(rows.size());
  PetscCallMPI(MPI_Allreduce(&m.owned, &m.vertices, 1, MPIU_INT, MPI_SUM, comm_));
  // Topology: owned bulk cells, vertices in closure order, as global numbers.
  std::vector<bool> ghost;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscInt chart0;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  std::vector<PetscInt> cells;
  PetscInt corners = 0;
  for (PetscInt c : space.cells()) {
    if (ghost[c - chart0]) continue;
    PetscInt n, *closure = nullptr, k = 0;
    PetscCall(DMPlexGetTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
    for (PetscInt i = 0; i < n; ++i) {
      const PetscInt p = closure[2 * i];
      if (p < vStart || p >= vEnd) continue;
      const PetscInt g = number[p - vStart];
      cells.push_back(g >= 0 ? g : -(g + 1));
      ++k;
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, c, PETSC_TRUE, &n, &closure));
    corners = k;
  }
  PetscCall(ISRestoreIndices(m.numbering, &number));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &corners, 1, MPIU_INT, MPI_MAX, comm_));
  m.corners = corners;
  const PetscInt local_cells = corners > 0 ? static_cast<PetscInt>(cells.size()) / corners : 0;
  PetscCallMPI(MPI_Allreduce(&local_cells, &m.cells, 1, MPIU_INT, MPI_SUM, comm_));
  meshes_[name] = m;

  PetscCall(PetscViewerHDF5PushGroup(viewer_, ("/" + name).c_str()));
  IS topology;
  PetscCall(ISCreateGeneral(comm_, static_cast<PetscInt>(cells.size()), cells.data(), PETSC_COPY_VALUES, &topology));
  PetscCall(ISSetBlockSize(topology, corners));
  PetscCall(PetscObjectSetName((PetscObject)topology, "topology"));
  PetscCall(ISView(topology, viewer_));
  PetscCall(ISDestroy(&topology));
  PetscCall(PetscViewerHDF5PopGroup(viewer_));
  PetscCall(Write(name, "geometry", 2, rows, xy, -1, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::Write(const std::string& mesh, const std::string& field, int components,
                                const std::vector<PetscInt>& rows, const std::vector<double>& values, int k,
                                double t) {
  PetscFunctionBeginUser;
  Mesh& m = meshes_.at(mesh);
  Vec out;
  PetscCall(VecCreateMPI(comm_, m.owned * components, m.vertices * components, &out));
  PetscCall(VecSetBlockSize(out, components));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int c = 0; c < components; ++c)
      PetscCall(VecSetValue(out, rows[i] * components + c, values[components * i + c], INSERT_VALUES));
  PetscCall(VecAssemblyBegin(out));
  PetscCall(VecAssemblyEnd(out));
  const std::string name = k < 0 ? field : field + "_" + std::to_string(k);
  PetscCall(PetscObjectSetName((PetscObject)out, name.c_str()));
  PetscCall(PetscViewerHDF5PushGroup(viewer_, ("/" + mesh).c_str()));
  PetscCall(PetscViewerHDF5SetBaseDimension2(viewer_, PETSC_TRUE));  // scalars as N × 1
  PetscCall(VecView(out, viewer_));
  PetscCall(PetscViewerHDF5PopGroup(viewer_));
  PetscCall(VecDestroy(&out));
  if (k >= 0) {
    m.fields[k].push_back({field, components});
    times_[k] = t;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::WriteField(const std::string& mesh, const std::string& field, Vec global, int k, double t) {
  PetscFunctionBeginUser;
  const Mesh& m = meshes_.at(mesh);
  DM dm = m.space->dm();
  const int nc = static_cast<int>(m.space->components());
  Vec local;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGlobalToLocal(dm, global, INSERT_VALUES, local));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  const PetscInt* number;
  const PetscScalar* a;
  PetscCall(ISGetIndices(m.numbering, &number));
  PetscCall(VecGetArrayRead(local, &a));
  std::vector<PetscInt> rows;
  std::vector<double> values;
  for (PetscInt v = vStart; v < vEnd; ++v) {
    if (number[v - vStart] < 0) continue;
    PetscInt dof, off;
    PetscCall(PetscSectionGetDof(section, v, &dof));
    PetscCall(PetscSectionGetOffset(section, v, &off));
    rows.push_back(number[v - vStart]);
    for (int c = 0; c < nc; ++c) values.push_back(dof >= nc ? PetscRealPart(a[off + c]) : 0.0);
  }
  PetscCall(VecRestoreArrayRead(local, &a));
  PetscCall(ISRestoreIndices(m.numbering, &number));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscCall(Write(mesh, field, nc, rows, values, k, t));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::WriteVertexValues(const std::string& mesh, const std::string& field,
                                            const std::vector<std::pair<PetscInt, double>>& pairs, double fill, int k,
                                            double t) {
  PetscFunctionBeginUser;
  const Mesh& m = meshes_.at(mesh);
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(m.space->dm(), 0, &vStart, &vEnd));
  std::vector<double> by_vertex(vEnd - vStart, fill);
  // The file holds vertex fields: values at other points (degree-2 edge nodes) are not written.
  for (const auto& [v, value] : pairs)
    if (v >= vStart && v < vEnd) by_vertex[v - vStart] = value;
  const PetscInt* number;
  PetscCall(ISGetIndices(m.numbering, &number));
  std::vector<PetscInt> rows;
  std::vector<double> values;
  for (PetscInt v = vStart; v < vEnd; ++v)
    if (number[v - vStart] >= 0) {
      rows.push_back(number[v - vStart]);
      values.push_back(by_vertex[v - vStart]);
    }
  PetscCall(ISRestoreIndices(m.numbering, &number));
  PetscCall(Write(mesh, field, 1, rows, values, k, t));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::Finish() {
  PetscFunctionBeginUser;
  if (!viewer_) PetscFunctionReturn(0);
  PetscCall(PetscViewerDestroy(&viewer_));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  const std::string h5 = std::filesystem::path(path_).filename().string();
  VibrothermCallCpp(PETSC_COMM_SELF, {
    AtomicFile::publish(path_);
    AtomicFile xmf(std::filesystem::path(path_).replace_extension(".xmf").string());
    std::ostream& out = xmf.stream();
    out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"2.0\">\n  <Domain>\n";
    for (const auto& [name, m] : meshes_) {
      const char* topology = m.corners == 3 ? "Triangle" : "Quadrilateral";
      out << "    <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      for (const auto& [k, fields] : m.fields) {
        out << "      <Grid Name=\"" << name << "_" << k << "\" GridType=\"Uniform\">\n"
            << "        <Time Value=\"" << times_.at(k) << "\"/>\n"
            << "        <Topology TopologyType=\"" << topology << "\" NumberOfElements=\"" << m.cells << "\">\n"
            << "          <DataItem Format=\"HDF\" DataType=\"Int\" Dimensions=\"" << m.cells << " " << m.corners
            << "\">" << h5 << ":/" << name << "/topology</DataItem>\n"
            << "        </Topology>\n"
            << "        <Geometry GeometryType=\"XY\">\n"
            << "          <DataItem Format=\"HDF\" DataType=\"Float\" Precision=\"8\" Dimensions=\"" << m.vertices
            << " 2\">" << h5 << ":/" << name << "/geometry</DataItem>\n"
            << "        </Geometry>\n";
        for (const auto& [field, nc] : fields)
          out << "        <Attribute Name=\"" << field << "\" AttributeType=\"" << (nc == 1 ? "Scalar" : "Vector")
              << "\" Center=\"Node\">\n"
              << "          <DataItem Format=\"HDF\" DataType=\"Float\" Precision=\"8\" Dimensions=\"" << m.vertices
              << " " << nc << "\">" << h5 << ":/" << name << "/" << field << "_" << k << "</DataItem>\n"
              << "        </Attribute>\n";
        out << "      </Grid>\n";
      }
      out << "    </Grid>\n";
    }
    out << "  </Domain>\n</Xdmf>\n";
    xmf.commit();
  });
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
