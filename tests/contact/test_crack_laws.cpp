// Requirement: every registered crack law follows the shared contract (trial
// = commit tractions, ΔW >= 0, energy identity), the simple laws match their
// closed forms, and bad input is rejected naming the option.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "contact_test_support.hpp"
#include "input_error_message.hpp"

namespace vibrotherm::contact {
namespace {

TEST(CrackLaws, EveryLawClosesTheEnergyIdentityOnACombinedCycle) {
  for (const auto& entry : crack_laws()) {
    ContactParameters p;
    p.crack_law = entry.name;
    p.linear_kt = p.coulomb_kt = 5e13;
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

// Checkpoints: a law restored from save_state into a fresh law (another cell's
// virgin state) continues bit for bit like the one never interrupted.
TEST(CrackLaws, EveryLawContinuesExactlyFromItsSavedState) {
  for (const auto& entry : crack_laws()) {
    ContactParameters p;
    p.crack_law = entry.name;
    const double s = 1e-8;
    const auto path = [&](int k, double& a, double& b) {
      a = s * (0.3 + 0.8 * std::sin(0.01 * k + 0.3));
      b = s * 0.6 * std::sin(0.013 * k) * (1.0 + 0.001 * k);
    };
    double a, b;
    path(0, a, b);
    auto original = testing::one_cell(p, a, b);
    for (int k = 1; k <= 700; ++k) path(k, a, b), original->commit(0, a, Tangential(b));
    const std::vector<double> saved = original->save_state(0);
    auto restored = testing::one_cell(p, 0.0, 0.0);
    restored->restore_state(0, saved.data(), saved.size());
    EXPECT_EQ(restored->save_state(0), saved) << entry.name;
    for (int k = 701; k <= 1400; ++k) {
      path(k, a, b);
      const StepResult x = original->commit(0, a, Tangential(b)), y = restored->commit(0, a, Tangential(b));
      ASSERT_EQ(x.N, y.N) << entry.name << " step " << k;
      ASSERT_EQ(x.T[0], y.T[0]) << entry.name << " step " << k;
      ASSERT_EQ(x.dW, y.dW) << entry.name << " step " << k;
      ASSERT_EQ(x.state, y.state) << entry.name << " step " << k;
    }
    EXPECT_EQ(original->stored_energy(0), restored->stored_energy(0)) << entry.name;
    EXPECT_THROW(restored->restore_state(0, saved.data(), saved.size() + 1), std::runtime_error) << entry.name;
  }
}

TEST(CrackLaws, LinearSlipIsSchoenbergsSpring) {
  ContactParameters p;
  p.crack_law = "linear";
  p.linear_kn = 3e13;
  p.linear_kt = 2e13;
  auto law = testing::one_cell(p, 0.0, 0.0);
  const StepResult r = law->commit(0, -2e-9, Tangential(5e-9));  // works in tension too
  EXPECT_DOUBLE_EQ(r.N, 3e13 * -2e-9);
  EXPECT_DOUBLE_EQ(r.T[0], 2e13 * 5e-9);
  EXPECT_EQ(r.dW, 0.0);
}

TEST(CrackLaws, CoulombSticksThenSlidesAtMuN) {
  ContactParameters p;
  p.crack_law = "coulomb";
  p.mu = 0.4;
  p.normal_law = "linear";
  p.linear_k = 1e14;
  p.coulomb_kt = 5e13;
  const double a = 1e-8, N = 1e14 * a, b_stick = p.mu * N / p.coulomb_kt;
  auto law = testing::one_cell(p, a, 0.0);
  EXPECT_DOUBLE_EQ(law->commit(0, a, Tangential(0.5 * b_stick)).T[0], 0.5 * p.mu * N);
  const StepResult r = law->commit(0, a, Tangential(3.0 * b_stick));
  EXPECT_EQ(r.state, ContactState::Slide);
  EXPECT_DOUBLE_EQ(r.T[0], p.mu * N);
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
  EXPECT_DOUBLE_EQ(law->commit(0, 2e-8, Tangential(1e-8)).N, normal->eval(2e-8).N);
  EXPECT_EQ(law->commit(0, 2e-8, Tangential(3e-8)).T[0], 0.0);
  EXPECT_EQ(law->commit(0, -1e-9, Tangential(0.0)).N, 0.0);
}

std::string error_of(const ContactParameters& p) {
  return testing::input_error_message([&] { create_crack_law(p); });
}

TEST(CrackLaws, BadInputIsNamed) {
  ContactParameters p;
  p.mu = -0.1;
  EXPECT_NE(error_of(p).find("-contact_mu must be >= 0"), std::string::npos);
  p = ContactParameters{};
  p.nu = 0.5;
  EXPECT_NE(error_of(p).find("-material_nu must be in (-1, 0.5)"), std::string::npos);
  p.nu = -1.0;
  EXPECT_NE(error_of(p).find("-material_nu"), std::string::npos);
  p = ContactParameters{};
  p.crack_law = "glue";
  EXPECT_NE(error_of(p).find("-crack_law: unknown value 'glue'"), std::string::npos);
  p = ContactParameters{};
  p.normal_law = "cubic";
  EXPECT_NE(error_of(p).find("-contact_normal_law: unknown value 'cubic'"), std::string::npos);
  p = ContactParameters{};
  p.normal_law = "power";
  p.power_p = 0.5;
  EXPECT_NE(error_of(p).find("-contact_power_p must be in [1, 10]"), std::string::npos);
  p = ContactParameters{};
  p.biwa_C = -1e11;  // was a "law default" sentinel once
  EXPECT_NE(error_of(p).find("-contact_biwa_C must be > 0, got -1e+11"), std::string::npos);
  p = ContactParameters{};
  p.biwa_m = 1.0;
  EXPECT_NE(error_of(p).find("-contact_biwa_m"), std::string::npos);
  p = ContactParameters{};
  p.biwa_C = 1e300;  // in range, but K0 = (2(1-m)C_B)^2 overflows
  EXPECT_NE(error_of(p).find("-contact_biwa_C 1e+300 with -contact_biwa_m 0.5 overflows"), std::string::npos);
}

TEST(ContactParameters, EachLawDeclaresItsOwnOptions) {
  std::vector<std::string> names;
  for (const ContactParameter& param : contact_parameters()) names.push_back(param.spec.name);
  const std::vector<std::string> expected = {
      "-crack_law",        "-contact_normal_law", "-contact_mu",      "-contact_a0",
      "-crack_linear_kn",  "-crack_linear_kt",    "-crack_coulomb_kt", "-material_nu",
      "-crack_mmd_tol",    "-crack_mmd_max_breakpoints", "-crack_mmd_levels", "-contact_power_C", "-contact_power_p",
      "-contact_biwa_C",   "-contact_biwa_m",     "-contact_linear_k", "-contact_table_file"};
  EXPECT_EQ(names, expected);
  for (const NormalLawEntry& e : normal_laws())
    for (const ContactParameter& param : e.parameters())
      EXPECT_EQ(param.spec.name.rfind(std::string("-contact_") + e.name + "_", 0), 0u) << param.spec.name;
  for (const RenamedOption& r : renamed_contact_options())
    EXPECT_EQ(std::count(names.begin(), names.end(), r.old_name), 0) << r.old_name;
}

// Every real parameter refuses NaN, ±inf and values just outside its declared
// range, whichever law is selected, with a message naming the option.
TEST(ContactParameters, EveryNumberOutsideItsRangeIsRefusedNamingTheOption) {
  EXPECT_EQ(error_of(ContactParameters{}), "");  // the defaults are valid values
  int checked = 0;
  for (const ContactParameter& param : contact_parameters()) {
    const auto* field = std::get_if<double ContactParameters::*>(&param.field);
    if (!field) continue;
    const Range& r = param.spec.range;
    std::vector<double> bad = {std::nan(""), HUGE_VAL, -HUGE_VAL};
    if (std::isfinite(r.lo)) bad.push_back(r.lo_open ? r.lo : std::nextafter(r.lo, -HUGE_VAL));
    if (std::isfinite(r.hi)) bad.push_back(r.hi_open ? r.hi : std::nextafter(r.hi, HUGE_VAL));
    for (double v : bad) {
      ContactParameters p;
      p.crack_law = "open";  // a law that reads none of them
      p.*(*field) = v;
      EXPECT_EQ(error_of(p).rfind(param.spec.name + " must be", 0), 0u) << param.spec.name << " = " << v;
      ++checked;
    }
  }
  EXPECT_GE(checked, 3 * 11);
}

}  // namespace
}  // namespace vibrotherm::contact
