#include "vibrotherm/wave/material.hpp"

namespace vibrotherm::wave {

const std::vector<OptionSpec<ElasticMaterial>>& ElasticMaterialOptionSpecs() {
  using M = ElasticMaterial;
  using contact::Range;
  static const std::vector<OptionSpec<M>> specs = {
      RealOption("-material_density", &M::density, Range::positive(), "kg/m^3", "Density"),
      RealOption("-material_E", &M::E, Range::positive(), "Pa", "Young's modulus"),
      RealOption("-material_nu", &M::nu, Range::open(-1.0, 0.5), "", "Poisson ratio"),
  };
  return specs;
}

PetscErrorCode ReadElasticMaterial(MPI_Comm comm, ElasticMaterial* m, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "Elastic material (2D: plane strain; 3D: the box)", ElasticMaterialOptionSpecs(), m, values));
  PetscFunctionReturn(0);
}

const std::vector<OptionSpec<ElasticMaterial>>& MaterialDampingOptionSpecs() {
  using M = ElasticMaterial;
  using contact::Range;
  static const std::vector<OptionSpec<M>> specs = {
      RealOption("-material_loss_factor", &M::loss_factor, Range::closed_open(0.0, 1.0), "",
                 "Loss factor eta = 1/Q of the solid at -material_damping_frequency (0: no damping); "
                 "mass-proportional: C = eta 2 pi f_d M"),
      GivenRealOption("-material_damping_frequency", &M::damping_frequency, Range::positive(), "Hz",
                      "Frequency the loss factor holds at (default: -source_frequency)"),
      FlagOption("-material_damping_heat", &M::damping_heat,
                 "The energy material damping takes heats the specimen where it is taken (a volume heat source; "
                 "off: only the crack's friction heats)"),
  };
  return specs;
}

PetscErrorCode ReadMaterialDamping(MPI_Comm comm, double source_frequency, ElasticMaterial* m, OptionValues* values) {
  PetscFunctionBeginUser;
  m->damping_frequency = source_frequency;
  PetscCall(ReadOptionSpecs(comm, "Material damping", MaterialDampingOptionSpecs(), m, values));
  // The default (the source's frequency) is checked only when damping is on, so an unusable
  // -source_frequency is refused under its own name.
  PetscCheck(m->loss_factor == 0.0 || (m->damping_frequency > 0.0 && std::isfinite(m->damping_frequency)), comm,
             PETSC_ERR_USER_INPUT, "-material_damping_frequency must be > 0 and finite, got %g", m->damping_frequency);
  PetscCheck(!m->damping_heat || m->loss_factor > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-material_damping_heat needs material damping (-material_loss_factor > 0)");
  m->damping_rate = m->loss_factor * 2.0 * M_PI * m->damping_frequency;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
