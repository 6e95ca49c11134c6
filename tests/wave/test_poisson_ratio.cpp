// Requirement: one Poisson ratio. The mmd crack law's Mindlin θ uses the
// material's -material_nu (no second option), read by the simulator's contact
// reader from the same PETSc options as the elastic material, with the same
// default.
#include <gtest/gtest.h>
#include <petscsys.h>

#include "vibrotherm/contact/contact_parameters.hpp"
#include "vibrotherm/interface/contact_options.hpp"
#include "vibrotherm/wave/material.hpp"

namespace vibrotherm {
namespace {

TEST(PoissonRatio, ContactAndMaterialReadTheSameOption) {
  EXPECT_EQ(contact::ContactParameters{}.nu, wave::ElasticMaterial{}.nu);  // same default
  ASSERT_EQ(PetscOptionsClear(nullptr), 0);
  ASSERT_EQ(PetscOptionsInsertString(nullptr, "-material_nu 0.25 -contact_biwa_C 2e11"), 0);
  contact::ContactParameters contact_params;
  wave::ElasticMaterial material;
  ASSERT_EQ(ReadContactOptions(PETSC_COMM_WORLD, contact_params), 0);
  ASSERT_EQ(wave::ReadElasticMaterial(PETSC_COMM_WORLD, &material), 0);
  EXPECT_EQ(contact_params.nu, 0.25);
  EXPECT_EQ(material.nu, 0.25);
  EXPECT_EQ(contact_params.biwa_C, 2e11);
  EXPECT_EQ(contact_params.theta(), (2 - 0.25) / (2 * (1 - 0.25)));
  ASSERT_EQ(PetscOptionsClear(nullptr), 0);
}

}  // namespace
}  // namespace vibrotherm
