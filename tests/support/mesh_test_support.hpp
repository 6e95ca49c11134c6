// Building a specimen from an options string inside a test, and gathering
// what the checks need from all ranks.
#pragma once

#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <array>
#include <string>
#include <vector>

#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/mesh_summary.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::testing {

/// A specimen built from `options` (replacing all options), destroyed with the object.
struct ScopedSpecimen {
  mesh::Specimen specimen;
  mesh::MeshSummary summary;
  PetscErrorCode status = 0;
  explicit ScopedSpecimen(const std::string& options) {
    status = PetscOptionsClear(nullptr);
    if (!status) status = PetscOptionsInsertString(nullptr, options.c_str());
    coupling::Scene scene;
    if (!status) status = coupling::ReadScene(PETSC_COMM_WORLD, &scene);
    if (!status) status = mesh::SpecimenCreate(PETSC_COMM_WORLD, scene.specimen, scene.exchange_length(), &specimen);
    if (!status) status = mesh::ComputeMeshSummary(specimen, &summary);
  }
  ~ScopedSpecimen() { (void)mesh::SpecimenDestroy(&specimen); }
};

/// All ranks' values, concatenated (every rank gets the whole list).
template <class T>
std::vector<T> AllGather(const std::vector<T>& mine) {
  int n = static_cast<int>(mine.size() * sizeof(T)), size;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  std::vector<int> counts(size), displs(size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, PETSC_COMM_WORLD);
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<T> all((displs.back() + counts.back()) / sizeof(T));
  MPI_Allgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), displs.data(), MPI_BYTE, PETSC_COMM_WORLD);
  return all;
}

inline long long Sum(long long mine) {
  long long all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD);
  return all;
}

/// Coordinates of the owned vertices of dm satisfying keep(v).
template <class Keep>
std::vector<std::array<double, 2>> OwnedVertexCoordinates(DM dm, Keep keep) {
  mesh::VertexCoordinates x;
  std::vector<bool> ghost;
  PetscInt chart0, vStart, vEnd;
  std::vector<std::array<double, 2>> out;
  if (x.Setup(dm) || mesh::GhostPoints(dm, &ghost) || DMPlexGetChart(dm, &chart0, nullptr) ||
      DMPlexGetDepthStratum(dm, 0, &vStart, &vEnd))
    return out;
  for (PetscInt v = vStart; v < vEnd; ++v)
    if (!ghost[v - chart0] && keep(v)) out.push_back(x(v));
  return out;
}

}  // namespace vibrotherm::testing
