// Isotropic linear elastic material: plane strain in 2D, full 3D in 3D (PHYSICS.md §2).
#pragma once

#include <petscsys.h>

#include <cmath>
#include <vector>

#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::wave {

struct ElasticMaterial {
  double density = 2700.0;  ///< -material_density [kg/m^3] (aluminium)
  double E = 70e9;          ///< -material_E [Pa]
  double nu = 0.33;         ///< -material_nu
  /// Material damping C = α M (PHYSICS.md §2): α = η · 2π f_d from -material_loss_factor η at
  /// -material_damping_frequency f_d (default the source frequency). 0: none.
  double damping_rate = 0.0;
  double loss_factor = 0.0;        ///< η as given
  double damping_frequency = 0.0;  ///< f_d [Hz] it was fitted at
  bool damping_heat = false;       ///< -material_damping_heat: the damped energy heats the specimen

  double lambda() const { return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)); }
  double shear_modulus() const { return E / (2.0 * (1.0 + nu)); }
  /// Bulk wave speeds: P (dilatational) and S (shear), the same in plane strain and 3D.
  double cp() const { return std::sqrt((lambda() + 2.0 * shear_modulus()) / density); }
  double cs() const { return std::sqrt(shear_modulus() / density); }
};

/// -material_density, -material_E, -material_nu, declared (option_spec.hpp).
const std::vector<OptionSpec<ElasticMaterial>>& ElasticMaterialOptionSpecs();
/// Reads -material_density, -material_E, -material_nu (validated, named errors).
PetscErrorCode ReadElasticMaterial(MPI_Comm comm, ElasticMaterial* material, OptionValues* values = nullptr);
/// -material_loss_factor, -material_damping_frequency, -material_damping_heat, declared.
const std::vector<OptionSpec<ElasticMaterial>>& MaterialDampingOptionSpecs();
/// Reads -material_loss_factor and -material_damping_frequency (default: source_frequency) into
/// the damping rate. Collective.
PetscErrorCode ReadMaterialDamping(MPI_Comm comm, double source_frequency, ElasticMaterial* material, OptionValues* values = nullptr);

}  // namespace vibrotherm::wave
