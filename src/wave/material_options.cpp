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

PetscErrorCode ReadElasticMaterial(MPI_Comm comm, ElasticMaterial* m) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "Elastic material (2D: plane strain; 3D: the box)", ElasticMaterialOptionSpecs(), m));
  PetscFunctionReturn(0);
}

PetscErrorCode ReadMaterialDamping(MPI_Comm comm, double source_frequency, ElasticMaterial* m) {
  PetscFunctionBeginUser;
  m->damping_frequency = source_frequency;
  PetscBool frequency_set = PETSC_FALSE;
  PetscOptionsBegin(comm, nullptr, "Material damping", nullptr);
  PetscCall(PetscOptionsReal("-material_loss_factor",
                             "Loss factor eta = 1/Q of the solid at -material_damping_frequency (0: no damping); "
                             "mass-proportional: C = eta 2 pi f_d M",
                             nullptr, m->loss_factor, &m->loss_factor, nullptr));
  PetscCall(PetscOptionsReal("-material_damping_frequency", "Frequency the loss factor holds at [Hz] (default: "
                             "-source_frequency)", nullptr, m->damping_frequency, &m->damping_frequency, &frequency_set));
  PetscBool heat = m->damping_heat ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(PetscOptionsBool("-material_damping_heat", "The energy material damping takes heats the specimen where it "
                             "is taken (a volume heat source; off: only the crack's friction heats)", nullptr, heat,
                             &heat, nullptr));
  m->damping_heat = heat;
  PetscOptionsEnd();
  PetscCheck(m->loss_factor >= 0.0 && m->loss_factor < 1.0, comm, PETSC_ERR_USER_INPUT,
             "-material_loss_factor must be in [0, 1), got %g", m->loss_factor);
  // A value the user gave is always checked; the default (the source's frequency) only when damping is on,
  // so an unusable -source_frequency is refused under its own name.
  PetscCheck((!frequency_set && m->loss_factor == 0.0) || (m->damping_frequency > 0.0 && std::isfinite(m->damping_frequency)), comm,
             PETSC_ERR_USER_INPUT, "-material_damping_frequency must be > 0 and finite, got %g", m->damping_frequency);
  PetscCheck(!m->damping_heat || m->loss_factor > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-material_damping_heat needs material damping (-material_loss_factor > 0)");
  m->damping_rate = m->loss_factor * 2.0 * M_PI * m->damping_frequency;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
