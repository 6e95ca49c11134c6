// The heat field read out at points: fixed probes (located once, read every step, or
// taken as linear functionals of the rise for the near-field correction and the
// partial rise), and one point on demand. It only reads a rise θ (a global vector of
// the heat DM); the solver that steps θ knows nothing of it.
#pragma once

#include <petscvec.h>

#include <cstddef>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/fe/point_location.hpp"

namespace vibrotherm::heat {

class HeatSolver;

class HeatProbes {
 public:
  /// Locates the points (x, y pairs; x, y, z triples on a 3D mesh) in `space` (kept, not
  /// owned: the heat solver's). Collective.
  PetscErrorCode Locate(const fe::LagrangeSpace& space, const std::vector<double>& points);
  std::size_t size() const { return points_.size(); }
  /// The points as located (the coordinates given, dim per point).
  const std::vector<double>& coordinates() const { return coordinates_; }
  /// Temperatures T0 + θ [K] at the points, on every rank. Collective.
  PetscErrorCode Temperatures(Vec theta, double T0, std::vector<double>* T) const;
  /// Probe p's rise as a linear functional of θ: sets phi (a global vector of the heat
  /// DM) to the heat basis at the point, φᵀθ = the rise there. Collective.
  PetscErrorCode Functional(std::size_t probe, Vec phi) const;

 private:
  const fe::LagrangeSpace* space_ = nullptr;
  std::vector<fe::LocatedPoint> points_;
  std::vector<double> coordinates_;
};

/// The temperature [K] of `heat` at a point of its mesh's dimension (x, y or x, y, z);
/// NaN outside the mesh. Collective.
PetscErrorCode TemperatureAt(const HeatSolver& heat, const double* point, double* T);
/// The temperature T0 + θ of `heat` as a new global vector of its DM (the field written out).
PetscErrorCode TemperatureField(const HeatSolver& heat, Vec* T);

}  // namespace vibrotherm::heat
