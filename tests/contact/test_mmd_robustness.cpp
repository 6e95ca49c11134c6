// Requirement: under long noisy histories the MMD stays bounded in memory,
// |T| <= μN, finite, ΔW >= 0; trial evaluations never change the committed state.
#include <gtest/gtest.h>

#include <random>

#include "contact_test_support.hpp"
#include "vibrotherm/contact/memory_diagram.hpp"

namespace vibrotherm::contact {
namespace {

TEST(MmdRobustness, MillionNoisyStepsStayBounded) {
  ContactParameters p;
  p.mu = 0.6;
  const auto law = create_normal_law(p);
  const MmdConfig cfg{p.mu, p.theta(), p.mmd_rel_tol, static_cast<std::size_t>(p.mmd_max_breakpoints)};
  MemoryDiagram cell;
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, 1.0);
  const double s = 1e-8, tm = p.theta() * p.mu;
  double a = 0.5 * s, b = 0.0;
  cell.reset(*law, a, b);
  std::size_t max_points = 0;
  bool ok = true;
  for (int k = 0; k < 1000000 && ok; ++k) {
    // A slow drift (sometimes out of contact) plus white noise in both a and b.
    const double t = k * 1e-4;
    a = s * (0.4 * std::sin(0.37 * t) + 0.5) + 0.02 * s * noise(rng);
    b = tm * s * (0.8 * std::sin(t)) + 0.03 * tm * s * noise(rng);
    const StepResult r = cell.commit(*law, cfg, a, b);
    const double N = law->eval(a).N;
    const double T = r.T[0];
    ok = std::isfinite(T) && std::isfinite(r.dW) && r.dW >= 0.0 && std::abs(T) <= p.mu * N * (1 + 1e-9) + 1e-300;
    EXPECT_TRUE(ok) << "step " << k << ": T = " << r.T[0] << " muN = " << p.mu * N << " dW = " << r.dW;
    max_points = std::max(max_points, cell.breakpoints());
  }
  // Documented bound: -crack_mmd_max_breakpoints (1024 by default).
  EXPECT_LE(max_points, static_cast<std::size_t>(p.mmd_max_breakpoints));
  RecordProperty("max_breakpoints_seen", static_cast<int>(max_points));
}

TEST(MmdRobustness, TrialNeverChangesTheCommittedState) {
  ContactParameters p;
  auto probe = testing::one_cell(p, 1e-8, 0.0);
  auto plain = testing::one_cell(p, 1e-8, 0.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  double a = 1e-8, b = 0.0;
  for (int k = 0; k < 20000; ++k) {
    for (int stage = 0; stage < 4; ++stage) probe->trial(0, a + 1e-9 * U(rng), Tangential(b + 1e-9 * U(rng)));
    a = std::max(-2e-9, a + 2e-10 * U(rng));
    b += 5e-10 * U(rng);
    const Traction t = probe->trial(0, a, Tangential(b));
    const StepResult r1 = probe->commit(0, a, Tangential(b)), r2 = plain->commit(0, a, Tangential(b));
    ASSERT_EQ(r1.T[0], r2.T[0]);
    ASSERT_EQ(r1.dW, r2.dW);
    ASSERT_EQ(t.T[0], r1.T[0]);
    ASSERT_EQ(t.N, r1.N);
  }
}

TEST(MmdRobustness, FrictionlessMmdNeverDissipates) {
  ContactParameters p;
  p.mu = 0.0;
  auto law = testing::one_cell(p, 1e-8, 0.0);
  for (int k = 0; k < 1000; ++k) {
    const StepResult r = law->commit(0, 1e-8 * (0.5 + std::sin(0.1 * k)), Tangential(1e-8 * std::cos(0.13 * k)));
    ASSERT_EQ(r.T[0], 0.0);
    ASSERT_EQ(r.dW, 0.0);
  }
  EXPECT_FALSE(law->can_dissipate());
}

}  // namespace
}  // namespace vibrotherm::contact
