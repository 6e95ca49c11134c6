#include "gmsh_support.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace vibrotherm::mesh::gmsh_support {

GmshSession::GmshSession() {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  // One thread: an error inside gmsh's OpenMP region would abort the process
  // instead of reaching our error handling.
  gmsh::option::setNumber("General.NumThreads", 1);
  gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
}

void OpenFile(const std::string& path, const std::string& where) {
  if (!std::ifstream(path)) throw std::invalid_argument(where + ": cannot open the file");
  try {
    gmsh::open(path);
  } catch (const std::string& error) {  // gmsh throws its message (the file and line of a script's error)
    throw std::invalid_argument(where + ": gmsh cannot read it: " + error);
  } catch (...) {
    throw std::invalid_argument(where + ": gmsh cannot read it");
  }
}

GmshSession::~GmshSession() {
  try {  // may run while a gmsh error unwinds the stack: never throw from here
    gmsh::finalize();
  } catch (...) {
  }
}

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
  orient_counter_clockwise(mesh);
}

void orient_counter_clockwise(MeshData& mesh) {
  // gmsh orders a cell's nodes along its surface's orientation; DMPlex wants
  // them counter-clockwise (a clockwise cell has a negative Jacobian).
  const int k = mesh.corners;
  for (std::size_t c = 0; c + k <= mesh.cells.size(); c += k) {
    double area = 0.0;
    for (int i = 0; i < k; ++i) {
      const int a = mesh.cells[c + i], b = mesh.cells[c + (i + 1) % k];
      area += mesh.coords[2 * a] * mesh.coords[2 * b + 1] - mesh.coords[2 * b] * mesh.coords[2 * a + 1];
    }
    if (area < 0.0) std::reverse(mesh.cells.begin() + c + 1, mesh.cells.begin() + c + k);
  }
}

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

bool has_triangles() {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
  for (std::size_t i = 0; i < types.size(); ++i)
    if (types[i] == 2 && !tags[i].empty()) return true;
  return false;
}

void collect_rectangle_edges(const NodeMap& nodes, const SpecimenGeometry& g, MeshData& mesh) {
  DimTags surfaces, boundary;
  gmsh::model::getEntities(surfaces, 2);
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
    const double along = side == Side::Bottom || side == Side::Top ? xm : ym;
    const bool patch = g.patch.on && g.patch.side == side && along > g.patch.start() && along < g.patch.end();
    for (MeshEdge e : edges) {
      e.tag = static_cast<int>(patch ? EdgeKind::Source : g.edges[static_cast<int>(side)]);
      mesh.kind_edges.push_back(e);
      mesh.sink_edges.push_back({e.v0, e.v1, 1});  // default thermal condition: all outer edges are sinks
    }
  }
}

void set_graded_size(const std::vector<double>& curves, const GradedSize& size) {
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", size.size_max);
  if (curves.empty()) {
    gmsh::option::setNumber("Mesh.MeshSizeMin", size.size_max);
    return;
  }
  const int distance = gmsh::model::mesh::field::add("Distance");
  gmsh::model::mesh::field::setNumbers(distance, "CurvesList", curves);
  gmsh::model::mesh::field::setNumber(distance, "NumPointsPerCurve", size.points_per_curve);
  const int threshold = gmsh::model::mesh::field::add("Threshold");
  gmsh::model::mesh::field::setNumber(threshold, "InField", distance);
  gmsh::model::mesh::field::setNumber(threshold, "SizeMin", size.size_min);
  gmsh::model::mesh::field::setNumber(threshold, "SizeMax", size.size_max);
  gmsh::model::mesh::field::setNumber(threshold, "DistMin", size.dist_min);
  gmsh::model::mesh::field::setNumber(threshold, "DistMax", size.dist_max);
  gmsh::model::mesh::field::setAsBackgroundMesh(threshold);
}

std::pair<std::array<double, 2>, std::array<double, 2>> curve_end_points(int curve) {
  DimTags points;
  gmsh::model::getBoundary({{1, curve}}, points, false, false, false);
  if (points.size() != 2) throw std::runtime_error("gmsh: curve " + std::to_string(curve) + " is not an open line");
  std::array<std::array<double, 2>, 2> ends;
  for (int k = 0; k < 2; ++k) {
    std::vector<double> xyz;
    gmsh::model::getValue(0, std::abs(points[k].second), {}, xyz);
    ends[k] = {xyz[0], xyz[1]};
  }
  return {ends[0], ends[1]};
}

MeshData collect_rectangle_mesh(const SpecimenGeometry& g, const std::vector<std::vector<int>>& crack_curves,
                                const std::string& where) {
  MeshData mesh;
  const NodeMap nodes = collect_nodes();
  mesh.coords = nodes.coords;
  collect_cells(nodes, mesh, where);
  collect_rectangle_edges(nodes, g, mesh);
  for (std::size_t i = 0; i < crack_curves.size(); ++i) {
    mesh.crack_names.push_back("crack" + std::to_string(i + 1));
    for (int curve : crack_curves[i]) append(mesh.crack_edges, curve_edges(nodes, curve, static_cast<int>(i)));
  }
  return mesh;
}

}  // namespace vibrotherm::mesh::gmsh_support
