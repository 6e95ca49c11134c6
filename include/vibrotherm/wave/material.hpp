// Isotropic linear elastic material in plane strain (PHYSICS.md §2).
#pragma once

#include <petscsys.h>

#include <cmath>

namespace vibrotherm::wave {

struct ElasticMaterial {
  double density = 2700.0;  ///< -material_density [kg/m^3] (aluminium)
  double E = 70e9;          ///< -material_E [Pa]
  double nu = 0.33;         ///< -material_nu

  double lambda() const { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
  double shear_modulus() const { return E / (2.0 * (1.0 + nu)); }
  /// Bulk wave speeds: P (dilatational) and S (shear), plane strain.
  double cp() const { return std::sqrt((lambda() + 2.0 * shear_modulus()) / density); }
  double cs() const { return std::sqrt(shear_modulus() / density); }
};

/// Reads -material_density, -material_E, -material_nu (validated, named errors).
PetscErrorCode ReadElasticMaterial(MPI_Comm comm, ElasticMaterial* material);

}  // namespace vibrotherm::wave
