#include "vibrotherm/mesh/geometry_script.hpp"

#include <gmsh.h>

#include <cctype>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "gmsh_support.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::mesh {
namespace {

/// Throws naming `where` when gmsh logged an error in its last step (open, meshing and
/// writing each clear the last error first).
void RefuseGmshError(const std::string& where, const std::string& doing) {
  std::string error;
  gmsh::logger::getLastError(error);
  if (!error.empty()) throw std::invalid_argument(where + ": gmsh " + doing + ": " + error);
}

/// gmsh writes only the physical groups' elements when a script defines any: then one of the
/// model's own dimension must exist, or the mesh written would lack its cells.
void RefuseMissingCellGroup(const std::string& where, int dimension) {
  gmsh_support::DimTags all, cells;
  gmsh::model::getPhysicalGroups(all);
  gmsh::model::getPhysicalGroups(cells, dimension);
  if (!all.empty() && cells.empty())
    throw std::invalid_argument(where + ": it names physical groups but none of dimension " + std::to_string(dimension) +
                                " (a Physical " + (dimension == 3 ? "Volume" : "Surface") + " for the body's cells)");
}

/// Writes the current mesh to msh whole: first under a partial name (gmsh takes the format
/// from the extension), renamed once complete, so a crash never leaves a half mesh as msh.
void WriteWhole(const std::string& where, const std::string& msh) {
  const std::string partial = std::filesystem::path(msh).replace_extension(".partial.msh").string();
  gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
  std::error_code ec;
  try {
    gmsh::write(partial);
    RefuseGmshError(where, "cannot write " + partial);
    std::filesystem::rename(partial, msh, ec);
    if (ec) throw std::invalid_argument(where + ": cannot write its mesh " + msh + ": " + ec.message());
  } catch (...) {
    std::filesystem::remove(partial, ec);
    throw;
  }
}

/// Rank 0: the script meshed and written (MeshGeometryScript, below).
void MeshScriptOnRoot(const std::string& geo, const std::string& where, const std::string& msh) {
  gmsh_support::GmshSession session;
  gmsh_support::OpenFile(geo, where);
  RefuseGmshError(where, "cannot read it");
  gmsh::option::setNumber("General.NumThreads", 1);  // again: a script may have raised it (see GmshSession)
  // gmsh meshes surfaces inside an OpenMP region (even on one thread): an error thrown there
  // aborts the process, so while meshing gmsh only logs its errors (RefuseGmshError reads them).
  gmsh::option::setNumber("General.AbortOnError", 0);
  const int dimension = gmsh::model::getDimension();
  if (dimension != 2 && dimension != 3)
    throw std::invalid_argument(where + ": its geometry has no surface or volume to mesh");
  RefuseMissingCellGroup(where, dimension);
  try {
    gmsh::model::mesh::generate(dimension);
  } catch (const std::string& error) {
    throw std::invalid_argument(where + ": gmsh cannot mesh it: " + error);
  }
  RefuseGmshError(where, "cannot mesh it");
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, dimension);
  if (types.empty()) throw std::invalid_argument(where + ": gmsh made no cells of it");
  WriteWhole(where, msh);
}

/// Meshes the script `geo` into the .msh file `msh` (written whole as <stem>.partial.msh, then renamed;
/// MSH 2.2). A script gmsh cannot read or mesh (gmsh's message quoted), one with physical groups
/// but none for its cells, or one whose mesh has no cells is refused naming `option` and the
/// file. Rank 0's work; collective.
PetscErrorCode MeshGeometryScript(MPI_Comm comm, const std::string& geo, const std::string& option,
                                  const std::string& msh) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(RunOnRoot(comm, [&] { MeshScriptOnRoot(geo, option + " " + geo, msh); }));
  PetscCall(PetscPrintf(comm, "Meshing: %s %s meshed by gmsh into %s in %.2f s\n", option.c_str(), geo.c_str(),
                        msh.c_str(), MPI_Wtime() - t0));
  PetscFunctionReturn(0);
}

}  // namespace

bool IsGeometryScript(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".geo";
}

PetscErrorCode MeshGeometryScripts(MPI_Comm comm, const std::string& directory, MeshSource* source,
                                   std::vector<std::string>* written) {
  PetscFunctionBeginUser;
  // Each script's mesh under the script's own name (the heat's with .heat), so that messages about
  // it name the script: dir/plate.msh for plate.geo.
  const auto mesh_script = [&](const char* option, const char* suffix, std::string* file) -> PetscErrorCode {
    PetscFunctionBeginUser;
    const std::string msh = directory + "/" + std::filesystem::path(*file).stem().string() + suffix;
    written->push_back(msh);
    PetscCall(MeshGeometryScript(comm, *file, option, msh));
    *file = msh;
    PetscFunctionReturn(0);
  };
  if (source->from_file && IsGeometryScript(source->file)) PetscCall(mesh_script("-mesh_file", ".msh", &source->file));
  if (source->heat_from_file && IsGeometryScript(source->heat_file))
    PetscCall(mesh_script("-heat_mesh_file", ".heat.msh", &source->heat_file));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
