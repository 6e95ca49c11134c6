#include <map>
#include <stdexcept>

#include "vibrotherm/mesh/mesh_data.hpp"

namespace vibrotherm::mesh {

void check_crack_lines(const MeshData& mesh, const std::string& where) {
  for (std::size_t c = 0; c < mesh.crack_names.size(); ++c) {
    std::map<int, int> degree;
    std::size_t edges = 0;
    for (const MeshEdge& e : mesh.crack_edges)
      if (e.tag == static_cast<int>(c)) ++degree[e.v0], ++degree[e.v1], ++edges;
    const std::string name = where + ": " + mesh.crack_names[c];
    if (edges < 2) throw std::invalid_argument(name + " is degenerate: fewer than 2 elements along it");
    int ends = 0;
    for (const auto& [v, d] : degree) {
      if (d > 2) throw std::invalid_argument(name + " branches");
      ends += d == 1;
    }
    if (ends != 2) throw std::invalid_argument(name + " is not one open line (" + std::to_string(ends) + " ends)");
    // One open chain: edges = vertices − 1.
    if (edges + 1 != degree.size()) throw std::invalid_argument(name + " is not one connected line");
  }
}

}  // namespace vibrotherm::mesh
