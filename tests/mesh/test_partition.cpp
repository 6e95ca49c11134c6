// Requirement: the METIS partitioner distributes the split mesh with every cell
// owned once and balanced cell counts, and crack facets of the split (wave) mesh
// match the unsplit (heat) mesh one to one through the crack_face id.
#include <algorithm>
#include <numeric>

#include "mesh_test_support.hpp"

namespace vibrotherm::testing {
namespace {

const std::string kPaper = std::string("-options_file ") + VIBROTHERM_SOURCE_DIR + "/options/paper.opts";

/// crack_face ids of the owned crack faces of dm (or of the cohesive cells' first face).
std::vector<PetscInt> OwnedCrackFaceIds(DM dm, bool via_cohesive) {
  DMLabel ids;
  DMGetLabel(dm, mesh::labels::crack_face, &ids);
  std::vector<bool> ghost;
  mesh::GhostPoints(dm, &ghost);
  PetscInt chart0, start, end;
  DMPlexGetChart(dm, &chart0, nullptr);
  std::vector<PetscInt> out;
  if (via_cohesive) {
    DMPlexGetHeightStratum(dm, 0, &start, &end);
    for (PetscInt c = start; c < end; ++c) {
      bool cohesive;
      mesh::IsCohesiveCell(dm, c, &cohesive);
      if (!cohesive || ghost[c - chart0]) continue;
      const PetscInt* cone;
      DMPlexGetCone(dm, c, &cone);
      PetscInt a, b;
      DMLabelGetValue(ids, cone[0], &a);
      DMLabelGetValue(ids, cone[1], &b);
      EXPECT_EQ(a, b) << "the two faces of cohesive cell " << c << " carry different crack_face ids";
      out.push_back(a);
    }
  } else {
    DMPlexGetDepthStratum(dm, 1, &start, &end);
    for (PetscInt f = start; f < end; ++f) {
      PetscInt id;
      DMLabelGetValue(ids, f, &id);
      if (id >= 0 && !ghost[f - chart0]) out.push_back(id);
    }
  }
  return out;
}

TEST(MetisPartition, CellsOwnedOnceBalancedAndCrackFacetsMatch) {
  ScopedSpecimen s(kPaper + " -petscpartitioner_type metis -heat_mesh wave");
  ASSERT_EQ(s.status, 0);
  PetscMPIInt size;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  for (DM dm : {s.specimen.wave, s.specimen.heat}) {
    std::vector<bool> ghost;
    mesh::GhostPoints(dm, &ghost);
    PetscInt chart0, cStart, cEnd;
    DMPlexGetChart(dm, &chart0, nullptr);
    DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd);
    long long ghost_cells = 0;
    for (PetscInt c = cStart; c < cEnd; ++c) ghost_cells += ghost[c - chart0];
    EXPECT_EQ(Sum(ghost_cells), 0) << "a cell is not owned by the rank holding it";
    EXPECT_EQ(Sum(cEnd - cStart), dm == s.specimen.wave ? s.summary.cells + s.summary.cohesive_cells
                                                        : s.summary.heat_cells);
  }
  EXPECT_EQ(s.summary.cells, s.summary.heat_cells) << "splitting changed the number of bulk cells";
  const auto& per_rank = s.summary.cells_per_rank;
  ASSERT_EQ(static_cast<int>(per_rank.size()), size);
  const double mean = std::accumulate(per_rank.begin(), per_rank.end(), 0.0) / size;
  const auto [lo, hi] = std::minmax_element(per_rank.begin(), per_rank.end());
  EXPECT_LE((*hi - *lo) / mean, 0.10) << "cells per rank unbalanced";
  for (PetscInt n : per_rank) EXPECT_GT(n, 0);

  const auto wave_ids = AllGather(OwnedCrackFaceIds(s.specimen.wave, true));
  const auto heat_ids = AllGather(OwnedCrackFaceIds(s.specimen.heat, false));
  const PetscInt facets = s.summary.cracks.at(0).facets;
  std::vector<int> seen_wave(facets, 0), seen_heat(facets, 0);
  for (PetscInt id : wave_ids) {
    ASSERT_TRUE(id >= 0 && id < facets) << id;
    ++seen_wave[id];
  }
  for (PetscInt id : heat_ids) {
    ASSERT_TRUE(id >= 0 && id < facets) << id;
    ++seen_heat[id];
  }
  for (PetscInt id = 0; id < facets; ++id) {
    EXPECT_EQ(seen_wave[id], 1) << "crack_face " << id << " on the split mesh";
    EXPECT_EQ(seen_heat[id], 1) << "crack_face " << id << " on the unsplit mesh";
  }
}

}  // namespace
}  // namespace vibrotherm::testing
