// -specimen_*, -crack_*, -mesh_*, -edge_* options → SpecimenGeometry.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "vibrotherm/mesh/box_grid.hpp"
#include "vibrotherm/mesh/specimen_options.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/options/petsc/option_list.hpp"
#include "vibrotherm/options/petsc/option_choice.hpp"

namespace vibrotherm::mesh {
namespace {

/// -edge_<name> (a side, front or back). *given: whether the option was given.
PetscErrorCode ReadEdgeKind(PetscOptionItems* PetscOptionsObject, const char* name, EdgeKind* kind,
                            PetscBool* given = nullptr) {
  PetscFunctionBeginUser;
  char option[32];
  PetscCall(PetscSNPrintf(option, sizeof(option), "-edge_%s", name));
  std::vector<std::string> names;
  for (EdgeKind k : all_edge_kinds()) names.push_back(to_string(k));
  PetscInt index = static_cast<PetscInt>(std::find(all_edge_kinds().begin(), all_edge_kinds().end(), *kind) -
                                         all_edge_kinds().begin());
  PetscCall(OptionsChoice(PetscOptionsObject, option,
                          "Mechanical kind of this outer edge (front, back: faces of a 3D box)", names, &index, given));
  *kind = all_edge_kinds()[index];
  PetscFunctionReturn(0);
}

/// One or (3D) two values of a patch option into *first, *second; one value in 3D
/// sets both (same_second: a square patch) or the first only (the centre's second
/// coordinate keeps its default).
PetscErrorCode PatchPair(PetscOptionItems* PetscOptionsObject, const char* option, const char* help, bool box,
                         bool same_second, double* first, double* second, PetscBool* given) {
  PetscFunctionBeginUser;
  std::vector<double> v;
  if (*first > 0.0) v = box ? std::vector<double>{*first, *second} : std::vector<double>{*first};
  PetscCall(OptionsRealList(PetscOptionsObject, option, help, &v, given));
  if (!*given) PetscFunctionReturn(0);
  PetscCheck(v.size() == 1 || (box && v.size() == 2), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "%s takes %s, got %d values", option, box ? "one or two values on a 3D face (its two axes)" :
             "one value on a 2D edge", static_cast<int>(v.size()));
  *first = v[0];
  if (v.size() == 2 || same_second) *second = v.back();
  PetscFunctionReturn(0);
}

/// -source_patch_edge (its presence makes the patch), -source_patch_center (default the
/// middle of the edge or face), -source_patch_width; 3D: two values each, along face_axes().
PetscErrorCode ReadSourcePatch(PetscOptionItems* PetscOptionsObject, SpecimenGeometry* g) {
  PetscFunctionBeginUser;
  PetscInt side = static_cast<PetscInt>(Side::Top);
  PetscBool on = PETSC_FALSE;
  PetscCall(OptionsChoice(PetscOptionsObject, "-source_patch_edge",
                          "A transducer patch on this edge (3D: face) is the source (the rest keeps -edge_<side>)",
                          {"bottom", "right", "top", "left", "front", "back"}, &side, &on));
  g->patch.on = on;
  g->patch.side = static_cast<Side>(side);
  const bool box = g->depth > 0.0;
  const auto axes = face_axes(g->patch.side);
  g->patch.center = 0.5 * g->extent(axes[0]);
  g->patch.center2 = 0.5 * g->extent(axes[1]);
  PetscBool has_center = PETSC_FALSE, has_width = PETSC_FALSE;
  PetscCall(PatchPair(PetscOptionsObject, "-source_patch_center",
                      "Centre of the patch along its edge [m] (x on bottom/top, y on the sides; 3D: then z, "
                      "front/back: x then y; default the middle)", box, false, &g->patch.center,
                      &g->patch.center2, &has_center));
  PetscCall(PatchPair(PetscOptionsObject, "-source_patch_width",
                      "Width of the transducer patch [m] (3D: along the face's two axes; one value: a square)", box,
                      true, &g->patch.width, &g->patch.width2, &has_width));
  PetscCheck(on || (!has_center && !has_width), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "-source_patch_%s given without -source_patch_edge (the edge the transducer sits on)",
             has_width ? "width" : "center");
  PetscFunctionReturn(0);
}

/// -specimen_depth, -crack_width, -edge_front, -edge_back, -crack_shape, -crack_tilt. *three_d: the first of
/// the 3D-only ones given (nullptr: none).
PetscErrorCode ReadBoxOptions(PetscOptionItems* PetscOptionsObject, SpecimenGeometry* g, std::vector<double>* widths,
                              std::vector<double>* tilts, std::vector<PetscInt>* shapes, const char** three_d) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsReal("-specimen_depth", "Depth [m] along z: > 0 makes the specimen a 3D box; 0 a 2D "
                             "plane-strain specimen", nullptr, g->depth, &g->depth, nullptr));
  PetscBool given[5] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};
  PetscCall(OptionsRealList(PetscOptionsObject, "-crack_width",
                            "3D: crack extent along z, or along its up-dip when tilted [m] (one value applies to all)",
                            widths, &given[0]));
  PetscCall(ReadEdgeKind(PetscOptionsObject, "front", &g->depth_edges[0], &given[1]));
  PetscCall(ReadEdgeKind(PetscOptionsObject, "back", &g->depth_edges[1], &given[2]));
  PetscCall(OptionsChoiceList(PetscOptionsObject, "-crack_shape",
                              "3D: the cracks' outlines, the length x width rectangle or the ellipse inscribed in it",
                              {"rectangle", "ellipse"}, shapes, &given[3]));
  PetscCall(OptionsRealList(PetscOptionsObject, "-crack_tilt",
                            "3D: crack planes turned about their strikes [deg] (0: containing z; > 0: the normal "
                            "toward +z; one value applies to all)", tilts, &given[4]));
  const char* names[5] = {"-crack_width", "-edge_front", "-edge_back", "-crack_shape", "-crack_tilt"};
  *three_d = nullptr;
  for (int k = 4; k >= 0; --k)
    if (given[k]) *three_d = names[k];
  PetscFunctionReturn(0);
}

/// A per-crack option's values: none (not given), one for all the cracks, or one a crack.
template <class T>
PetscErrorCode CheckPerCrack(MPI_Comm comm, const char* option, const std::vector<T>& values, PetscInt ncracks) {
  PetscFunctionBeginUser;
  PetscCheck(values.size() <= 1 || static_cast<PetscInt>(values.size()) == ncracks, comm, PETSC_ERR_USER_INPUT,
             "%s: %zu values for %" PetscInt_FMT " cracks (one for all, or one a crack)", option, values.size(),
             ncracks);
  PetscFunctionReturn(0);
}

/// Crack i's value of such a list (given).
template <class T>
T PerCrack(const std::vector<T>& values, PetscInt i) {
  return values[values.size() == 1 ? 0 : static_cast<std::size_t>(i)];
}

/// -mesh_crack_mirror off|on|<half-width [m]> → g->crack_mirror_width (0, −1: DefaultMirrorWidth, the width).
PetscErrorCode ReadCrackMirror(PetscOptionItems* PetscOptionsObject, SpecimenGeometry* g) {
  PetscFunctionBeginUser;
  char text[64] = "";
  PetscBool given = PETSC_FALSE;
  PetscCall(PetscOptionsString("-mesh_crack_mirror",
                               "Mesh a band around each crack mirror-symmetric across it (issue 41): off, on (half-width: "
                               "the distance over which the mesh grades from -mesh_h_crack to -mesh_h) or a half-width [m]",
                               nullptr, "off", text, sizeof(text), &given));
  if (!given) PetscFunctionReturn(0);
  const std::string value = text;
  char* end = nullptr;
  const double width = std::strtod(text, &end);
  const bool number = end != text && *end == '\0' && std::isfinite(width) && width >= 0.0;
  PetscCheck(value == "off" || value == "on" || number, PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "-mesh_crack_mirror takes off, on or a half-width >= 0 in metres, got '%s'", text);
  g->crack_mirror_width = value == "off" ? 0.0 : value == "on" ? -1.0 : width;
  PetscFunctionReturn(0);
}

PetscErrorCode ReadSpecimenGeometry(MPI_Comm comm, SpecimenGeometry* g, bool check) {
  PetscFunctionBeginUser;
  std::vector<double> centers, lengths, angles, widths, tilts;
  std::vector<PetscInt> shapes;
  const char* three_d_given = nullptr;
  PetscBool has_lengths = PETSC_FALSE, has_angles = PETSC_FALSE;
  PetscInt cell = g->quads ? 0 : 1;
  PetscOptionsBegin(comm, nullptr, "Generated specimen (used unless -mesh_file)", nullptr);
  PetscCall(PetscOptionsReal("-specimen_width", "Width [m]", nullptr, g->width, &g->width, nullptr));
  PetscCall(PetscOptionsReal("-specimen_height", "Height [m]", nullptr, g->height, &g->height, nullptr));
  PetscCall(OptionsRealList(PetscOptionsObject, "-crack_center",
                            "Crack centres x1,y1,x2,y2,... [m] (origin bottom-left, y up; 3D: x1,y1,z1,x2,y2,z2,...)",
                            &centers, nullptr));
  PetscCall(OptionsRealList(PetscOptionsObject, "-crack_length",
                            "Crack lengths [m] (one value applies to all; 3D: along the strike in the x-y plane)",
                            &lengths, &has_lengths));
  PetscCall(OptionsRealList(PetscOptionsObject, "-crack_angle",
                            "Crack angles to the horizontal [deg] (one value applies to all)", &angles, &has_angles));
  PetscCall(PetscOptionsReal("-mesh_h", "Element size away from the cracks [m]", nullptr, g->h, &g->h, nullptr));
  PetscCall(PetscOptionsReal("-mesh_h_crack", "Element size along the cracks [m]", nullptr, g->h_crack, &g->h_crack,
                             nullptr));
  PetscCall(PetscOptionsReal("-mesh_grading", "Element size growth per metre of distance from a crack", nullptr,
                             g->grading, &g->grading, nullptr));
  PetscCall(OptionsChoice(PetscOptionsObject, "-mesh_cell", "Cell type", {"quad", "tri"}, &cell, nullptr));
  PetscCall(ReadCrackMirror(PetscOptionsObject, g));
  for (Side side : {Side::Bottom, Side::Right, Side::Top, Side::Left})
    PetscCall(ReadEdgeKind(PetscOptionsObject, to_string(side), &g->edges[static_cast<int>(side)]));
  PetscCall(ReadBoxOptions(PetscOptionsObject, g, &widths, &tilts, &shapes, &three_d_given));
  PetscCall(ReadSourcePatch(PetscOptionsObject, g));  // after the depth: the patch's axes
  PetscOptionsEnd();
  g->quads = cell == 0;
  if (!check) PetscFunctionReturn(0);  // declared only: a -mesh_file sets the geometry
  PetscCheck(!(g->depth < 0.0) && std::isfinite(g->depth), comm, PETSC_ERR_USER_INPUT,
             "-specimen_depth must be >= 0 (0: a 2D specimen), got %g", g->depth);
  PetscCheck(g->depth > 0.0 || !three_d_given, comm, PETSC_ERR_USER_INPUT,
             "%s applies to a 3D box only: give -specimen_depth > 0", three_d_given);
  PetscCheck(!(g->depth > 0.0) || g->crack_mirror_width == 0.0, comm, PETSC_ERR_USER_INPUT,
             "-mesh_crack_mirror applies to a generated 2D specimen only: give -specimen_depth 0 or leave it off");

  const PetscInt ncenters = static_cast<PetscInt>(centers.size());
  const PetscInt dim = g->depth > 0.0 ? 3 : 2;
  PetscCheck(ncenters % dim == 0, comm, PETSC_ERR_USER_INPUT, "-crack_center needs %s (got %" PetscInt_FMT " values)",
             dim == 2 ? "x,y pairs" : "x,y,z triples in 3D", ncenters);
  const PetscInt ncracks = ncenters / dim;
  PetscCheck(ncracks == 0 || has_lengths, comm, PETSC_ERR_USER_INPUT, "-crack_length is required with -crack_center");
  PetscCheck(ncracks > 0 || (!has_lengths && !has_angles), comm, PETSC_ERR_USER_INPUT,
             "-crack_length/-crack_angle given without -crack_center");
  PetscCheck(ncracks > 0 || (widths.empty() && tilts.empty() && shapes.empty()), comm, PETSC_ERR_USER_INPUT,
             "%s given without -crack_center", !widths.empty() ? "-crack_width" : !tilts.empty() ? "-crack_tilt"
                                                                                                  : "-crack_shape");
  if (ncracks > 0) PetscCall(CheckPerCrack(comm, "-crack_length", lengths, ncracks));
  PetscCall(CheckPerCrack(comm, "-crack_angle", angles, ncracks));
  PetscCall(CheckPerCrack(comm, "-crack_width", widths, ncracks));
  PetscCall(CheckPerCrack(comm, "-crack_tilt", tilts, ncracks));
  PetscCall(CheckPerCrack(comm, "-crack_shape", shapes, ncracks));
  g->cracks.clear();
  for (PetscInt i = 0; i < ncracks; ++i) {
    Crack c;
    c.x = centers[dim * i];
    c.y = centers[dim * i + 1];
    if (dim == 3) c.z = centers[dim * i + 2];
    if (!widths.empty()) c.width = PerCrack(widths, i);
    if (!tilts.empty()) c.tilt_deg = PerCrack(tilts, i);
    c.length = PerCrack(lengths, i);
    if (!angles.empty()) c.angle_deg = PerCrack(angles, i);
    if (!shapes.empty()) c.shape = static_cast<CrackShape>(PerCrack(shapes, i));
    g->cracks.push_back(c);
  }
  if (dim == 3) VibrothermCallCpp(comm, (void)BoxGrid(*g));
  else VibrothermCallCpp(comm, g->validate());
  PetscFunctionReturn(0);
}

/// Reads the -heat_mesh* options given (-help shows the defaults for this geometry);
/// check: refuse sizes that do not nest.
PetscErrorCode ReadHeatMeshOptions(MPI_Comm comm, const SpecimenGeometry& g, double exchange_length,
                                   HeatMeshOptions* o, bool check) {
  PetscFunctionBeginUser;
  HeatMeshSizes shown = HeatMeshSizesFor(HeatMeshOptions{}, g, exchange_length);  // the defaults
  PetscInt kind = o->graded ? 1 : 0;
  PetscBool set[5] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};
  PetscOptionsBegin(comm, nullptr, "Heat mesh (generated specimens)", nullptr);
  PetscCall(OptionsChoice(PetscOptionsObject, "-heat_mesh",
                          "Heat mesh: its own, graded to the cracks, or the unsplit wave mesh", {"wave", "graded"},
                          &kind, nullptr));
  PetscCall(PetscOptionsReal("-heat_mesh_h_crack", "First layer thickness at the cracks [m] (default: half of sqrt(alpha couple_dt))",
                             nullptr, shown.h_crack, &shown.h_crack, &set[0]));
  PetscCall(PetscOptionsReal("-heat_mesh_growth", "Thickness ratio of successive layers", nullptr, shown.growth,
                             &shown.growth, &set[1]));
  PetscCall(PetscOptionsReal("-heat_mesh_h_along", "Element length along the cracks [m] (default: -mesh_h_crack / 2)",
                             nullptr, shown.h_along, &shown.h_along, &set[2]));
  PetscCall(PetscOptionsReal("-heat_mesh_h", "Element size away from the cracks [m] (default: -mesh_h)", nullptr,
                             shown.h, &shown.h, &set[3]));
  PetscCall(PetscOptionsReal("-heat_mesh_grading", "Element size growth per metre away from the crack bands (default: 2 x -mesh_grading)",
                             nullptr, shown.grading, &shown.grading, &set[4]));
  PetscOptionsEnd();
  o->graded = kind == 1;
  std::optional<double>* given[5] = {&o->h_crack, &o->growth, &o->h_along, &o->h, &o->grading};
  const double values[5] = {shown.h_crack, shown.growth, shown.h_along, shown.h, shown.grading};
  for (int k = 0; k < 5; ++k)
    if (set[k]) *given[k] = values[k];
  if (o->graded && check) VibrothermCallCpp(comm, HeatMeshSizesFor(*o, g, exchange_length).validate());
  PetscFunctionReturn(0);
}

PetscErrorCode ReadMeshSource(MPI_Comm comm, MeshSource* m) {
  PetscFunctionBeginUser;
  char file[PETSC_MAX_PATH_LEN] = "", heat_file[PETSC_MAX_PATH_LEN] = "";
  PetscBool from_file = PETSC_FALSE, heat_from_file = PETSC_FALSE, force = PETSC_FALSE, refine_given = PETSC_FALSE;
  PetscOptionsBegin(comm, nullptr, "Specimen mesh", nullptr);
  PetscCall(PetscOptionsString("-mesh_file", "gmsh .msh file (physical curves, 3D: surfaces of hexahedra: source, "
                               "absorbing, free, roller, fixed, sink, crack*); default: generate from -specimen_* "
                               "and -crack_*",
                               nullptr, file, file, sizeof(file), &from_file));
  PetscCall(PetscOptionsString("-heat_mesh_file", "gmsh .msh file of the heat mesh for a -mesh_file scene (same "
                               "physical curve names; default: the unsplit -mesh_file mesh)",
                               nullptr, heat_file, heat_file, sizeof(heat_file), &heat_from_file));
  PetscCall(PetscOptionsInt("-dm_refine", "Uniform refinements of the wave mesh before splitting", nullptr,
                            m->refinements, &m->refinements, &refine_given));
  PetscCall(PetscOptionsBool("-force",
                             "Run even when a memory estimate exceeds the memory available (the scene's; MUMPS's for "
                             "-modes and -wave_start harmonic)",
                             nullptr, force, &force, nullptr));
  PetscOptionsEnd();
  m->file = file;
  m->heat_file = heat_file;
  m->from_file = from_file;
  m->heat_from_file = heat_from_file;
  m->force = force;
  // Checked here: PetscOptionsBoundedInt's own error is a PETSc trace (exit 1) that does not name the option.
  PetscCheck(m->refinements >= 0, comm, PETSC_ERR_USER_INPUT, "-dm_refine must be >= 0, got %" PetscInt_FMT,
             m->refinements);
  // -dm_refine has PETSc's dm_ prefix, so the audit of missing values leaves it to PETSc,
  // which takes "-dm_refine" with no value as not given: vibrotherm reads it, so it checks.
  bool refine_named;
  PetscCall(OptionGiven(nullptr, "-dm_refine", &refine_named));
  PetscCheck(!refine_named || refine_given, comm, PETSC_ERR_USER_INPUT, "-dm_refine: needs a value");
  PetscCheck(!m->from_file || !m->file.empty(), comm, PETSC_ERR_USER_INPUT, "-mesh_file: needs a value");
  PetscCheck(!m->heat_from_file || !m->heat_file.empty(), comm, PETSC_ERR_USER_INPUT, "-heat_mesh_file: needs a value");
  PetscCheck(!m->heat_from_file || m->from_file, comm, PETSC_ERR_USER_INPUT,
             "-heat_mesh_file goes with -mesh_file (a generated specimen gets its heat mesh from -heat_mesh_*)");
  PetscFunctionReturn(0);
}

/// -mesh_file sets the specimen's outline, cracks, mesh and edges: the options of a
/// generated specimen given with it (an options file written for one, such as
/// paper.opts) are ignored, said in one note.
PetscErrorCode NoteIgnoredGeometry(MPI_Comm comm, const std::string& file) {
  PetscFunctionBeginUser;
  static const char* const names[] = {"-specimen_width", "-specimen_height", "-crack_center", "-crack_length",
                                      "-crack_angle", "-mesh_h", "-mesh_h_crack", "-mesh_grading", "-mesh_cell", "-mesh_crack_mirror",
                                      "-edge_top", "-edge_bottom", "-edge_left", "-edge_right", "-crack_width",
                                      "-edge_front", "-edge_back", "-specimen_depth", "-crack_shape", "-crack_tilt",
                                      "-source_patch_edge", "-source_patch_center", "-source_patch_width"};
  std::string given;
  for (const char* name : names) {
    bool set;
    PetscCall(OptionGiven(nullptr, name, &set));
    if (set) given += std::string(given.empty() ? "" : ", ") + name;
  }
  if (!given.empty())
    PetscCall(PetscPrintf(comm, "vibrotherm: note: -mesh_file %s sets the specimen, its cracks, mesh and edges: %s "
                                "ignored\n", file.c_str(), given.c_str()));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ReadSpecimenOptions(MPI_Comm comm, double exchange_length, SpecimenOptions* o) {
  PetscFunctionBeginUser;
  PetscCall(ReadMeshSource(comm, &o->source));
  const bool generated = !o->source.from_file;
  PetscCall(ReadSpecimenGeometry(comm, &o->geometry, generated));
  if (!generated) PetscCall(NoteIgnoredGeometry(comm, o->source.file));
  // A mesh file's heat mesh sizes are checked against the geometry read from it (SpecimenCreate).
  PetscCall(ReadHeatMeshOptions(comm, o->geometry, exchange_length, &o->heat, generated));
  PetscFunctionReturn(0);
}

HeatMeshSizes HeatMeshSizesFor(const HeatMeshOptions& o, const SpecimenGeometry& g, double exchange_length) {
  // Each default is capped by the next size: a slow source (1 Hz: a 2 mm exchange layer) must
  // not fail on sizes the user never set; diffusion smooths, so the heat mesh may coarsen faster.
  HeatMeshSizes s;
  s.h = g.h;
  s.h_along = std::min(0.5 * g.h_crack, s.h);
  s.h_crack = std::min(0.5 * exchange_length, s.h_along);
  s.grading = 2.0 * g.grading;
  s.graded = o.graded;
  if (o.h_crack) s.h_crack = *o.h_crack;
  if (o.growth) s.growth = *o.growth;
  if (o.h_along) s.h_along = *o.h_along;
  if (o.h) s.h = *o.h;
  if (o.grading) s.grading = *o.grading;
  // A default follows the size the user set next to it (a bad one is refused, naming it).
  if (!o.h_along && s.h > 0.0) s.h_along = std::min(s.h_along, s.h);
  if (!o.h_crack && s.h_along > 0.0) s.h_crack = std::min(s.h_crack, s.h_along);
  return s;
}

double FinestRequestedElement(const SpecimenOptions& o) {
  if (o.source.from_file) return 0.0;
  return std::ldexp(std::min(o.geometry.h, o.geometry.h_crack), -static_cast<int>(o.source.refinements));
}

}  // namespace vibrotherm::mesh
