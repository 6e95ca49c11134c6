// Prescribed crack heating (-physics heat -heat_crack_power): a uniform power per unit
// area on every crack facet, integrated against the heat basis into the load Q.
#include <petscdmplex.h>

#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::heat {

PetscErrorCode HeatSolver::SetCrackPower(const mesh::CrackSurface& cracks, const std::vector<double>& power) {
  PetscFunctionBeginUser;
  std::vector<std::pair<PetscInt, int>> facets;
  for (const mesh::OwnedCrackFacet& owned : cracks.owned())
    facets.emplace_back(owned.facet, cracks.facets()[owned.index].crack);
  PetscCall(SetFacetPower(facets, power));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::SetLabelledCrackPower(const std::vector<double>& power) {
  PetscFunctionBeginUser;
  DMLabel crack;
  PetscCall(DMGetLabel(dm_, mesh::labels::crack, &crack));
  std::vector<bool> ghost;  // a facet on the partition boundary counts once, on its owner
  PetscCall(mesh::GhostPoints(dm_, &ghost));
  PetscInt chart0, fStart, fEnd;
  PetscCall(DMPlexGetChart(dm_, &chart0, nullptr));
  PetscCall(mesh::FacetRange(dm_, &fStart, &fEnd));
  std::vector<std::pair<PetscInt, int>> facets;
  for (PetscInt f = fStart; f < fEnd && crack; ++f) {
    PetscInt value;
    PetscCall(DMLabelGetValue(crack, f, &value));
    if (value >= 1 && !ghost[f - chart0]) facets.emplace_back(f, static_cast<int>(value - 1));
  }
  PetscCall(SetFacetPower(facets, power));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::SetFacetPower(const std::vector<std::pair<PetscInt, int>>& facets,
                                         const std::vector<double>& power) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(source_event_, 0, 0, 0, 0));
  Vec local;
  PetscCall(DMGetLocalVector(dm_, &local));
  PetscCall(VecSet(local, 0.0));
  PetscScalar* q;
  PetscCall(VecGetArray(local, &q));
  std::vector<PetscInt> offsets;
  std::vector<double> weights;
  for (const auto& [facet, crack] : facets) {
    PetscCheck(crack < static_cast<int>(power.size()), PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ,
               "crack power given for %zu cracks, crack %d exists", power.size(), crack + 1);
    double measure;
    PetscCall(space_.FaceNodes(facet, &offsets, &weights, &measure));
    for (std::size_t j = 0; j < offsets.size(); ++j) q[offsets[j]] += power[crack] * weights[j];
  }
  PetscCall(VecRestoreArray(local, &q));
  PetscCall(VecSet(Q_, 0.0));
  PetscCall(DMLocalToGlobal(dm_, local, ADD_VALUES, Q_));
  PetscCall(DMRestoreLocalVector(dm_, &local));
  PetscCall(SetSourceLoad(Q_));
  PetscCall(PetscLogEventEnd(source_event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
