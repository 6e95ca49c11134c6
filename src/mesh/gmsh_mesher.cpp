// gmsh → MeshData. One gmsh session per call (gmsh's API is a process-wide
// singleton): initialise, build or open, mesh, extract, finalise.
#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::mesh {
namespace {

using DimTags = std::vector<std::pair<int, int>>;

/// RAII for the gmsh session.
struct GmshSession {
  GmshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    // One thread: an error inside gmsh's OpenMP region would abort the process
    // instead of reaching our error handling.
    gmsh::option::setNumber("General.NumThreads", 1);
    gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
  }
  ~GmshSession() {
    try {  // may run while a gmsh error unwinds the stack: never throw from here
      gmsh::finalize();
    } catch (...) {
    }
  }
};

/// gmsh node tags → dense 0-based vertex indices, with coordinates.
struct NodeMap {
  std::map<std::size_t, int> index;
  std::vector<double> coords;
  int operator()(std::size_t tag) const { return index.at(tag); }
};

NodeMap collect_nodes() {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, param;
  gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false);
  NodeMap map;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    map.index[tags[i]] = static_cast<int>(i);
    map.coords.push_back(xyz[3 * i]);
    map.coords.push_back(xyz[3 * i + 1]);
  }
  return map;
}

/// 2D cells of the whole model; rejects mixed or higher-order meshes.
void collect_cells(const NodeMap& nodes, MeshData& mesh, const std::string& where) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, node_tags;
  gmsh::model::mesh::getElements(types, tags, node_tags, 2, -1);
  std::size_t tri = 0, quad = 0;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i] == 2) tri += tags[i].size();
    else if (types[i] == 3) quad += tags[i].size();
    else throw std::invalid_argument(where + ": unsupported 2D element type " + std::to_string(types[i]) +
                                     " (linear triangles or quadrilaterals only)");
  }
  if (tri + quad == 0) throw std::invalid_argument(where + ": the mesh has no 2D cells");
  if (tri && quad) throw std::invalid_argument(where + ": mixed triangles and quadrilaterals are not supported");
  mesh.corners = quad ? 4 : 3;
  for (std::size_t i = 0; i < types.size(); ++i)
    for (std::size_t n : node_tags[i]) mesh.cells.push_back(nodes(n));
}

/// Mesh edges (2-node lines) of a model curve.
std::vector<MeshEdge> curve_edges(const NodeMap& nodes, int curve, int tag) {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, node_tags;
  gmsh::model::mesh::getElements(types, tags, node_tags, 1, curve);
  std::vector<MeshEdge> edges;
  for (std::size_t i = 0; i < types.size(); ++i) {
    if (types[i] != 1) throw std::invalid_argument("curve " + std::to_string(curve) + ": only linear edges are supported");
    for (std::size_t k = 0; k + 1 < node_tags[i].size(); k += 2)
      edges.push_back({nodes(node_tags[i][k]), nodes(node_tags[i][k + 1]), tag});
  }
  return edges;
}

void append(std::vector<MeshEdge>& to, const std::vector<MeshEdge>& from) { to.insert(to.end(), from.begin(), from.end()); }

/// Whether the current 2D mesh contains triangles.
bool has_triangles() {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i] == 2 && !tags[i].empty()) return true;
  return false;
}

/// Size field: h_crack within a band around the cracks, growing by `grading` per metre to h.
void set_size_field(const SpecimenGeometry& g, const std::vector<double>& crack_curves) {
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", g.h);
  if (crack_curves.empty()) {
    gmsh::option::setNumber("Mesh.MeshSizeMin", g.h);
    return;
  }
  const int distance = gmsh::model::mesh::field::add("Distance");
  gmsh::model::mesh::field::setNumbers(distance, "CurvesList", crack_curves);
  gmsh::model::mesh::field::setNumber(distance, "NumPointsPerCurve",
                                      std::max(100.0, 4.0 * g.cracks.front().length / g.h_crack));
  const int threshold = gmsh::model::mesh::field::add("Threshold");
  gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
  gmsh::model::mesh::field::setNumber(threshold, "SizeMin", g.h_crack);
  gmsh::model::mesh::field::setNumber(threshold, "SizeMax", g.h);
  gmsh::model::mesh::field::setNumber(threshold, "DistMin", g.h_crack);
  gmsh::model::mesh::field::setNumber(threshold, "DistMax", g.h_crack + (g.h - g.h_crack) / g.grading);
  gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
}

}  // namespace

MeshData generate_specimen_mesh(const SpecimenGeometry& g) {
  GmshSession session;
  gmsh::model::add("specimen");
  const int rectangle = gmsh::model::occ::addRectangle(0, 0, 0, g.width, g.height);
  DimTags cracks;
  for (const Crack& c : g.cracks) {
    const auto p0 = c.end(0), p1 = c.end(1);
    const int a = gmsh::model::occ::addPoint(p0[0], p0[1], 0), b = gmsh::model::occ::addPoint(p1[0], p1[1], 0);
    cracks.push_back({1, gmsh::model::occ::addLine(a, b)});
  }
  // Fragmenting embeds the crack lines in the surface and splits outer edges
  // where a crack ends on them.
  DimTags out;
  std::vector<DimTags> produced(1);
  if (!cracks.empty()) gmsh::model::occ::fragment({{2, rectangle}}, cracks, out, produced);
  gmsh::model::occ::synchronize();

  std::vector<std::vector<int>> crack_curves(g.cracks.size());
  std::vector<double> all_crack_curves;
  for (std::size_t i = 0; i < g.cracks.size(); ++i)
    for (const auto& [dim, tag] : produced[i + 1])
      if (dim == 1) crack_curves[i].push_back(tag), all_crack_curves.push_back(tag);

  set_size_field(g, all_crack_curves);
  gmsh::option::setNumber("Mesh.Algorithm", 6);  // frontal-Delaunay: 8 crashes with embedded cracks
  if (g.quads) {
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.RecombinationAlgorithm", 1);  // blossom
  }
  gmsh::model::mesh::generate(2);
  if (g.quads && has_triangles()) {
    // Strong grading can leave triangles after recombination: mesh at twice the
    // size and subdivide every element into quads (back to the requested size).
    SpecimenGeometry coarse = g;
    coarse.h *= 2.0;
    coarse.h_crack *= 2.0;
    gmsh::model::mesh::clear();
    set_size_field(coarse, all_crack_curves);
    gmsh::option::setNumber("Mesh.SubdivisionAlgorithm", 1);
    gmsh::model::mesh::generate(2);
  }

  MeshData mesh;
  const NodeMap nodes = collect_nodes();
  mesh.coords = nodes.coords;
  collect_cells(nodes, mesh, "gmsh");

  // Outer curves: classify by the side their midpoint lies on.
  DimTags surfaces;
  gmsh::model::getEntities(surfaces, 2);
  DimTags boundary;
  gmsh::model::getBoundary(surfaces, boundary, true, false, false);
  const double tol = 1e-9 * std::max(g.width, g.height);
  for (const auto& [dim, signed_tag] : boundary) {
    const int curve = std::abs(signed_tag);
    double xmin, ymin, zmin, xmax, ymax, zmax;
    gmsh::model::getBoundingBox(1, curve, xmin, ymin, zmin, xmax, ymax, zmax);
    const double xm = 0.5 * (xmin + xmax), ym = 0.5 * (ymin + ymax);
    Side side = Side::Bottom;
    if (std::abs(ym) <= tol) side = Side::Bottom;
    else if (std::abs(xm - g.width) <= tol) side = Side::Right;
    else if (std::abs(ym - g.height) <= tol) side = Side::Top;
    else if (std::abs(xm) <= tol) side = Side::Left;
    else continue;  // not an outer curve
    const auto edges = curve_edges(nodes, curve, static_cast<int>(side));
    append(mesh.side_edges, edges);
    for (MeshEdge e : edges) {
      e.tag = static_cast<int>(g.edges[static_cast<int>(side)]);
      mesh.kind_edges.push_back(e);
      mesh.sink_edges.push_back({e.v0, e.v1, 1});  // default thermal condition: all outer edges are sinks
    }
  }
  for (std::size_t i = 0; i < g.cracks.size(); ++i) {
    mesh.crack_names.push_back("crack" + std::to_string(i + 1));
    for (int curve : crack_curves[i]) append(mesh.crack_edges, curve_edges(nodes, curve, static_cast<int>(i)));
  }
  return mesh;
}

MeshData read_mesh_file(const std::string& path) {
  const std::string where = "-mesh_file " + path;
  if (!std::ifstream(path)) throw std::invalid_argument(where + ": cannot open the file");
  GmshSession session;
  try {
    gmsh::open(path);
  } catch (...) {
    throw std::invalid_argument(where + ": gmsh cannot read it");
  }
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
