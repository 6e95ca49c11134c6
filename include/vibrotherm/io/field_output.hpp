// fields.h5 + fields.xmf: vertex fields of several meshes at chosen times, for
// ParaView (XDMF temporal collections, one per mesh). Layout of fields.h5:
//   /<mesh>/geometry            vertices × 2
//   /<mesh>/topology            bulk cells × corners (global vertex numbers)
//   /<mesh>/<field>_<k>         vertices × components, output number k
// Meshes here: "heat" (unsplit: temperature) and "wave" (split: displacement,
// velocity, contact_state). The .h5 is written as .partial and renamed, and the
// .xmf appears last, so a crash never leaves files that look complete.
#pragma once

#include <petscviewer.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::io {

class FieldFile {
 public:
  ~FieldFile();
  PetscErrorCode Open(MPI_Comm comm, const std::string& h5_path);
  /// Writes the geometry and topology of space's DM under /name. Collective.
  PetscErrorCode AddMesh(const std::string& name, const fe::LagrangeSpace& space);
  /// Writes the vertex values of a global vector of the mesh's space at output k (time t).
  PetscErrorCode WriteField(const std::string& mesh, const std::string& field, Vec global, int k, double t);
  /// Writes a scalar vertex field given as (local point, value) pairs, `fill` elsewhere
  /// (pairs at points that are not vertices, e.g. degree-2 edge nodes, are skipped).
  PetscErrorCode WriteVertexValues(const std::string& mesh, const std::string& field,
                                   const std::vector<std::pair<PetscInt, double>>& values, double fill, int k,
                                   double t);
  /// Closes fields.h5 and writes fields.xmf. Collective.
  PetscErrorCode Finish();
  bool open() const { return viewer_ != nullptr; }

 private:
  struct Mesh {
    const fe::LagrangeSpace* space = nullptr;
    IS numbering = nullptr;  ///< DMPlexGetVertexNumbering (not owned)
    PetscInt vertices = 0, cells = 0, corners = 0, owned = 0;
    std::map<int, std::vector<std::pair<std::string, int>>> fields;  ///< k → (field, components)
  };
  PetscErrorCode Write(const std::string& mesh, const std::string& field, int components,
                       const std::vector<PetscInt>& rows, const std::vector<double>& values, int k, double t);

  MPI_Comm comm_ = MPI_COMM_NULL;
  std::string path_;
  PetscViewer viewer_ = nullptr;
  std::map<std::string, Mesh> meshes_;
  std::map<int, double> times_;
};

}  // namespace vibrotherm::io
