// Requirement: at constant approach the MMD reproduces Cattaneo–Mindlin partial
// slip (loading, Masing unloading/reloading, total sliding) exactly, and the
// Mindlin–Deresiewicz energy per cycle.
#include <gtest/gtest.h>

#include "contact_test_support.hpp"

namespace vibrotherm::contact {
namespace {

using testing::hertz_params;
using testing::one_cell;

struct Hertz {
  ContactParameters p = hertz_params();
  std::unique_ptr<NormalLaw> law = create_normal_law(p);
  double tm = p.theta() * p.mu;
  double N(double a) const { return law->eval(a).N; }
  double M(double a) const { return law->eval(a).M; }
  /// Virgin loading branch T(b) = μ[N(a) − N(a − b/(θμ))] (Cattaneo–Mindlin).
  double T_load(double a, double b) const { return p.mu * (N(a) - N(a - b / tm)); }
};

TEST(CattaneoMindlin, VirginLoadingBranchIsExact) {
  Hertz h;
  const double a = 2e-8;
  auto law = one_cell(h.p, a, 0.0);
  const double b_max = 0.9 * h.tm * a;
  for (int k = 1; k <= 500; ++k) {
    const double b = b_max * k / 500;
    const Traction t = law->trial(0, a, Tangential(b));
    const StepResult r = law->commit(0, a, Tangential(b));
    EXPECT_EQ(t.T[0], r.T[0]) << "trial and commit disagree";
    EXPECT_NEAR(r.T[0], h.T_load(a, b), 1e-12 * std::abs(h.T_load(a, b))) << "b = " << b;
    EXPECT_DOUBLE_EQ(r.N, h.N(a));
    EXPECT_EQ(r.state, ContactState::Partial);
  }
}

TEST(CattaneoMindlin, MasingUnloadingAndReloading) {
  Hertz h;
  const double a = 2e-8, bs = 0.6 * h.tm * a;
  auto law = one_cell(h.p, a, 0.0);
  const int n = 400;
  for (int k = 1; k <= n; ++k) law->commit(0, a, Tangential(bs * k / n));
  const double T_rev = h.T_load(a, bs);
  for (int k = 1; k <= 2 * n; ++k) {  // unload from +b* to −b*
    const double b = bs - 2 * bs * k / (2 * n);
    const double ref = T_rev - 2.0 * h.T_load(a, (bs - b) / 2.0);
    EXPECT_NEAR(law->commit(0, a, Tangential(b)).T[0], ref, 1e-12 * h.p.mu * h.N(a)) << "unloading b = " << b;
  }
  for (int k = 1; k <= 2 * n; ++k) {  // reload from −b* to +b*
    const double b = -bs + 2 * bs * k / (2 * n);
    const double ref = -T_rev + 2.0 * h.T_load(a, (b + bs) / 2.0);
    EXPECT_NEAR(law->commit(0, a, Tangential(b)).T[0], ref, 1e-12 * h.p.mu * h.N(a)) << "reloading b = " << b;
  }
}

TEST(CattaneoMindlin, TotalSlidingAtMuN) {
  Hertz h;
  const double a = 2e-8;
  auto law = one_cell(h.p, a, 0.0);
  const double b_slide = h.tm * a;
  for (int k = 1; k <= 300; ++k) {
    const StepResult r = law->commit(0, a, Tangential(1.5 * b_slide * k / 300));
    if (1.5 * b_slide * k / 300 >= b_slide * (1 + 1e-12)) {
      EXPECT_EQ(r.state, ContactState::Slide);
      EXPECT_NEAR(r.T[0], h.p.mu * h.N(a), 1e-12 * h.N(a));
    } else {
      EXPECT_LE(r.T[0], h.p.mu * h.N(a));
    }
  }
  EXPECT_NEAR(law->slip_offset(0)[0], 0.5 * b_slide, 1e-9 * b_slide);
  for (int k = 1; k <= 600; ++k) law->commit(0, a, Tangential(1.5 * b_slide - 3 * b_slide * k / 600));
  EXPECT_NEAR(law->trial(0, a, Tangential(-1.5 * b_slide)).T[0], -h.p.mu * h.N(a), 1e-12 * h.N(a));
}

/// W per steady cycle ±b* at constant a: 8θμ²[u(N(a) + N(a − u)) − 2(M(a) − M(a − u))], u = b*/(θμ).
TEST(CattaneoMindlin, MindlinDeresiewiczEnergyPerCycle) {
  Hertz h;
  const double a = 3e-8;
  for (double frac : {0.05, 0.3, 0.7, 0.99}) {
    const double bs = frac * h.tm * a, u = bs / h.tm;
    const double W_ref =
        8.0 * h.p.theta() * h.p.mu * h.p.mu * (u * (h.N(a) + h.N(a - u)) - 2.0 * (h.M(a) - h.M(a - u)));
    auto law = one_cell(h.p, a, 0.0);
    const testing::Path cycle = [&](double s, double& aa, double& b) {
      aa = a;
      b = bs * std::sin(2 * M_PI * s);
    };
    testing::drive(*law, cycle, 0.0, 1.0, 1000);  // first cycle: virgin loading
    const auto e = testing::drive(*law, cycle, 1.0, 2.0, 1000);
    EXPECT_NEAR(e.dissipated, W_ref, 1e-6 * W_ref) << "b*/(θμa) = " << frac;
    // The loop area converges to the same value (trapezoid, second order).
    EXPECT_NEAR(e.loop_area, W_ref, 1e-4 * W_ref);
  }
}

}  // namespace
}  // namespace vibrotherm::contact
