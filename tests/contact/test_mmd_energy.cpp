// Requirement: the MMD dissipation is the exact friction work of the spring bed
// along each straight step, so every energy identity closes (PHYSICS.md §3.4):
// a step split into substeps dissipates the same; ΣΔW = loop area over steady
// cycles (partial slip, combined, total sliding, contact loss) with errors that
// fall with the step; W_ext = ΔU + ΣΔW to second order.
#include <gtest/gtest.h>

#include <random>

#include "contact_test_support.hpp"

namespace vibrotherm::contact {
namespace {

using testing::drive;
using testing::Path;

ContactParameters biwa_params(double mu = 1.0) {
  ContactParameters p;
  p.mu = mu;
  p.nu = 0.33;
  p.normal_law = "biwa";  // N = 1e22 a² with the defaults
  return p;
}

// One straight step in (a, b) must dissipate what the same path split into
// 1000 substeps dissipates, and leave the same diagram: the closed-form
// integral is exact for the path.
TEST(MmdExactness, OneStepEqualsItsSubsteps) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (const char* normal : {"biwa", "power", "linear"}) {
    ContactParameters p = biwa_params(0.8);
    p.normal_law = normal;
    if (p.normal_law == "power") p.power_C = 1e18;
    const double scale = 1e-8, tm = p.theta() * p.mu;
    for (int trial = 0; trial < 200; ++trial) {
      auto big = testing::one_cell(p, scale, 0.0);
      auto fine = testing::one_cell(p, scale, 0.0);
      // A random prehistory builds a diagram with memory.
      double a = scale, b = 0.0;
      for (int k = 0; k < 6; ++k) {
        a = std::max(0.2 * scale, a + 0.5 * scale * U(rng));
        b += 0.8 * tm * scale * U(rng);
        big->commit(0, a, Tangential(b));
        fine->commit(0, a, Tangential(b));
      }
      const double a2 = a + 0.7 * scale * U(rng), b2 = b + 0.7 * tm * scale * U(rng);
      const StepResult one = big->commit(0, a2, Tangential(b2));
      double W_fine = 0.0;
      StepResult r;
      for (int k = 1; k <= 1000; ++k) {
        r = fine->commit(0, a + (a2 - a) * k / 1000.0, Tangential(b + (b2 - b) * k / 1000.0));
        W_fine += r.dW;
      }
      const double Wscale = p.mu * 1e22 * scale * scale * tm * scale;
      EXPECT_NEAR(one.dW, W_fine, 1e-9 * Wscale + 1e-9 * W_fine) << normal << " trial " << trial;
      EXPECT_NEAR(one.T[0], r.T[0], 1e-9 * p.mu * 1e22 * scale * scale) << normal << " trial " << trial;
      EXPECT_NEAR(big->stored_energy(0), fine->stored_energy(0), 1e-9 * Wscale) << normal << " trial " << trial;
      EXPECT_GE(one.dW, 0.0);
    }
  }
}

struct CycleCase {
  const char* name;
  double a_mean, a_amp, phase, b_amp;  // a in units of 1e-8 m, b in units of θμ·1e-8 m
};

/// ΣΔW over the third steady cycle and the loop area ∮2T db, with n steps per cycle.
testing::PathEnergy third_cycle(const ContactParameters& p, const CycleCase& c, int n) {
  const double s = 1e-8, tm = p.theta() * p.mu;
  const Path path = [&](double t, double& a, double& b) {
    a = s * (c.a_mean + c.a_amp * std::sin(2 * M_PI * t + c.phase));
    b = tm * s * c.b_amp * std::sin(2 * M_PI * t);
  };
  double a0, b0;
  path(0.0, a0, b0);
  auto law = testing::one_cell(p, a0, b0);
  drive(*law, path, 0.0, 2.0, 2 * n);
  return drive(*law, path, 2.0, 3.0, n);
}

const CycleCase kCycles[] = {
    {"pure tangential, partial slip", 1.0, 0.0, 0.0, 0.5},
    {"combined, phase shift", 1.0, 0.4, 0.7, 0.5},
    {"combined, total sliding", 1.0, 0.3, 1.2, 1.6},
    {"through contact loss", 0.4, 0.8, 0.4, 0.6},
};

TEST(MmdLoopInvariant, DissipationEqualsLoopAreaAndConverges) {
  const ContactParameters p = biwa_params();
  for (const CycleCase& c : kCycles) {
    const auto e3 = third_cycle(p, c, 1000);
    const auto e4 = third_cycle(p, c, 10000);
    ASSERT_GT(e4.dissipated, 0.0) << c.name;
    const double err3 = std::abs(e3.dissipated - e3.loop_area) / e3.dissipated;
    const double err4 = std::abs(e4.dissipated - e4.loop_area) / e4.dissipated;
    EXPECT_LT(err4, 1e-3) << c.name;
    // At least first order: ten times more steps, at least ~ten times smaller error.
    if (err3 > 1e-11) {
      EXPECT_LT(err4, err3 / 8.0) << c.name << ": " << err3 << " -> " << err4;
    }
    // A steady cycle stores no net energy: the external work is the dissipation.
    EXPECT_NEAR(e4.work_trap, e4.dissipated, 1e-3 * e4.dissipated) << c.name;
  }
}

// Per step, 2(NΔa + TΔb) = ΔU + ΔW to second order: the accumulated defect of
// identity A over a fixed path falls ~4x when the step halves. For every normal
// law: a flat contact (linear, N'(0+) > 0) puts a spring at α = 0 that must be
// counted once (it was counted twice, doubling its sliding loss).
TEST(MmdEnergyIdentity, ExternalWorkEqualsStoredPlusDissipatedToSecondOrder) {
  for (const char* normal : {"biwa", "power", "linear"}) {
    ContactParameters p = biwa_params();
    p.normal_law = normal;
    if (p.normal_law == "power") p.power_C = 1e18;
    const double s = 1e-8, tm = p.theta() * p.mu;
    const Path path = [&](double t, double& a, double& b) {  // start from a small a, not from 0
      a = s * (0.05 + 1.2 * t + 0.5 * std::sin(7.0 * t) * t);
      b = tm * s * (0.9 * std::sin(9.0 * t) + 0.3 * std::sin(23.0 * t));
    };
    double defect[3];
    int k = 0;
    for (int n : {2000, 4000, 8000}) {
      double a0, b0;
      path(0.0, a0, b0);
      auto law = testing::one_cell(p, a0, b0);
      const double U0 = law->stored_energy(0);
      const auto e = drive(*law, path, 0.0, 1.0, n);
      const double dU = law->stored_energy(0) - U0;
      defect[k++] = std::abs(e.work_trap - dU - e.dissipated) / e.dissipated;
      EXPECT_LT(defect[k - 1], 1e-3) << normal << ", " << n << " steps";
    }
    EXPECT_GT(defect[0] / defect[1], 3.0) << normal;
    EXPECT_GT(defect[1] / defect[2], 3.0) << normal;
  }
}

}  // namespace
}  // namespace vibrotherm::contact
