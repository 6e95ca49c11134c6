// HDF5 fields of several grids at chosen outputs, indexed by XDMF for ParaView.
// Layout of the .h5 (every dataset has a string attribute `units`; every
// per-output dataset has the attribute `time` [s], or `frequency` [Hz] for modes):
//   /<grid>/geometry            vertices × dim (2 or 3) [m]
//   /<grid>/topology            cells × corners (global vertex numbers; no units)
//   /<grid>/<field>_<k>         vertices × components (node fields) or cells × 1
//                               (cell fields) at output k; vectors have 3
//                               components (z = 0) so ParaView sees vectors
// Grids: a mesh's bulk cells (AddMesh: triangles, quads; tetrahedra, hexahedra in
// VTK's corner order), its cohesive cells as their − faces on the mesh's vertices
// (AddCohesiveCells: segments in 2D, triangles or quads in 3D), or free cells
// with their own points (AddFreeCells: segments, quads). The .h5 is written as .partial and renamed; the .xmf files
// appear last, so a crash never leaves files that look complete.
#pragma once

#include <petscviewer.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/io/plex_grid.hpp"
#include "vibrotherm/io/xdmf_index.hpp"

namespace vibrotherm::io {

/// The .xmf files Finish writes next to <stem>.h5.
enum class XdmfLayout {
  kSeriesPerGrid,  ///< <stem>_<grid>.xmf per grid: its outputs as a temporal collection (fields.h5)
  kSingleSeries,   ///< <stem>.xmf: the outputs of the file's one grid (modes.h5)
  kStaticGrids,    ///< <stem>.xmf: every grid, no fields, as a spatial collection (mesh.h5)
};

class FieldFile {
 public:
  FieldFile() = default;
  FieldFile(const FieldFile&) = delete;
  FieldFile& operator=(const FieldFile&) = delete;
  ~FieldFile();
  /// `axis`: the attribute naming an output's position, "time" [s] or "frequency" [Hz].
  /// append: reopen the .partial an interrupted run left (checkpoint restart).
  PetscErrorCode Open(MPI_Comm comm, const std::string& h5_path, XdmfLayout layout, const std::string& axis = "time",
                      bool append = false);
  /// While on, grids and fields are only indexed for the .xmf, not written: a
  /// restart replays the outputs the interrupted run wrote before its checkpoint.
  void set_index_only(bool on) { index_only_ = on; }
  /// The bulk cells of dm as grid `name` (geometry and topology). Collective.
  PetscErrorCode AddMesh(const std::string& name, DM dm);
  /// The same for the DM of space, whose global vectors WriteField then takes.
  PetscErrorCode AddMesh(const std::string& name, const fe::LagrangeSpace& space);
  /// The cohesive cells of grid `mesh`'s DM as grid `name` of their − faces on its
  /// vertices (2-node lines in 2D); nothing when the DM has none.
  PetscErrorCode AddCohesiveCells(const std::string& name, const std::string& mesh);
  /// Grid `name` of this rank's cells with points of their own: `corners` points a cell
  /// (2: segments, 4: quadrilaterals in cyclic order), `dim` coordinates a point.
  PetscErrorCode AddFreeCells(const std::string& name, int corners, int dim, const std::vector<double>& points);
  bool has_grid(const std::string& name) const { return grids_.count(name) > 0; }

  /// Vertex values of a global vector of the grid's space at output k (time t).
  PetscErrorCode WriteField(const std::string& grid, const std::string& field, const char* units, Vec global, int k,
                            double t);
  /// A scalar vertex field given as (local point, value) pairs, `fill` elsewhere
  /// (pairs at points that are not vertices, e.g. degree-2 edge nodes, are skipped).
  PetscErrorCode WriteVertexValues(const std::string& grid, const std::string& field, const char* units,
                                   const std::vector<std::pair<PetscInt, double>>& values, double fill, int k,
                                   double t);
  /// A scalar cell field: one value per owned cell, in the order the grid was added.
  PetscErrorCode WriteCellValues(const std::string& grid, const std::string& field, const char* units,
                                 const std::vector<double>& values, int k, double t);
  /// Flushes everything written to disk: a run killed later leaves a file a restart can reopen. Collective.
  PetscErrorCode Flush();
  /// Closes the .h5 and writes the .xmf files. Collective.
  PetscErrorCode Finish();
  bool open() const { return viewer_ != nullptr; }

 private:
  struct Grid {
    DM dm = nullptr;                          ///< null for free segments
    const fe::LagrangeSpace* space = nullptr;
    IS numbering = nullptr;                   ///< vertex numbering of dm (not owned)
    std::string points;                       ///< the grid whose geometry this one uses
    XdmfGrid xdmf;
    PetscInt owned_vertices = 0, owned_cells = 0;
    std::map<int, std::vector<XdmfAttribute>> outputs;  ///< k → fields written
  };
  struct Dataset {
    std::string grid, field, units;
    int components = 1;
    bool cell = false;
  };
  PetscErrorCode AddGrid(const std::string& name, Grid grid, PetscInt corners, const std::vector<PetscInt>& cells);
  PetscErrorCode Write(const Dataset& d, const std::vector<PetscInt>& rows, const std::vector<double>& values,
                       int k, double t);
  PetscErrorCode WriteXdmf() const;
  /// Adds dataset `name` of output k (time t) to the .xmf index.
  PetscErrorCode Index(Grid& g, const Dataset& d, const std::string& name, int k, double t);

  MPI_Comm comm_ = MPI_COMM_NULL;
  std::string path_, axis_;
  XdmfLayout layout_ = XdmfLayout::kSeriesPerGrid;
  PetscViewer viewer_ = nullptr;
  std::map<std::string, Grid> grids_;
  std::vector<std::string> order_;  ///< grid names in the order added
  std::map<int, double> times_;
  bool index_only_ = false;
};

}  // namespace vibrotherm::io
