#include "vibrotherm/heat/heat_probes.hpp"

#include <petscdmplex.h>

#include <cmath>

#include "vibrotherm/heat/heat_solver.hpp"

namespace vibrotherm::heat {
namespace {

/// Values of θ at located points, on every rank.
PetscErrorCode RiseAt(const fe::LagrangeSpace& space, Vec theta, const std::vector<fe::LocatedPoint>& points,
                      std::vector<double>* values) {
  PetscFunctionBeginUser;
  Vec local;
  PetscCall(DMGetLocalVector(space.dm(), &local));
  PetscCall(DMGlobalToLocal(space.dm(), theta, INSERT_VALUES, local));
  PetscCall(fe::EvaluateScalarAtPoints(space, local, points, values));
  PetscCall(DMRestoreLocalVector(space.dm(), &local));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode HeatProbes::Locate(const fe::LagrangeSpace& space, const std::vector<double>& points) {
  PetscFunctionBeginUser;
  space_ = &space;
  coordinates_ = points;
  std::vector<bool> inside;
  PetscCall(fe::LocatePoints(space, points, &points_, &inside));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatProbes::Temperatures(Vec theta, double T0, std::vector<double>* T) const {
  PetscFunctionBeginUser;
  PetscCall(RiseAt(*space_, theta, points_, T));
  for (double& t : *T) t += T0;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatProbes::Functional(std::size_t probe, Vec phi) const {
  PetscFunctionBeginUser;
  DM dm = space_->dm();
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  Vec local;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecSet(local, 0.0));
  const fe::LocatedPoint& p = points_.at(probe);
  if (p.cell >= 0) PetscCall(DMPlexVecSetClosure(dm, section, local, p.cell, p.phi.data(), INSERT_VALUES));
  PetscCall(VecSet(phi, 0.0));
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, phi));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

PetscErrorCode TemperatureAt(const HeatSolver& heat, const double* point, double* T) {
  PetscFunctionBeginUser;
  const fe::LagrangeSpace& space = heat.space();
  std::vector<fe::LocatedPoint> points;
  std::vector<bool> inside;
  PetscCall(fe::LocatePoints(space, std::vector<double>(point, point + space.dim()), &points, &inside));
  std::vector<double> values;
  PetscCall(RiseAt(space, heat.rise(), points, &values));
  *T = inside[0] ? heat.material().T0 + values[0] : NAN;
  PetscFunctionReturn(0);
}

PetscErrorCode TemperatureField(const HeatSolver& heat, Vec* T) {
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(heat.rise(), T));
  PetscCall(VecCopy(heat.rise(), *T));
  PetscCall(VecShift(*T, heat.material().T0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
