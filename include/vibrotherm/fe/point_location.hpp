// Fixed points of a LagrangeSpace (probes, point sources): each point is
// assigned to exactly one rank, the lowest whose cells contain it, which keeps
// its cell and basis values. A point on a cell boundary is therefore never
// counted twice, and serial and parallel runs evaluate the same thing.
#pragma once

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::fe {

struct LocatedPoint {
  PetscInt cell = -1;       ///< local cell on the rank that evaluates the point, -1 elsewhere
  std::vector<double> phi;  ///< basis values there (nodes_per_cell)
};

/// Locates the points xy = (x0, y0, x1, y1, ...), dim() coordinates a point
/// (x0, y0, z0, ... in 3D). Collective. inside[i] is
/// false (on every rank) when no rank holds point i.
PetscErrorCode LocatePoints(const LagrangeSpace& space, const std::vector<double>& xy,
                            std::vector<LocatedPoint>* points, std::vector<bool>* inside);

/// Values of a scalar-per-node local vector at located points, summed onto every rank.
PetscErrorCode EvaluateScalarAtPoints(const LagrangeSpace& space, Vec local, const std::vector<LocatedPoint>& points,
                                      std::vector<double>* values);

}  // namespace vibrotherm::fe
