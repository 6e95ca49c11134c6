// gmsh → MeshData. One gmsh session per call (gmsh's API is a process-wide
// singleton): initialise, build or open, mesh, extract, finalise.
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "crack_mirror_gmsh.hpp"
#include "gmsh_support.hpp"
#include "vibrotherm/mesh/crack_mirror.hpp"
#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::mesh {
namespace {

using namespace gmsh_support;

/// Size field: h_crack within a band around the cracks, growing by `grading` per metre to h.
void set_size_field(const SpecimenGeometry& g, const std::vector<double>& crack_curves) {
  const int points = crack_curves.empty() ? 0 : static_cast<int>(std::max(100.0, 4.0 * g.cracks.front().length / g.h_crack));
  set_graded_size(crack_curves, {g.h_crack, g.h, g.h_crack, g.h_crack + (g.h - g.h_crack) / g.grading, points});
}

/// Each crack's line (its pieces, when a mirror band cuts it) and the bands' halves, added
/// to the model; `tools` gets the crack lines first (crack by crack), then the halves.
struct CrackShapes {
  std::vector<std::vector<int>> lines;  ///< per crack
  std::vector<crack_mirror_gmsh::BandShapes> bands;
};
CrackShapes AddCracks(const SpecimenGeometry& g, const CrackMirrorPlan& plan, DimTags* tools) {
  CrackShapes shapes;
  shapes.lines.resize(g.cracks.size());
  for (const CrackMirror& band : plan.bands) {
    shapes.bands.push_back(crack_mirror_gmsh::AddBand(band));
    shapes.lines[band.crack] = shapes.bands.back().crack_lines;
  }
  for (std::size_t i = 0; i < g.cracks.size(); ++i) {
    if (shapes.lines[i].empty()) {
      const auto p0 = g.cracks[i].end(0), p1 = g.cracks[i].end(1);
      const int a = gmsh::model::occ::addPoint(p0[0], p0[1], 0), b = gmsh::model::occ::addPoint(p1[0], p1[1], 0);
      shapes.lines[i].push_back(gmsh::model::occ::addLine(a, b));
    }
    for (int line : shapes.lines[i]) tools->push_back({1, line});
  }
  for (const auto& band : shapes.bands) tools->insert(tools->end(), {{2, band.upper}, {2, band.lower}});
  return shapes;
}

/// The one surface a tool became in the fragment.
int SurfaceAfterFragment(const DimTags& produced) {
  for (const auto& [dim, tag] : produced)
    if (dim == 2) return tag;
  throw std::runtime_error("gmsh: a crack's mirror band vanished in the fragment");
}

/// gmsh's 2D mesher; its own errors (it throws strings) become one line naming the mesh options.
void generate_2d(const SpecimenGeometry& g) {
  try {
    gmsh::model::mesh::generate(2);
  } catch (const std::exception&) {
    throw;
  } catch (...) {
    char text[400];
    std::snprintf(text, sizeof(text),
                  "gmsh could not mesh the specimen with -mesh_h %g, -mesh_h_crack %g, -mesh_grading %g (its "
                  "recombination into quads failed): change -mesh_h_crack or -mesh_grading, or use -mesh_cell tri",
                  g.h, g.h_crack, g.grading);
    throw std::invalid_argument(text);
  }
}

}  // namespace

MeshData generate_specimen_mesh(const SpecimenGeometry& g) {
  GmshSession session;
  gmsh::model::add("specimen");
  const int rectangle = gmsh::model::occ::addRectangle(0, 0, 0, g.width, g.height);
  // Fragmenting embeds the crack lines (and their mirror bands, crack_mirror.hpp) in the
  // surface and splits outer edges where a crack ends on them, and at a transducer patch's
  // ends (a line on the edge).
  const CrackMirrorPlan plan = PlanCrackMirror(g, g.crack_mirror_width < 0.0 ? DefaultMirrorWidth(g) : g.crack_mirror_width);
  DimTags tools;
  const CrackShapes shapes = AddCracks(g, plan, &tools);
  if (g.patch.on) {
    const auto ends = g.patch_ends();
    const int a = gmsh::model::occ::addPoint(ends[0][0], ends[0][1], 0), b = gmsh::model::occ::addPoint(ends[1][0], ends[1][1], 0);
    tools.push_back({1, gmsh::model::occ::addLine(a, b)});
  }
  DimTags out;
  std::vector<DimTags> produced(1);
  if (!tools.empty()) gmsh::model::occ::fragment({{2, rectangle}}, tools, out, produced);
  gmsh::model::occ::synchronize();

  std::vector<std::vector<int>> crack_curves(g.cracks.size());
  std::vector<double> all_crack_curves;
  std::size_t next = 1;  // produced[0] is the rectangle's
  for (std::size_t i = 0; i < g.cracks.size(); ++i)
    for (std::size_t k = 0; k < shapes.lines[i].size(); ++k, ++next)
      for (const auto& [dim, tag] : produced[next])
        if (dim == 1) crack_curves[i].push_back(tag), all_crack_curves.push_back(tag);
  for (std::size_t k = 0; k < plan.bands.size(); ++k, next += 2)
    crack_mirror_gmsh::MirrorOutline(plan.bands[k], SurfaceAfterFragment(produced[next]),
                                     SurfaceAfterFragment(produced[next + 1]));

  set_size_field(g, all_crack_curves);
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // frontal-Delaunay: 8 crashes with embedded cracks
  if (g.quads) {
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);  // blossom
  }
  generate_2d(g);
  if (g.quads && has_triangles()) {
    // Strong grading can leave triangles after recombination: mesh at twice the
    // size and subdivide every element into quads (back to the requested size).
    SpecimenGeometry coarse = g;
    coarse.h *= 2.0;
    coarse.h_crack *= 2.0;
    gmsh::model::mesh::clear();
    set_size_field(coarse, all_crack_curves);
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
    generate_2d(g);
  }

  MeshData mesh = collect_rectangle_mesh(g, crack_curves, "gmsh");
  for (const CrackMirror& band : plan.bands) MirrorBandCells(band, &mesh);
  mesh.notes = plan.why;
  return mesh;
}

MeshData read_mesh_file(const std::string& path) {
  const std::string where = "-mesh_file " + path;
  GmshSession session;
  OpenFile(path, where);
  MeshData mesh;
  const NodeMap nodes = collect_nodes();
  mesh.coords = nodes.coords;
  collect_cells(nodes, mesh, where);

  DimTags groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  bool any_kind = false;
  for (const auto& [dim, group] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, group, name);
    std::vector<int> curves;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group, curves);
    std::vector<MeshEdge> edges;
    for (int c : curves) append(edges, curve_edges(nodes, c, 0));
    if (name.rfind("crack", 0) == 0) {
      const int id = static_cast<int>(mesh.crack_names.size());
      mesh.crack_names.push_back(name);
      for (MeshEdge& e : edges) e.tag = id;
      append(mesh.crack_edges, edges);
      continue;
    }
    if (name == "sink") {
      for (MeshEdge& e : edges) e.tag = 1;
      append(mesh.sink_edges, edges);
      continue;
    }
    bool known = false;
    for (EdgeKind kind : all_edge_kinds()) {
      if (name != to_string(kind)) continue;
      for (MeshEdge& e : edges) e.tag = static_cast<int>(kind);
      append(mesh.kind_edges, edges);
      known = any_kind = true;
    }
    if (!known) throw std::invalid_argument(where + ": unknown physical group '" + name + "' (known: " +
                                            edge_kind_names() + ", sink, crack*)");
  }
  if (!any_kind)
    throw std::invalid_argument(where + ": no boundary physical group (need at least one of " + edge_kind_names() +
                                ")");
  for (MeshEdge e : mesh.kind_edges) mesh.side_edges.push_back({e.v0, e.v1, -1});
  return mesh;
}

}  // namespace vibrotherm::mesh
