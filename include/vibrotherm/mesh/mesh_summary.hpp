// Counts and sizes of a specimen's meshes, reduced over all ranks.
#pragma once

#include <petscdmplex.h>

#include <optional>
#include <string>
#include <vector>

#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::mesh {

struct CrackSummary {
  std::string name;
  PetscInt facets = 0;       ///< cohesive cells
  PetscInt node_pairs = 0;   ///< split vertex pairs (the contact cells)
  PetscInt tips = 0;         ///< buried ends (vertices not split; 3D: the front's vertices)
  double length = 0.0;       ///< Σ facet lengths [m] (2D)
  double area = 0.0;         ///< Σ facet areas [m²] (3D)
  double requested_length = 0.0;
  std::optional<std::vector<std::string>> breaks;  ///< the faces it breaks, where the specimen knows (CrackInfo)
};

struct MeshSummary {
  int dimension = 2;
  std::string source, cell_type;
  int ranks = 1;
  PetscInt cells = 0;           ///< bulk cells of the wave mesh
  PetscInt cohesive_cells = 0;
  PetscInt vertices = 0;        ///< wave mesh (split vertices counted twice)
  PetscInt heat_cells = 0, heat_vertices = 0;
  std::string heat_source;                 ///< graded, wave or the heat mesh file
  double heat_h_min = 0.0, heat_h_max = 0.0;  ///< shortest and longest heat cell edge [m]
  std::vector<PetscInt> heat_cells_per_rank;
  std::vector<PetscInt> cells_per_rank;
  double h_min = 0.0, h_max = 0.0;  ///< shortest and longest bulk cell edge [m]
  std::vector<CrackSummary> cracks;
  double source_area = 0.0;  ///< 3D: Σ areas of the faces labelled source (the face or the patch) [m²]
};

PetscErrorCode ComputeMeshSummary(const Specimen& specimen, MeshSummary* summary);
/// Prints the summary on rank 0.
PetscErrorCode PrintMeshSummary(MPI_Comm comm, const MeshSummary& summary);

}  // namespace vibrotherm::mesh
