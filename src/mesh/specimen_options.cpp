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

namespace vibrotherm::mesh {
namespace {

/// The mechanical kinds an outer edge can have, by name (in label order).
std::vector<std::string> EdgeKindNames() {
  std::vector<std::string> names;
  for (EdgeKind k : all_edge_kinds()) names.push_back(to_string(k));
  return names;
}

/// An -edge_<name> option (a side, front or back) read into *kind.
PetscErrorCode ReadEdgeKind(PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& spec, EdgeKind* kind,
                            std::string* shown) {
  PetscFunctionBeginUser;
  PetscInt index = static_cast<PetscInt>(std::find(all_edge_kinds().begin(), all_edge_kinds().end(), *kind) -
                                         all_edge_kinds().begin());
  PetscCall(OptionsChoice(PetscOptionsObject, spec.name.c_str(), spec.help.c_str(), spec.choices, &index, nullptr));
  *kind = all_edge_kinds()[index];
  *shown = spec.choices[index];
  PetscFunctionReturn(0);
}

/// -edge_<side> (side: a mesh::Side), declared.
OptionSpec<SpecimenGeometryInput> EdgeOption(Side side) {
  const int s = static_cast<int>(side);
  return {{std::string("-edge_") + to_string(side), "Mechanical kind of this outer edge (front, back: faces of a 3D box)",
           "", contact::ParameterType::Choice, "", contact::Range::any(), EdgeKindNames()},
          [s](PetscOptionItems* items, const contact::ParameterSpec& spec, SpecimenGeometryInput* in,
              std::string* shown) {
            EdgeKind* kind = s < 4 ? &in->geometry.edges[s] : &in->geometry.depth_edges[s - 4];
            return ReadEdgeKind(items, spec, kind, shown);
          }};
}

/// One or (3D) two values of a patch option into *first, *second; one value in 3D
/// sets both (same_second: a square patch) or the first only (the centre's second
/// coordinate keeps its default). *shown: the value as -help shows it.
PetscErrorCode PatchPair(PetscOptionItems* PetscOptionsObject, const char* option, const char* help, bool box,
                         bool same_second, double* first, double* second, std::string* shown) {
  PetscFunctionBeginUser;
  std::vector<double> v;
  if (*first > 0.0) v = box ? std::vector<double>{*first, *second} : std::vector<double>{*first};
  PetscBool given;
  PetscCall(OptionsRealList(PetscOptionsObject, option, help, &v, &given, shown));
  if (!given) PetscFunctionReturn(0);
  PetscCheck(v.size() == 1 || (box && v.size() == 2), PETSC_COMM_SELF, PETSC_ERR_USER_INPUT,
             "%s takes %s, got %d values", option, box ? "one or two values on a 3D face (its two axes)" :
             "one value on a 2D edge", static_cast<int>(v.size()));
  *first = v[0];
  if (v.size() == 2 || same_second) *second = v.back();
  PetscFunctionReturn(0);
}

/// -source_patch_edge (its presence makes the patch; the default centre is the middle of the edge or face).
PetscErrorCode ReadPatchEdge(PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& spec,
                             SpecimenGeometry* g, std::string* shown) {
  PetscFunctionBeginUser;
  PetscInt side = static_cast<PetscInt>(Side::Top);
  PetscBool on = PETSC_FALSE;
  PetscCall(OptionsChoice(PetscOptionsObject, spec.name.c_str(), spec.help.c_str(), spec.choices, &side, &on));
  g->patch.on = on;
  g->patch.side = static_cast<Side>(side);
  *shown = spec.choices[side];
  const auto axes = face_axes(g->patch.side);
  g->patch.center = 0.5 * g->extent(axes[0]);
  g->patch.center2 = 0.5 * g->extent(axes[1]);
  PetscFunctionReturn(0);
}

/// A patch option of one or (3D: along face_axes()) two values, read by PatchPair.
OptionSpec<SpecimenGeometryInput> PatchOption(const char* name, bool square, double SourcePatch::*first,
                                              double SourcePatch::*second, const char* help) {
  return {{name, help, "m", contact::ParameterType::RealList, "", contact::Range::any(), {}},
          [=](PetscOptionItems* items, const contact::ParameterSpec& spec, SpecimenGeometryInput* in,
              std::string* shown) {
            SourcePatch& patch = in->geometry.patch;
            return PatchPair(items, spec.name.c_str(), spec.describe().c_str(), in->geometry.depth > 0.0, square,
                             &(patch.*first), &(patch.*second), shown);
          }};
}

/// -crack_shape rectangle|ellipse, one for all or one a crack.
OptionSpec<SpecimenGeometryInput> CrackShapeOption() {
  return {{"-crack_shape", "3D: the cracks' outlines, the length x width rectangle or the ellipse inscribed in it", "",
           contact::ParameterType::Choice, "", contact::Range::any(), {"rectangle", "ellipse"}},
          [](PetscOptionItems* items, const contact::ParameterSpec& spec, SpecimenGeometryInput* in,
             std::string* shown) {
            return OptionsChoiceList(items, spec.name.c_str(), spec.help.c_str(), spec.choices, &in->shapes, nullptr,
                                     shown);
          }};
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
PetscErrorCode ReadCrackMirror(PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& spec,
                               SpecimenGeometry* g, std::string* shown) {
  PetscFunctionBeginUser;
  char text[64] = "";
  PetscBool given = PETSC_FALSE;
  PetscCall(PetscOptionsString(spec.name.c_str(), spec.help.c_str(), nullptr, "off", text, sizeof(text), &given));
  *shown = given ? text : "off";
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

PetscErrorCode ReadSpecimenGeometry(MPI_Comm comm, SpecimenGeometry* g, bool check, OptionValues* values) {
  PetscFunctionBeginUser;
  SpecimenGeometryInput in;
  in.geometry = *g;
  in.cell = g->quads ? MeshCell::Quad : MeshCell::Triangle;
  PetscCall(ReadOptionSpecs(comm, "Generated specimen (used unless -mesh_file)", SpecimenGeometryOptionSpecs(), &in, values));
  *g = in.geometry;
  g->quads = in.cell == MeshCell::Quad;
  if (!check) PetscFunctionReturn(0);  // declared only: a -mesh_file sets the geometry
  const char* three_d_given;
  PetscCall(FirstOptionGiven({"-crack_width", "-edge_front", "-edge_back", "-crack_shape", "-crack_tilt"},
                             &three_d_given));
  const char* patch_given;
  PetscCall(FirstOptionGiven({"-source_patch_center", "-source_patch_width"}, &patch_given));
  PetscCheck(g->patch.on || !patch_given, comm, PETSC_ERR_USER_INPUT,
             "%s given without -source_patch_edge (the edge the transducer sits on)", patch_given);
  const std::vector<double>& centers = in.centers;
  const std::vector<double>& lengths = in.lengths;
  const std::vector<double>& angles = in.angles;
  const std::vector<double>& widths = in.widths;
  const std::vector<double>& tilts = in.tilts;
  const std::vector<PetscInt>& shapes = in.shapes;
  const bool has_lengths = !lengths.empty(), has_angles = !angles.empty();
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

/// -heat_mesh_<size>: -help shows the default for this geometry (in->shown); a value given is kept.
OptionSpec<HeatMeshInput> HeatMeshSizeOption(const char* name, double HeatMeshSizes::*shown,
                                             std::optional<double> HeatMeshOptions::*given, const char* unit,
                                             const char* help) {
  return {{name, help, unit, contact::ParameterType::Real, "", contact::Range::any(), {}},
          [=](PetscOptionItems* PetscOptionsObject, const contact::ParameterSpec& spec, HeatMeshInput* in,
              std::string* text) {
            double& value = in->shown.*shown;
            PetscBool set = PETSC_FALSE;
            PetscCall(PetscOptionsReal(spec.name.c_str(), spec.describe().c_str(), nullptr, value, &value, &set));
            *text = ShownReal(value);
            if (set) in->options.*given = value;
            return set ? CheckOptionRange(PetscOptionsObject->comm, spec, value) : PetscErrorCode(0);
          }};
}

/// Reads the -heat_mesh* options given (-help shows the defaults for this geometry);
/// check: refuse sizes that do not nest.
PetscErrorCode ReadHeatMeshOptions(MPI_Comm comm, const SpecimenGeometry& g, double exchange_length,
                                   HeatMeshOptions* o, bool check, OptionValues* values) {
  PetscFunctionBeginUser;
  HeatMeshInput in{*o, HeatMeshSizesFor(HeatMeshOptions{}, g, exchange_length)};  // the defaults shown
  PetscCall(ReadOptionSpecs(comm, "Heat mesh (generated specimens)", HeatMeshOptionSpecs(), &in, values));
  *o = in.options;
  if (o->graded && check) VibrothermCallCpp(comm, HeatMeshSizesFor(*o, g, exchange_length).validate());
  PetscFunctionReturn(0);
}

PetscErrorCode ReadMeshSource(MPI_Comm comm, MeshSource* m, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "Specimen mesh", MeshSourceOptionSpecs(), m, values));
  bool refine_named;
  std::string refinements;
  PetscCall(OptionGiven(nullptr, "-mesh_file", &m->from_file));
  PetscCall(OptionGiven(nullptr, "-heat_mesh_file", &m->heat_from_file));
  PetscCall(OptionText(nullptr, "-dm_refine", &refinements, &refine_named));
  // -dm_refine has PETSc's dm_ prefix, so the audit of missing values leaves it to PETSc,
  // which takes "-dm_refine" with no value as not given: vibrotherm reads it, so it checks.
  PetscCheck(!refine_named || !refinements.empty(), comm, PETSC_ERR_USER_INPUT, "-dm_refine: needs a value");
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

const std::vector<OptionSpec<MeshSource>>& MeshSourceOptionSpecs() {
  using M = MeshSource;
  static const std::vector<OptionSpec<M>> specs = {
      TextOption("-mesh_file", &M::file, "gmsh .msh file, or a .geo script that vibrotherm meshes into the output "
                 "directory (physical curves, 3D: surfaces of hexahedra: source, absorbing, free, roller, fixed, sink, "
                 "crack*); default: generate from -specimen_* and -crack_*"),
      TextOption("-heat_mesh_file", &M::heat_file, "gmsh .msh file (or .geo script) of the heat mesh for a -mesh_file "
                 "scene (same physical curve names; default: the unsplit -mesh_file mesh)"),
      // Declared with a range: PetscOptionsBoundedInt's own error is a PETSc trace that does not name the option.
      IntOption("-dm_refine", &M::refinements, contact::Range::at_least(0.0),
                "Uniform refinements of the wave mesh before splitting"),
      FlagOption("-force", &M::force, "Run even when a memory estimate exceeds the memory available (the scene's; "
                 "MUMPS's for -modes and -wave_start harmonic)"),
  };
  return specs;
}

const std::vector<OptionSpec<HeatMeshInput>>& HeatMeshOptionSpecs() {
  using In = HeatMeshInput;
  using S = HeatMeshSizes;
  using O = HeatMeshOptions;
  static const std::vector<OptionSpec<In>> specs = {
      NestedOption(&In::options, ChoiceOption("-heat_mesh", &O::graded, {"wave", "graded"},
                                              "Heat mesh: its own, graded to the cracks, or the unsplit wave mesh")),
      HeatMeshSizeOption("-heat_mesh_h_crack", &S::h_crack, &O::h_crack, "m",
                         "First layer thickness at the cracks (default: half of sqrt(alpha couple_dt))"),
      HeatMeshSizeOption("-heat_mesh_growth", &S::growth, &O::growth, "", "Thickness ratio of successive layers"),
      HeatMeshSizeOption("-heat_mesh_h_along", &S::h_along, &O::h_along, "m",
                         "Element length along the cracks (default: -mesh_h_crack / 2)"),
      HeatMeshSizeOption("-heat_mesh_h", &S::h, &O::h, "m", "Element size away from the cracks (default: -mesh_h)"),
      HeatMeshSizeOption("-heat_mesh_grading", &S::grading, &O::grading, "",
                         "Element size growth per metre away from the crack bands (default: 2 x -mesh_grading)"),
  };
  return specs;
}

const std::vector<OptionSpec<SpecimenGeometryInput>>& SpecimenGeometryOptionSpecs() {
  using In = SpecimenGeometryInput;
  using G = SpecimenGeometry;
  using contact::Range;
  const auto geometry = [](const OptionSpec<G>& option) { return NestedOption(&In::geometry, option); };
  static const std::vector<OptionSpec<In>> specs = {
      geometry(RealOption("-specimen_width", &G::width, Range::any(), "m", "Width")),
      geometry(RealOption("-specimen_height", &G::height, Range::any(), "m", "Height")),
      RealListOption("-crack_center", &In::centers, Range::any(), "m",
                     "Crack centres x1,y1,x2,y2,... (origin bottom-left, y up; 3D: x1,y1,z1,x2,y2,z2,...)"),
      RealListOption("-crack_length", &In::lengths, Range::any(), "m",
                     "Crack lengths (one value applies to all; 3D: along the strike in the x-y plane)"),
      RealListOption("-crack_angle", &In::angles, Range::any(), "deg",
                     "Crack angles to the horizontal (one value applies to all)"),
      geometry(RealOption("-mesh_h", &G::h, Range::any(), "m", "Element size away from the cracks")),
      geometry(RealOption("-mesh_h_crack", &G::h_crack, Range::any(), "m", "Element size along the cracks")),
      geometry(RealOption("-mesh_grading", &G::grading, Range::any(), "", "Element size growth per metre of distance "
                          "from a crack")),
      ChoiceOption("-mesh_cell", &In::cell, {"quad", "tri"}, "Cell type"),
      {{"-mesh_crack_mirror", "Mesh a band around each crack mirror-symmetric across it (issue 41): off, on "
        "(half-width: the distance over which the mesh grades from -mesh_h_crack to -mesh_h) or a half-width [m]",
        "", contact::ParameterType::Text, "off", Range::any(), {}},
       [](PetscOptionItems* items, const contact::ParameterSpec& spec, In* in, std::string* shown) {
         return ReadCrackMirror(items, spec, &in->geometry, shown);
       }},
      EdgeOption(Side::Bottom), EdgeOption(Side::Right), EdgeOption(Side::Top), EdgeOption(Side::Left),
      geometry(RealOption("-specimen_depth", &G::depth, Range::at_least(0.0), "m",
                          "Depth along z: > 0 makes the specimen a 3D box; 0 a 2D plane-strain specimen")),
      RealListOption("-crack_width", &In::widths, Range::any(), "m",
                     "3D: crack extent along z, or along its up-dip when tilted (one value applies to all)"),
      EdgeOption(Side::Front), EdgeOption(Side::Back), CrackShapeOption(),
      RealListOption("-crack_tilt", &In::tilts, Range::any(), "deg",
                     "3D: crack planes turned about their strikes (0: containing z; > 0: the normal toward +z; one "
                     "value applies to all)"),
      // After the depth: the patch's axes.
      {{"-source_patch_edge", "A transducer patch on this edge (3D: face) is the source (the rest keeps -edge_<side>)",
        "", contact::ParameterType::Choice, "", Range::any(), {"bottom", "right", "top", "left", "front", "back"}},
       [](PetscOptionItems* items, const contact::ParameterSpec& spec, In* in, std::string* shown) {
         return ReadPatchEdge(items, spec, &in->geometry, shown);
       }},
      PatchOption("-source_patch_center", false, &SourcePatch::center, &SourcePatch::center2,
                  "Centre of the patch along its edge (x on bottom/top, y on the sides; 3D: then z, front/back: x then "
                  "y; default the middle)"),
      PatchOption("-source_patch_width", true, &SourcePatch::width, &SourcePatch::width2,
                  "Width of the transducer patch (3D: along the face's two axes; one value: a square)"),
  };
  return specs;
}

PetscErrorCode ReadSpecimenOptions(MPI_Comm comm, double exchange_length, SpecimenOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadMeshSource(comm, &o->source, values));
  const bool generated = !o->source.from_file;
  PetscCall(ReadSpecimenGeometry(comm, &o->geometry, generated, values));
  if (!generated) PetscCall(NoteIgnoredGeometry(comm, o->source.file));
  // A mesh file's heat mesh sizes are checked against the geometry read from it (SpecimenCreate).
  PetscCall(ReadHeatMeshOptions(comm, o->geometry, exchange_length, &o->heat, generated, values));
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
