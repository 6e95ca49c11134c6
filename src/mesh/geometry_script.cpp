#include "vibrotherm/mesh/geometry_script.hpp"

#include <gmsh.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "gmsh_support.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::mesh {
namespace {

/// Throws naming `where` when gmsh has logged an error since the session began.
void RefuseGmshError(const std::string& where, const std::string& doing) {
  std::string error;
  gmsh::logger::getLastError(error);
  if (!error.empty()) throw std::invalid_argument(where + ": gmsh " + doing + ": " + error);
}

/// Rank 0: the script meshed and written (see MeshGeometryScript).
void MeshScriptOnRoot(const std::string& geo, const std::string& where, const std::string& msh) {
  if (!std::ifstream(geo)) throw std::invalid_argument(where + ": cannot open the file");
  gmsh_support::GmshSession session;
  try {
    gmsh::open(geo);
  } catch (...) {
    throw std::invalid_argument(where + ": gmsh cannot read it");
  }
  RefuseGmshError(where, "cannot read it");
  const int dimension = gmsh::model::getDimension();
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument(where + ": its geometry has no surface or volume to mesh");
  gmsh::model::mesh::generate(dimension);
  RefuseGmshError(where, "cannot mesh it");
  std::vector<std::size_t> nodes;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(nodes, coordinates, parametric);
  if (nodes.empty()) throw std::invalid_argument(where + ": gmsh made an empty mesh of it");
  gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
  // A crash never leaves a half mesh under the final name (gmsh takes the format from the extension).
  const std::string partial = std::filesystem::path(msh).replace_extension(".partial.msh").string();
  std::error_code ec;
  try {
    gmsh::write(partial);
    RefuseGmshError(where, "cannot write " + partial);
  } catch (...) {
    std::filesystem::remove(partial, ec);
    throw;
  }
  std::filesystem::rename(partial, msh, ec);
  if (ec) throw std::invalid_argument(where + ": cannot write its mesh " + msh + ": " + ec.message());
}

}  // namespace

bool IsGeometryScript(const std::string& path) {
  return std::filesystem::path(path).extension() == ".geo";
}

PetscErrorCode MeshGeometryScript(MPI_Comm comm, const std::string& geo, const std::string& option,
                                  const std::string& msh) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(RunOnRoot(comm, [&] { MeshScriptOnRoot(geo, option + " " + geo, msh); }));
  PetscCall(PetscPrintf(comm, "Meshing: %s %s meshed by gmsh into %s in %.2f s\n", option.c_str(), geo.c_str(),
                        msh.c_str(), MPI_Wtime() - t0));
  PetscFunctionReturn(0);
}

PetscErrorCode MeshGeometryScripts(MPI_Comm comm, const std::string& directory, MeshSource* source,
                                   std::vector<std::string>* written) {
  PetscFunctionBeginUser;
  if (source->from_file && IsGeometryScript(source->file)) {
    const std::string msh = directory + "/mesh_file.msh";
    written->push_back(msh);
    PetscCall(MeshGeometryScript(comm, source->file, "-mesh_file", msh));
    source->file = msh;
  }
  if (source->heat_from_file && IsGeometryScript(source->heat_file)) {
    const std::string msh = directory + "/heat_mesh_file.msh";
    written->push_back(msh);
    PetscCall(MeshGeometryScript(comm, source->heat_file, "-heat_mesh_file", msh));
    source->heat_file = msh;
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
