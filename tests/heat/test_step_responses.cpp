// Requirement: HeatSolver::StepResponses is the coupled integrator's own
// response of a probe to a load: with θ = 0 at the start and loads q_n Q in
// steps of unequal lengths, the probe's rise after the last step equals
// Σ_k q_{n−k} w_kᵀQ to rounding (the crack probes' near field subtracts exactly
// this from the heat field), serial and on 2 ranks.
#include <cmath>

#include "mesh_test_support.hpp"
#include "vibrotherm/heat/heat_probes.hpp"
#include "vibrotherm/heat/heat_solver.hpp"

namespace vibrotherm::testing {
namespace {

TEST(StepResponses, ReproduceTheProbeThroughUnequalSteps) {
  ScopedSpecimen s("-specimen_width 0.01 -specimen_height 0.01 -mesh_h 0.001 -mesh_h_crack 2.5e-4 "
                   "-crack_center 0.005,0.005 -crack_length 0.004 -crack_angle 20");
  ASSERT_EQ(s.status, 0);
  heat::HeatOptions options;
  ASSERT_EQ(heat::ReadHeatOptions(PETSC_COMM_WORLD, 2700.0, &options), 0);
  heat::HeatSolver solver;
  ASSERT_EQ(solver.Setup(s.specimen.heat, options), 0);
  heat::HeatProbes probes;
  ASSERT_EQ(probes.Locate(solver.space(), {0.005, 0.005, 0.0062, 0.0051}), 0);
  Vec Q, phi;
  ASSERT_EQ(DMCreateGlobalVector(s.specimen.heat, &Q), 0);
  ASSERT_EQ(VecDuplicate(Q, &phi), 0);
  PetscRandom random;
  ASSERT_EQ(PetscRandomCreate(PETSC_COMM_WORLD, &random), 0);
  ASSERT_EQ(PetscRandomSetSeed(random, 23), 0);
  ASSERT_EQ(PetscRandomSeed(random), 0);
  ASSERT_EQ(VecSetRandom(Q, random), 0);
  ASSERT_EQ(PetscRandomDestroy(&random), 0);
  const std::vector<double> lengths = {4e-7, 4e-7, 5e-7, 2e-7, 4e-7, 4e-7, 3e-7};  // in time order
  const std::vector<double> power = {1.0, -0.3, 2.0, 0.5, 0.0, 1.5, 0.7};
  Vec load;
  ASSERT_EQ(VecDuplicate(Q, &load), 0);
  double t = 0.0;
  for (std::size_t n = 0; n < lengths.size(); ++n) {
    ASSERT_EQ(VecAXPBY(load, power[n], 0.0, Q), 0);
    ASSERT_EQ(solver.SetSourceLoad(load), 0);
    t += lengths[n];
    ASSERT_EQ(solver.AdvanceInSteps(t, 1), 0);
  }
  std::vector<double> T;
  ASSERT_EQ(probes.Temperatures(solver.rise(), options.material.T0, &T), 0);
  const std::vector<double> newest_first(lengths.rbegin(), lengths.rend());
  for (std::size_t p = 0; p < T.size(); ++p) {
    ASSERT_EQ(probes.Functional(p, phi), 0);
    PetscScalar rise;  // φᵀθ: the probe's rise without T0's rounding
    ASSERT_EQ(VecDot(phi, solver.rise(), &rise), 0);
    EXPECT_NEAR(PetscRealPart(rise), T[p] - options.material.T0, 1e-12 * options.material.T0) << "probe " << p;
    std::vector<Vec> w;
    bool supported;
    ASSERT_EQ(solver.StepResponses(phi, newest_first, &w, &supported), 0);
    ASSERT_TRUE(supported);
    ASSERT_EQ(w.size(), lengths.size());
    double predicted = 0.0;
    for (std::size_t k = 0; k < w.size(); ++k) {
      PetscScalar dot;
      ASSERT_EQ(VecDot(w[k], Q, &dot), 0);
      predicted += power[lengths.size() - 1 - k] * PetscRealPart(dot);
      ASSERT_EQ(VecDestroy(&w[k]), 0);
    }
    EXPECT_NEAR(predicted, PetscRealPart(rise), 1e-10 * std::abs(PetscRealPart(rise))) << "probe " << p;
  }
  for (Vec* v : {&Q, &phi, &load}) ASSERT_EQ(VecDestroy(v), 0);
}

}  // namespace
}  // namespace vibrotherm::testing
