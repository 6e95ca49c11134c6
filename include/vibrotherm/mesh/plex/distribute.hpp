// Distributing a serial DMPlex with the partitioner the options choose.
#pragma once

#include <petscdmplex.h>

#include "vibrotherm/mesh/plex/point_origin.hpp"

namespace vibrotherm::mesh {

/// Distributes dm in place with the partitioner chosen by the options and names
/// it; origin: each new point's number in the serial mesh (checkpoint keys). Collective.
PetscErrorCode DistributeMesh(DM* dm, const char* name, PointOrigin* origin);

}  // namespace vibrotherm::mesh
