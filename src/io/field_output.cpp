#include "vibrotherm/io/field_output.hpp"

#include <petscdmplex.h>
#include <petscviewerhdf5.h>

#include <filesystem>

#include "vibrotherm/store/atomic_file.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

FieldFile::~FieldFile() { (void)PetscViewerDestroy(&viewer_); }

PetscErrorCode FieldFile::Open(MPI_Comm comm, const std::string& h5_path, XdmfLayout layout,
                               const std::string& axis, bool append) {
  PetscFunctionBeginUser;
  comm_ = comm;
  path_ = h5_path;
  layout_ = layout;
  axis_ = axis;
  const std::string partial = store::AtomicFile::partial_name(h5_path);
  PetscCheck(!append || std::filesystem::exists(partial), comm, PETSC_ERR_FILE_OPEN,
             "-restart: cannot resume '%s': missing", partial.c_str());
  const WritingFile writing(partial);  // PETSc's HDF5 errors do not name the file
  PetscCall(PetscViewerHDF5Open(comm, partial.c_str(), append ? FILE_MODE_APPEND : FILE_MODE_WRITE, &viewer_));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::AddMesh(const std::string& name, DM dm) {
  PetscFunctionBeginUser;
  PlexVertices vertices;
  PetscCall(OwnedVertices(dm, &vertices));
  std::vector<PetscInt> cells;
  PetscInt corners;
  PetscCall(OwnedBulkCells(dm, &cells, &corners));
  Grid g;
  g.dm = dm;
  g.numbering = vertices.numbering;
  g.points = name;
  g.owned_vertices = static_cast<PetscInt>(vertices.rows.size());
  g.xdmf.vertices = vertices.global;
  g.xdmf.dim = vertices.dim;
  PetscInt dim;
  PetscCall(DMGetDimension(dm, &dim));
  g.xdmf.topology_type = XdmfTopologyType(static_cast<int>(dim), corners);
  PetscCall(AddGrid(name, g, corners, cells));
  PetscCall(Write({name, "geometry", "m", vertices.dim, false}, vertices.rows, vertices.coordinates, -1, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::AddMesh(const std::string& name, const fe::LagrangeSpace& space) {
  PetscFunctionBeginUser;
  PetscCall(AddMesh(name, space.dm()));
  grids_.at(name).space = &space;
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::AddCohesiveCells(const std::string& name, const std::string& mesh) {
  PetscFunctionBeginUser;
  const Grid& m = grids_.at(mesh);
  std::vector<PetscInt> faces;
  PetscInt corners;
  PetscCall(OwnedCohesiveFaces(m.dm, &faces, &corners));
  PetscInt count = static_cast<PetscInt>(faces.size());
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &count, 1, MPIU_INT, MPI_SUM, comm_));
  if (count == 0) PetscFunctionReturn(0);  // an unsplit mesh
  Grid g;
  g.dm = m.dm;
  g.numbering = m.numbering;
  g.points = mesh;  // lines on the mesh's own vertices: no geometry of its own
  g.xdmf.vertices = m.xdmf.vertices;
  g.xdmf.dim = m.xdmf.dim;
  g.xdmf.topology_type = XdmfTopologyType(m.xdmf.dim - 1, corners);
  PetscCall(AddGrid(name, g, corners, faces));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::AddFreeCells(const std::string& name, int corners, int dim,
                                       const std::vector<double>& coordinates) {
  PetscFunctionBeginUser;
  const PetscInt points = static_cast<PetscInt>(coordinates.size() / dim);
  PetscInt first = 0;
  PetscCallMPI(MPI_Exscan(&points, &first, 1, MPIU_INT, MPI_SUM, comm_));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank == 0) first = 0;  // MPI_Exscan leaves rank 0's result undefined
  std::vector<PetscInt> rows(points);
  for (PetscInt i = 0; i < points; ++i) rows[i] = first + i;
  Grid g;
  g.points = name;
  g.owned_vertices = points;
  PetscCallMPI(MPI_Allreduce(&points, &g.xdmf.vertices, 1, MPIU_INT, MPI_SUM, comm_));
  g.xdmf.dim = dim;
  g.xdmf.topology_type = XdmfTopologyType(corners == 2 ? 1 : 2, corners);  // lines or polygons
  PetscCall(AddGrid(name, g, corners, rows));  // cell i joins points corners·i, ..., corners·i + corners − 1
  PetscCall(Write({name, "geometry", "m", dim, false}, rows, coordinates, -1, 0.0));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::AddGrid(const std::string& name, Grid g, PetscInt corners,
                                  const std::vector<PetscInt>& cells) {
  PetscFunctionBeginUser;
  PetscCheck(!has_grid(name), comm_, PETSC_ERR_ARG_WRONG, "%s: grid %s added twice", path_.c_str(), name.c_str());
  g.owned_cells = corners > 0 ? static_cast<PetscInt>(cells.size()) / corners : 0;
  PetscCallMPI(MPI_Allreduce(&g.owned_cells, &g.xdmf.cells, 1, MPIU_INT, MPI_SUM, comm_));
  const std::string h5 = std::filesystem::path(path_).filename().string();
  g.xdmf.name = name;
  g.xdmf.corners = corners;
  g.xdmf.topology = h5 + ":/" + name + "/topology";
  g.xdmf.geometry = h5 + ":/" + g.points + "/geometry";
  grids_[name] = g;
  order_.push_back(name);

  if (index_only_) PetscFunctionReturn(0);
  const WritingFile writing(store::AtomicFile::partial_name(path_));
  PetscCall(PetscViewerHDF5PushGroup(viewer_, ("/" + name).c_str()));
  IS topology;
  PetscCall(ISCreateGeneral(comm_, static_cast<PetscInt>(cells.size()), cells.data(), PETSC_COPY_VALUES, &topology));
  PetscCall(ISSetBlockSize(topology, corners));
  PetscCall(PetscObjectSetName((PetscObject)topology, "topology"));
  PetscCall(ISView(topology, viewer_));
  PetscCall(ISDestroy(&topology));
  PetscCall(PetscViewerHDF5PopGroup(viewer_));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::Write(const Dataset& d, const std::vector<PetscInt>& rows, const std::vector<double>& values,
                                int k, double t) {
  PetscFunctionBeginUser;
  Grid& g = grids_.at(d.grid);
  const int nc = d.components;
  const std::string name = k < 0 ? d.field : d.field + "_" + std::to_string(k);
  if (index_only_) {
    if (k >= 0) PetscCall(Index(g, d, name, k, t));
    PetscFunctionReturn(0);
  }
  const PetscInt owned = d.cell ? g.owned_cells : g.owned_vertices;
  const PetscInt global = d.cell ? g.xdmf.cells : g.xdmf.vertices;
  Vec out;
  PetscCall(VecCreateMPI(comm_, owned * nc, global * nc, &out));
  PetscCall(VecSetBlockSize(out, nc));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int c = 0; c < nc; ++c) PetscCall(VecSetValue(out, rows[i] * nc + c, values[nc * i + c], INSERT_VALUES));
  PetscCall(VecAssemblyBegin(out));
  PetscCall(VecAssemblyEnd(out));
  PetscCall(PetscObjectSetName((PetscObject)out, name.c_str()));
  const WritingFile writing(store::AtomicFile::partial_name(path_));
  PetscCall(PetscViewerHDF5PushGroup(viewer_, ("/" + d.grid).c_str()));
  PetscCall(PetscViewerHDF5SetBaseDimension2(viewer_, PETSC_TRUE));  // scalars as N × 1
  PetscCall(VecView(out, viewer_));
  PetscCall(PetscViewerHDF5WriteObjectAttribute(viewer_, (PetscObject)out, "units", PETSC_STRING, d.units.c_str()));
  if (k >= 0) PetscCall(PetscViewerHDF5WriteObjectAttribute(viewer_, (PetscObject)out, axis_.c_str(), PETSC_DOUBLE, &t));
  PetscCall(PetscViewerHDF5PopGroup(viewer_));
  PetscCall(VecDestroy(&out));
  if (k >= 0) PetscCall(Index(g, d, name, k, t));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::Index(Grid& g, const Dataset& d, const std::string& name, int k, double t) {
  PetscFunctionBeginUser;
  const std::string h5 = std::filesystem::path(path_).filename().string();
  g.outputs[k].push_back({d.field, d.components, d.cell, h5 + ":/" + d.grid + "/" + name});
  times_[k] = t;
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::Flush() {
  PetscFunctionBeginUser;
  if (!viewer_) PetscFunctionReturn(0);
  const WritingFile writing(store::AtomicFile::partial_name(path_));
  hid_t file;
  PetscCall(PetscViewerHDF5GetFileId(viewer_, &file));
  PetscCheck(H5Fflush(file, H5F_SCOPE_GLOBAL) >= 0, comm_, PETSC_ERR_FILE_WRITE, "%s: cannot flush the file",
             path_.c_str());
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::WriteField(const std::string& grid, const std::string& field, const char* units, Vec global,
                                     int k, double t) {
  PetscFunctionBeginUser;
  const Grid& g = grids_.at(grid);
  PetscCheck(g.space, comm_, PETSC_ERR_ARG_WRONG, "grid %s has no space", grid.c_str());
  DM dm = g.space->dm();
  const int nc = static_cast<int>(g.space->components());
  const int written = nc == 1 ? 1 : 3;  // 2D vectors padded with z = 0: ParaView needs 3 components
  Vec local;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGlobalToLocal(dm, global, INSERT_VALUES, local));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd));
  const PetscInt* number;
  const PetscScalar* a;
  PetscCall(ISGetIndices(g.numbering, &number));
  PetscCall(VecGetArrayRead(local, &a));
  std::vector<PetscInt> rows;
  std::vector<double> values;
  for (PetscInt v = vStart; v < vEnd; ++v) {
    if (number[v - vStart] < 0) continue;
    PetscInt dof, off;
    PetscCall(PetscSectionGetDof(section, v, &dof));
    PetscCall(PetscSectionGetOffset(section, v, &off));
    rows.push_back(number[v - vStart]);
    for (int c = 0; c < written; ++c) values.push_back(c < nc && dof >= nc ? PetscRealPart(a[off + c]) : 0.0);
  }
  PetscCall(VecRestoreArrayRead(local, &a));
  PetscCall(ISRestoreIndices(g.numbering, &number));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscCall(Write({grid, field, units, written, false}, rows, values, k, t));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::WriteVertexValues(const std::string& grid, const std::string& field, const char* units,
                                            const std::vector<std::pair<PetscInt, double>>& pairs, double fill, int k,
                                            double t) {
  PetscFunctionBeginUser;
  const Grid& g = grids_.at(grid);
  PetscInt vStart, vEnd;
  PetscCall(DMPlexGetDepthStratum(g.dm, 0, &vStart, &vEnd));
  std::vector<double> by_vertex(vEnd - vStart, fill);
  // The file holds vertex fields: values at other points (degree-2 edge nodes) are not written.
  for (const auto& [v, value] : pairs)
    if (v >= vStart && v < vEnd) by_vertex[v - vStart] = value;
  const PetscInt* number;
  PetscCall(ISGetIndices(g.numbering, &number));
  std::vector<PetscInt> rows;
  std::vector<double> values;
  for (PetscInt v = vStart; v < vEnd; ++v)
    if (number[v - vStart] >= 0) {
      rows.push_back(number[v - vStart]);
      values.push_back(by_vertex[v - vStart]);
    }
  PetscCall(ISRestoreIndices(g.numbering, &number));
  PetscCall(Write({grid, field, units, 1, false}, rows, values, k, t));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::WriteCellValues(const std::string& grid, const std::string& field, const char* units,
                                          const std::vector<double>& values, int k, double t) {
  PetscFunctionBeginUser;
  const Grid& g = grids_.at(grid);
  const PetscInt n = static_cast<PetscInt>(values.size());
  PetscCheck(n == g.owned_cells, comm_, PETSC_ERR_ARG_SIZ, "%s: %" PetscInt_FMT " values for %" PetscInt_FMT " cells",
             field.c_str(), n, g.owned_cells);
  PetscInt first = 0;
  PetscCallMPI(MPI_Exscan(&n, &first, 1, MPIU_INT, MPI_SUM, comm_));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank == 0) first = 0;
  std::vector<PetscInt> rows(n);
  for (PetscInt i = 0; i < n; ++i) rows[i] = first + i;
  PetscCall(Write({grid, field, units, 1, true}, rows, values, k, t));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::Finish() {
  PetscFunctionBeginUser;
  if (!viewer_) PetscFunctionReturn(0);
  {
    const WritingFile writing(store::AtomicFile::partial_name(path_));  // closing flushes what HDF5 holds
    PetscCall(PetscViewerDestroy(&viewer_));
  }
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank != 0) PetscFunctionReturn(0);
  VibrothermCallIo(PETSC_COMM_SELF, store::AtomicFile::publish(path_));
  PetscCall(WriteXdmf());
  PetscFunctionReturn(0);
}

PetscErrorCode FieldFile::WriteXdmf() const {
  PetscFunctionBeginUser;
  const std::filesystem::path h5(path_);
  const std::string stem = (h5.parent_path() / h5.stem()).string();
  auto series = [&](const Grid& g, const std::string& xmf_path) {
    std::vector<XdmfStep> steps;
    for (const auto& [k, attributes] : g.outputs) steps.push_back({times_.at(k), attributes});
    store::AtomicFile xmf(xmf_path);
    WriteXdmfSeries(xmf.stream(), g.xdmf, steps);
    xmf.commit();
  };
  if (layout_ == XdmfLayout::kStaticGrids) {
    std::vector<XdmfGrid> grids;
    for (const std::string& name : order_) grids.push_back(grids_.at(name).xdmf);
    VibrothermCallCpp(PETSC_COMM_SELF, {
      store::AtomicFile xmf(stem + ".xmf");
      WriteXdmfCollection(xmf.stream(), h5.stem().string(), grids);
      xmf.commit();
    });
  } else if (layout_ == XdmfLayout::kSingleSeries) {
    PetscCheck(order_.size() == 1, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: one grid expected", path_.c_str());
    VibrothermCallCpp(PETSC_COMM_SELF, series(grids_.at(order_[0]), stem + ".xmf"));
  } else {
    for (const std::string& name : order_)
      if (!grids_.at(name).outputs.empty()) VibrothermCallCpp(PETSC_COMM_SELF, series(grids_.at(name), stem + "_" + name + ".xmf"));
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
