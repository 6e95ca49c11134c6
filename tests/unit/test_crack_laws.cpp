// Requirement: every registered crack law follows the shared contract (trial
// = commit tractions, ΔW >= 0, energy identity), the simple laws match their
// closed forms, and bad input is rejected naming the option.
#include <gtest/gtest.h>

#include "contact_test_support.hpp"

namespace vibrotherm::contact {
namespace {

TEST(CrackLaws, EveryLawClosesTheEnergyIdentityOnACombinedCycle) {
  for (const auto& entry : crack_laws()) {
    ContactParameters p;
    p.crack_law = entry.name;
    p.tangential_k = 5e13;
    const double s = 1e-8;
    const testing::Path path = [&](double t, double& a, double& b) {
      a = s * (0.3 + 0.8 * std::sin(2 * M_PI * t + 0.3));
      b = s * 0.6 * std::sin(2 * M_PI * t);
    };
    double a0, b0;
    path(0.0, a0, b0);
    auto law = testing::one_cell(p, a0, b0);
    const double U0 = law->stored_energy(0);
    const auto e = testing::drive(*law, path, 0.0, 3.0, 30000);
    const double dU = law->stored_energy(0) - U0;
    const double scale = e.work_abs;
    EXPECT_NEAR(e.work_trap, dU + e.dissipated, 1e-5 * scale) << entry.name;
    EXPECT_GE(e.dissipated, 0.0) << entry.name;
    if (!law->can_dissipate()) {
      EXPECT_EQ(e.dissipated, 0.0) << entry.name;
    }
  }
}

TEST(CrackLaws, LinearSlipIsSchoenbergsSpring) {
  ContactParameters p;
  p.crack_law = "linear";
  p.normal_k = 3e13;
  p.tangential_k = 2e13;
  auto law = testing::one_cell(p, 0.0, 0.0);
  const StepResult r = law->commit(0, -2e-9, 5e-9);  // works in tension too
  EXPECT_DOUBLE_EQ(r.N, 3e13 * -2e-9);
  EXPECT_DOUBLE_EQ(r.T, 2e13 * 5e-9);
  EXPECT_EQ(r.dW, 0.0);
}

TEST(CrackLaws, CoulombSticksThenSlidesAtMuN) {
  ContactParameters p;
  p.crack_law = "coulomb";
  p.mu = 0.4;
  p.normal_law = "linear";
  p.normal_k = 1e14;
  p.tangential_k = 5e13;
  const double a = 1e-8, N = 1e14 * a, b_stick = p.mu * N / p.tangential_k;
  auto law = testing::one_cell(p, a, 0.0);
  EXPECT_DOUBLE_EQ(law->commit(0, a, 0.5 * b_stick).T, 0.5 * p.mu * N);
  const StepResult r = law->commit(0, a, 3.0 * b_stick);
  EXPECT_EQ(r.state, ContactState::Slide);
  EXPECT_DOUBLE_EQ(r.T, p.mu * N);
  // Steady cycle ±b*: loop area 8 μN (b* − μN/k_t).
  const double bs = 3.0 * b_stick;
  const testing::Path cycle = [&](double t, double& aa, double& b) {
    aa = a;
    b = bs * std::cos(2 * M_PI * t);
  };
  testing::drive(*law, cycle, 0.0, 1.0, 1000);
  const auto e = testing::drive(*law, cycle, 1.0, 2.0, 1000);
  EXPECT_NEAR(e.dissipated, 8.0 * p.mu * N * (bs - b_stick), 1e-9 * e.dissipated);
}

TEST(CrackLaws, ClappingIsTheNormalLawAlone) {
  ContactParameters p;
  p.crack_law = "clapping";
  auto law = testing::one_cell(p, 0.0, 0.0);
  const auto normal = create_normal_law(p);
  EXPECT_DOUBLE_EQ(law->commit(0, 2e-8, 1e-8).N, normal->eval(2e-8).N);
  EXPECT_EQ(law->commit(0, 2e-8, 3e-8).T, 0.0);
  EXPECT_EQ(law->commit(0, -1e-9, 0.0).N, 0.0);
}

std::string error_of(const ContactParameters& p) {
  try {
    create_crack_law(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CrackLaws, BadInputIsNamed) {
  ContactParameters p;
  p.mu = -0.1;
  EXPECT_NE(error_of(p).find("-contact_mu"), std::string::npos);
  p = ContactParameters{};
  p.nu = 0.5;
  EXPECT_NE(error_of(p).find("-contact_nu"), std::string::npos);
  p.nu = -1.0;
  EXPECT_NE(error_of(p).find("-contact_nu"), std::string::npos);
  p = ContactParameters{};
  p.crack_law = "glue";
  EXPECT_NE(error_of(p).find("-crack_law: unknown law 'glue'"), std::string::npos);
  p = ContactParameters{};
  p.normal_law = "cubic";
  EXPECT_NE(error_of(p).find("-contact_normal_law: unknown law 'cubic'"), std::string::npos);
  p = ContactParameters{};
  p.normal_law = "power";
  p.normal_p = 0.5;
  EXPECT_NE(error_of(p).find("-contact_normal_p"), std::string::npos);
  p = ContactParameters{};
  p.normal_m = 1.0;
  EXPECT_NE(error_of(p).find("-contact_normal_m"), std::string::npos);
}

}  // namespace
}  // namespace vibrotherm::contact
