#include "vibrotherm/heat/crack_power.hpp"

#include <petscdmplex.h>

#include <utility>

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::heat {
namespace {

/// Q from a uniform power per unit area on each facet (this rank's, facet and crack index pairs).
PetscErrorCode FacetPowerLoad(const fe::LagrangeSpace& space, const std::vector<std::pair<PetscInt, int>>& facets,
                              const std::vector<double>& power, Vec Q) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  Vec local;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecSet(local, 0.0));
  PetscScalar* q;
  PetscCall(VecGetArray(local, &q));
  std::vector<PetscInt> offsets;
  std::vector<double> weights;
  for (const auto& [facet, crack] : facets) {
    PetscCheck(crack < static_cast<int>(power.size()), PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
               "crack power given for %zu cracks, crack %d exists", power.size(), crack + 1);
    double measure;
    PetscCall(space.FaceNodes(facet, &offsets, &weights, &measure));
    for (std::size_t j = 0; j < offsets.size(); ++j) q[offsets[j]] += power[crack] * weights[j];
  }
  PetscCall(VecRestoreArray(local, &q));
  PetscCall(VecSet(Q, 0.0));
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, Q));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode CrackPowerLoad(const fe::LagrangeSpace& space, const std::vector<double>& power, Vec Q) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  DMLabel crack;
  PetscCall(DMGetLabel(dm, mesh::labels::crack, &crack));
  std::vector<bool> ghost;  // a facet on the partition boundary counts once, on its owner
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscInt chart0, fStart, fEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(mesh::FacetRange(dm, &fStart, &fEnd));
  std::vector<std::pair<PetscInt, int>> facets;
  for (PetscInt f = fStart; f < fEnd && crack; ++f) {
    PetscInt value;
    PetscCall(DMLabelGetValue(crack, f, &value));
    if (value >= 1 && !ghost[f - chart0]) facets.emplace_back(f, static_cast<int>(value - 1));
  }
  PetscCall(FacetPowerLoad(space, facets, power, Q));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
