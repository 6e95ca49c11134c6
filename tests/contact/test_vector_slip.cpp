// Requirement: the crack laws take a tangential slip vector of two components
// (the 3D contract, PHYSICS.md §3.5). Coulomb returns radially onto the
// friction disk: on a circle its steady cycle dissipates the 2D Jenkins closed
// form 2·2πF√(r² − (F/k)²), converging at first order; a path of fixed
// direction at any angle is the one-component law to rounding; every step
// closes the energy identity on the dog-leg path radial return is exact for.
// Linear is k_t b per component (mmd with two components: test_mmd_vector).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contact_test_support.hpp"

namespace vibrotherm::contact {
namespace {

/// Coulomb on the linear normal law at a = 1e-8 m: F = μN = 5e5 Pa, F/k_t = 1e-8 m.
ContactParameters coulomb_params() {
  ContactParameters p = testing::on_linear_normal_law("coulomb");
  p.coulomb_kt = 5e13;
  return p;
}
constexpr double kApproach = 1e-8;

Tangential on_circle(double radius, double cycles) {
  return Tangential(radius * std::cos(2 * M_PI * cycles), radius * std::sin(2 * M_PI * cycles));
}

/// Dissipation of the 5th cycle on the circle of radius r (steady from the 3rd
/// on), and the largest |T|/(μN) met.
double steady_circle_energy(int steps_per_cycle, double r, double* largest_friction_ratio) {
  const ContactParameters p = coulomb_params();
  auto law = testing::one_cell(p, kApproach, on_circle(r, 0.0));
  const double muN = p.mu * p.linear_k * kApproach;
  double W = 0.0;
  *largest_friction_ratio = 0.0;
  for (int k = 1; k <= 5 * steps_per_cycle; ++k) {
    const StepResult s = law->commit(0, kApproach, on_circle(r, double(k) / steps_per_cycle));
    if (k > 4 * steps_per_cycle) W += s.dW;
    *largest_friction_ratio = std::max(*largest_friction_ratio, norm(s.T) / muN);
  }
  return W;
}

TEST(VectorSlip, CoulombOnACircleDissipatesTheJenkinsClosedFormAtFirstOrder) {
  const ContactParameters p = coulomb_params();
  const double F = p.mu * p.linear_k * kApproach, k = p.coulomb_kt, r = 2.0 * F / k;
  // 2D Jenkins element on a circle: F√(r² − (F/k)²) per radian; ×2 for the half displacements.
  const double exact = 2.0 * 2.0 * M_PI * F * std::sqrt(r * r - (F / k) * (F / k));
  double previous_error = 0.0;
  for (int steps : {100, 200, 400}) {
    double ratio;
    const double error = steady_circle_energy(steps, r, &ratio) / exact - 1.0;
    std::printf("circle, %d steps per cycle: relative error %.6g\n", steps, error);
    EXPECT_LT(std::abs(error), 2.0 / steps) << steps;
    EXPECT_LE(ratio, 1.0 + 1e-14) << "|T| <= mu N";
    if (previous_error != 0.0) {
      std::printf("  error ratio %.6g\n", previous_error / error);
      EXPECT_NEAR(previous_error / error, 2.0, 0.02) << "first order";
    }
    previous_error = error;
  }
}

TEST(VectorSlip, InsideTheStickRadiusACircleDissipatesNothing) {
  const ContactParameters p = coulomb_params();
  double ratio;
  EXPECT_EQ(steady_circle_energy(100, 0.9 * p.mu * p.linear_k * kApproach / p.coulomb_kt, &ratio), 0.0);
}

/// The combined cycle of test_crack_laws (contact loss included) as a scalar path s.
void combined_cycle(double t, double& a, double& s) {
  a = 1e-8 * (0.3 + 0.8 * std::sin(2 * M_PI * t + 0.3));
  s = 1e-8 * 0.6 * std::sin(2 * M_PI * t);
}

/// The largest difference between a law driven with one component along s(t)
/// and with two along s(t)·(cos φ, sin φ), relative to μN(a_max) or k_t b.
double collinear_difference(const ContactParameters& p, double angle) {
  const double c = std::cos(angle), sn = std::sin(angle);
  double a, s;
  combined_cycle(0.0, a, s);
  auto one = testing::one_cell(p, a, s), two = testing::one_cell(p, a, Tangential(s * c, s * sn));
  const double scale = 1e14 * 1.1e-8, energy_scale = scale * 1e-8;  // traction, dissipation per step
  double largest = 0.0;
  auto differ = [&](double x, double y, double unit) { largest = std::max(largest, std::abs(x - y) / unit); };
  for (int k = 1; k <= 3000; ++k) {
    combined_cycle(k / 1000.0, a, s);
    const StepResult r1 = one->commit(0, a, Tangential(s)), r2 = two->commit(0, a, Tangential(s * c, s * sn));
    EXPECT_EQ(r1.state, r2.state) << p.crack_law << " step " << k;
    differ(r1.N, r2.N, scale);
    differ(r1.T[0], r2.T[0] * c + r2.T[1] * sn, scale);
    differ(0.0, r2.T[1] * c - r2.T[0] * sn, scale);
    differ(r1.dW, r2.dW, energy_scale);
    differ(one->stored_energy(0), two->stored_energy(0), energy_scale);
    const Tangential b0 = two->slip_offset(0);
    differ(one->slip_offset(0)[0], b0[0] * c + b0[1] * sn, 1e-8);
  }
  return largest;
}

TEST(VectorSlip, AFixedDirectionAtAnyAngleIsTheOneComponentLaw) {
  for (const char* name : {"coulomb", "linear", "clapping", "open"}) {
    ContactParameters p = coulomb_params();
    p.crack_law = name;
    EXPECT_EQ(collinear_difference(p, 0.0), 0.0) << name << ": along the first axis, bit for bit";
    for (double degrees : {30.0, 137.0, -90.0}) {
      const double d = collinear_difference(p, degrees * M_PI / 180.0);
      std::printf("%s at %g deg: largest relative difference %.3g\n", name, degrees, d);
      EXPECT_LT(d, 1e-14) << name << " at " << degrees << " deg";
    }
  }
}

TEST(VectorSlip, CoulombClosesTheEnergyIdentityEveryStep) {
  const ContactParameters p = coulomb_params();
  const double muN = p.mu * p.linear_k * kApproach;
  auto law = testing::one_cell(p, kApproach, testing::drifting_ellipse(muN / p.coulomb_kt, 0));
  double dissipated;
  const double worst = testing::worst_dog_leg_imbalance(*law, kApproach, muN, p.coulomb_kt, &dissipated);
  std::printf("energy identity per step: largest error %.3g of mu N rho\n", worst);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(dissipated, 10.0 * muN * muN / p.coulomb_kt) << "the path slips";
}

TEST(VectorSlip, LinearIsTheSpringPerComponent) {
  ContactParameters p;
  p.crack_law = "linear";
  p.linear_kn = 3e13;
  p.linear_kt = 2e13;
  auto law = testing::one_cell(p, 0.0, Tangential(0.0, 0.0));
  const StepResult r = law->commit(0, -2e-9, Tangential(5e-9, -3e-9));
  EXPECT_EQ(r.T.components(), 2);
  EXPECT_EQ(r.T[0], 2e13 * 5e-9);
  EXPECT_EQ(r.T[1], 2e13 * -3e-9);
  EXPECT_EQ(r.dW, 0.0);
  EXPECT_DOUBLE_EQ(law->stored_energy(0), 3e13 * 4e-18 + 2e13 * (25e-18 + 9e-18));
  const Traction t = law->trial(0, 1e-9, Tangential(-1e-9, 2e-9));
  EXPECT_EQ(t.T[0], 2e13 * -1e-9);
  EXPECT_EQ(t.T[1], 2e13 * 2e-9);
}

TEST(VectorSlip, CoulombWithTwoComponentsContinuesExactlyFromItsSavedState) {
  const ContactParameters p = coulomb_params();
  const double r = 2.0 * p.mu * p.linear_k * kApproach / p.coulomb_kt;
  auto original = testing::one_cell(p, kApproach, on_circle(r, 0.0));
  for (int k = 1; k <= 150; ++k) original->commit(0, kApproach, on_circle(r, k / 100.0));
  const std::vector<double> saved = original->save_state(0);
  EXPECT_EQ(saved.size(), 5u) << "a, b (2), b0 (2)";
  auto restored = testing::one_cell(p, 0.0, Tangential(0.0, 0.0));
  restored->restore_state(0, saved.data(), saved.size());
  for (int k = 151; k <= 300; ++k) {
    const StepResult x = original->commit(0, kApproach, on_circle(r, k / 100.0));
    const StepResult y = restored->commit(0, kApproach, on_circle(r, k / 100.0));
    ASSERT_EQ(x.T[0], y.T[0]) << k;
    ASSERT_EQ(x.T[1], y.T[1]) << k;
    ASSERT_EQ(x.dW, y.dW) << k;
  }
  auto one_component = testing::one_cell(p, 0.0, 0.0);
  EXPECT_THROW(one_component->restore_state(0, saved.data(), saved.size()), std::runtime_error);
}

}  // namespace
}  // namespace vibrotherm::contact
