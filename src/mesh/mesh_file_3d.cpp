#include "vibrotherm/mesh/mesh_file_3d.hpp"

#include <gmsh.h>
#include <petscdmplex.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <vector>

#include "gmsh_support.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::mesh {
namespace {

/// A 3D file's physical surfaces: tag → name, checked (hexahedra only, known names).
std::map<PetscInt, std::string> SurfaceNames(const std::string& path, const std::string& option) {
  const std::string where = option + " " + path;
  gmsh_support::GmshSession session;
  gmsh_support::OpenFile(path, where);
  if (gmsh::model::getDimension() != 3) throw std::invalid_argument(where + ": not a 3D mesh");
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3);
  for (int type : types)
    if (type != 5) {
      std::string name;
      int dim, order, nodes, primary;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(type, name, dim, order, nodes, local, primary);
      throw std::invalid_argument(where + ": a 3D mesh file must be of 8-node hexahedra (Q2 waves need a lumped-mass "
                                  "hexahedron), found " + name);
    }
  if (types.empty()) throw std::invalid_argument(where + ": no volume elements");
  gmsh_support::DimTags groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  std::map<PetscInt, std::string> names;
  bool any_kind = false;
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    bool known = name.rfind("crack", 0) == 0 || name == "sink";
    for (EdgeKind kind : all_edge_kinds())
      if (name == to_string(kind)) known = any_kind = true;
    if (!known)
      throw std::invalid_argument(where + ": unknown physical surface '" + name + "' (known: " + edge_kind_names() +
                                  ", sink, crack*)");
    names[tag] = name;
  }
  if (!any_kind)
    throw std::invalid_argument(where + ": no boundary physical surface (need at least one of " + edge_kind_names() +
                                ")");
  return names;
}

/// The side of an outer face from its centroid on the bounding box (−1: on none).
PetscInt SideOf(const PetscReal* c, const PetscReal* lo, const PetscReal* hi) {
  const double tol = 1e-9 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const auto at = [tol](double v, double target) { return std::abs(v - target) <= tol; };
  if (at(c[1], lo[1])) return static_cast<PetscInt>(Side::Bottom);
  if (at(c[0], hi[0])) return static_cast<PetscInt>(Side::Right);
  if (at(c[1], hi[1])) return static_cast<PetscInt>(Side::Top);
  if (at(c[0], lo[0])) return static_cast<PetscInt>(Side::Left);
  if (at(c[2], hi[2])) return static_cast<PetscInt>(Side::Front);
  return at(c[2], lo[2]) ? static_cast<PetscInt>(Side::Back) : -1;
}

/// The crack names in crack-number order (crack1, crack2, ...: sorted by their number).
std::vector<std::string> CrackNames(const std::map<PetscInt, std::string>& names) {
  std::vector<std::string> cracks;
  for (const auto& [tag, name] : names)
    if (name.rfind("crack", 0) == 0 && std::find(cracks.begin(), cracks.end(), name) == cracks.end())
      cracks.push_back(name);
  std::sort(cracks.begin(), cracks.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  return cracks;
}

/// The labels of labels.hpp and the kinds from PETSc's "Face Sets" (physical tags).
PetscErrorCode LabelFileFaces(DM dm, const std::map<PetscInt, std::string>& names, const std::string& where) {
  PetscFunctionBeginUser;
  for (const char* name : {labels::crack, labels::crack_face, labels::crack_tip, labels::side, labels::sink})
    PetscCall(DMCreateLabel(dm, name));
  for (EdgeKind kind : all_edge_kinds()) PetscCall(DMCreateLabel(dm, to_string(kind)));
  const std::vector<std::string> cracks = CrackNames(names);
  const bool sink_named = std::any_of(names.begin(), names.end(), [](const auto& n) { return n.second == "sink"; });
  PetscReal lo[3], hi[3];
  PetscCall(DMGetBoundingBox(dm, lo, hi));
  DMLabel sets;
  PetscCall(DMGetLabel(dm, "Face Sets", &sets));
  PetscInt fStart, fEnd, ids = 0;
  PetscCall(FacetRange(dm, &fStart, &fEnd));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    std::vector<std::string> in;  // every physical surface holding f (a face may be in several)
    for (const auto& [tag, name] : names) {
      PetscBool has = PETSC_FALSE;
      if (sets) PetscCall(DMLabelStratumHasPoint(sets, tag, f, &has));
      if (has) in.push_back(name);
    }
    const auto named = [&in](const std::string& name) { return std::find(in.begin(), in.end(), name) != in.end(); };
    PetscInt cells;
    PetscCall(DMPlexGetSupportSize(dm, f, &cells));
    const auto crack = std::find_if(cracks.begin(), cracks.end(), named);
    if (crack != cracks.end()) {
      PetscCheck(cells == 2, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT, "%s: %s has a face on the outer boundary (a "
                 "crack's faces are interior faces)", where.c_str(), crack->c_str());
      PetscCall(DMSetLabelValue(dm, labels::crack, f, static_cast<PetscInt>(crack - cracks.begin()) + 1));
      PetscCall(DMSetLabelValue(dm, labels::crack_face, f, ids++));
      continue;
    }
    if (cells != 1) continue;
    PetscReal area, c[3], n[3];
    PetscCall(DMPlexComputeCellGeometryFVM(dm, f, &area, c, n));
    const PetscInt side = SideOf(c, lo, hi);
    if (side >= 0) PetscCall(DMSetLabelValue(dm, labels::side, f, side));
    if (!sink_named || named("sink")) PetscCall(DMSetLabelValue(dm, labels::sink, f, 1));
    for (EdgeKind kind : all_edge_kinds())
      if (named(to_string(kind))) PetscCall(DMSetLabelValue(dm, to_string(kind), f, 1));
  }
  for (const char* petsc : {"Face Sets", "Cell Sets", "Vertex Sets", "marker"}) PetscCall(DMRemoveLabel(dm, petsc, nullptr));
  PetscFunctionReturn(0);
}

/// A file's serial mesh (rank 0), labelled; its crack names.
PetscErrorCode ReadLabelledPlex(MPI_Comm comm, const std::string& file, const std::string& option, DM* dm,
                                std::vector<std::string>* crack_names) {
  PetscFunctionBeginUser;
  std::map<PetscInt, std::string> names;
  VibrothermCallCpp(comm, names = SurfaceNames(file, option));  // every rank: the names (the mesh: PETSc, rank 0)
  PetscCall(DMPlexCreateGmshFromFile(comm, file.c_str(), PETSC_TRUE, dm));
  PetscCall(PetscObjectSetName((PetscObject)*dm, "specimen"));
  PetscCall(LabelFileFaces(*dm, names, option + " " + file));
  *crack_names = CrackNames(names);
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode MeshFileDimension(MPI_Comm comm, const std::string& path, int* dimension) {
  PetscFunctionBeginUser;
  *dimension = 0;
  PetscCall(RunOnRoot(comm, [&] {  // gmsh loads the whole mesh: once, on rank 0
    gmsh_support::GmshSession session;
    gmsh_support::OpenFile(path, "-mesh_file " + path);
    *dimension = gmsh::model::getDimension();
  }));
  PetscCallMPI(MPI_Bcast(dimension, 1, MPI_INT, 0, comm));
  PetscFunctionReturn(0);
}

PetscErrorCode CreateMeshFileSpecimen3D(MPI_Comm comm, const std::string& file, const std::string& heat_file,
                                        DM* serial, Specimen* s) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  std::vector<std::string> cracks, heat_cracks;
  PetscCall(ReadLabelledPlex(comm, file, "-mesh_file", serial, &cracks));
  PetscCall(PetscPrintf(comm, "Meshing: read %s (hexahedra, %zu crack%s)\n", file.c_str(), cracks.size(),
                        cracks.size() == 1 ? "" : "s"));
  for (const std::string& name : cracks) s->cracks.push_back(CrackInfo{name, 0.0, std::nullopt});
  s->source = file;
  if (heat_file.empty()) {
    s->heat_source = "wave";  // SpecimenCreate gives the heat the wave mesh unsplit
    s->crack_face_subdivisions = 1;  // the heat faces are the wave faces: one part a face is exact
    if (!cracks.empty())
      PetscCall(PetscPrintf(comm, "vibrotherm: note: the heat runs on %s unsplit: vibrotherm grades no heat mesh "
                            "to a 3D file's cracks (-heat_mesh_file gives one)\n", file.c_str()));
  } else {
    PetscCall(ReadLabelledPlex(comm, heat_file, "-heat_mesh_file", &s->heat, &heat_cracks));
    PetscCheck(heat_cracks == cracks, comm, PETSC_ERR_USER_INPUT,
               "-heat_mesh_file %s: its crack surfaces differ from -mesh_file %s's", heat_file.c_str(), file.c_str());
    s->heat_source = heat_file;
    s->crack_face_subdivisions = 16;  // the heat faces need not nest in the wave faces: accurate, not exact
    PetscCall(PetscPrintf(comm, "vibrotherm: note: with -heat_mesh_file the friction heat's transfer is "
                          "conservative, exact only where the heat faces nest in 16 sub-squares a wave crack face\n"));
  }
  PetscCall(PetscPrintf(comm, "Meshing: %.2f s\n", MPI_Wtime() - t0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
