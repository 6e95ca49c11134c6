// The absorbing boundary's dashpots: per node a symmetric D×D block C (force
// −C v), stored as its upper triangle row by row, packed node after node —
// 2D: xx, xy, yy (3 numbers a node, as the 2D code has always had); 3D: xx, xy,
// xz, yy, yz, zz (6).
#pragma once

#include <petscsys.h>

#include <vector>

namespace vibrotherm::wave {

/// Where entry (i, j) of a symmetric D×D block lies in its packed upper triangle.
inline int UpperIndex(int i, int j, int D) {
  if (i > j) return UpperIndex(j, i, D);
  return i * D - i * (i - 1) / 2 + (j - i);
}

struct DashpotBlocks {
  int dim = 2;
  std::vector<PetscInt> nodes;  ///< owned node of each block
  std::vector<double> upper;    ///< the blocks' upper triangles, packed

  int stride() const { return dim * (dim + 1) / 2; }
  std::size_t size() const { return nodes.size(); }
  bool empty() const { return nodes.empty(); }
  void clear() {
    nodes.clear();
    upper.clear();
  }
  /// Adds the block of node whose upper triangle is entries (stride() of them).
  void Add(PetscInt node, const double* entries) {
    nodes.push_back(node);
    upper.insert(upper.end(), entries, entries + stride());
  }
  const double* block(std::size_t k) const { return &upper[k * stride()]; }
  /// Entry (i, j) of block k.
  double at(std::size_t k, int i, int j) const { return block(k)[UpperIndex(i, j, dim)]; }
};

}  // namespace vibrotherm::wave
