// Requirement: each normal law gives N, N' and M = ∫N consistently, is convex
// and increasing; Biwa's law has the interface stiffness it is defined by; the
// table law reproduces quadratic data exactly and rejects bad tables by line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

/// Checks N' against central differences of N, M against Simpson's rule on
/// N, and N' non-decreasing, over (0, a_max].
void expect_consistent(const NormalLaw& law, double a_max) {
  const int n = 2000;
  const double h = a_max / n;
  double prev_dN = 0.0, M_simpson = 0.0;
  for (int i = 1; i <= n; ++i) {
    const double a = i * h;
    const NormalLawValue v = law.eval(a);
    const double fd = (law.eval(a + 1e-4 * h).N - law.eval(a - 1e-4 * h).N) / (2e-4 * h);
    EXPECT_NEAR(v.dN, fd, 1e-5 * v.dN + 1e-9 * law.eval(a_max).dN) << law.name() << " a = " << a;
    EXPECT_GE(v.dN, prev_dN * (1 - 1e-12)) << law.name() << ": not convex at a = " << a;
    prev_dN = v.dN;
    // Simpson from the first node on (a^p is not smooth at 0): M(h) + ∫_h^a N.
    M_simpson = i == 1 ? v.M : M_simpson + h / 6.0 * (law.eval(a - h).N + 4.0 * law.eval(a - 0.5 * h).N + v.N);
    EXPECT_NEAR(v.M, M_simpson, 1e-8 * law.eval(a_max).M) << law.name() << " a = " << a;
  }
  EXPECT_EQ(law.eval(0.0).N, 0.0);
  EXPECT_EQ(law.eval(-1e-9).N, 0.0);
}

std::string csv_row(double a, double N) {
  std::ostringstream row;
  row.precision(17);
  row << a << "," << N << "\n";
  return row.str();
}

std::string write_table(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(NormalLaws, AllLawsAreConsistentAndConvex) {
  ContactParameters p;
  for (const auto& entry : normal_laws()) {
    p.normal_law = entry.name;
    if (p.normal_law == "table") {
      std::string text = "a,N\n";
      for (int i = 0; i <= 20; ++i) {  // convex, not polynomial
        const double a = 1e-9 * i * i;
        text += csv_row(a, 1e6 * (std::exp(a / 1e-7) - 1.0 - a / 1e-7));
      }
      p.table_file = write_table("convex.csv", text);
    }
    expect_consistent(*create_normal_law(p), 4e-7);
  }
}

TEST(NormalLaws, BiwaStiffnessIsCBTimesNToTheM) {
  ContactParameters p;
  p.normal_law = "biwa";
  for (double m : {0.3, 0.5, 0.8}) {
    p.biwa_m = m;
    p.biwa_C = 1e14 / std::pow(1e6, m);
    const auto law = create_normal_law(p);
    for (double a : {1e-10, 1e-9, 1e-8, 3e-8}) {
      const NormalLawValue v = law->eval(a);
      // K = dN/d(2a) = C_B N^m by definition (Biwa et al. 2004).
      EXPECT_NEAR(0.5 * v.dN, p.biwa_C * std::pow(v.N, m), 1e-12 * 0.5 * v.dN) << "m = " << m;
    }
  }
  // The declared default is the paper's: K = 1e14 Pa/m at N = 1 MPa.
  const auto law = create_normal_law(ContactParameters{});
  const double a_1MPa = 1e-8;  // N = (1e11 a)² = 1e6 at a = 10 nm
  EXPECT_NEAR(law->eval(a_1MPa).N, 1e6, 1e-6);
  EXPECT_NEAR(0.5 * law->eval(a_1MPa).dN, 1e14, 1e2);
}

TEST(NormalLaws, TableReproducesQuadraticDataExactly) {
  ContactParameters p;
  p.normal_law = "table";
  std::string text = "# a [m], N [Pa]\n";
  const double c = 1e22;
  for (double a : {0.0, 1e-9, 2.5e-9, 4e-9, 7e-9, 1e-8}) text += csv_row(a, c * a * a);
  p.table_file = write_table("quadratic.csv", text);
  const auto law = create_normal_law(p);
  for (double a = 1e-11; a < 1e-8; a *= 1.3) {
    EXPECT_NEAR(law->eval(a).N, c * a * a, 1e-12 * c * 1e-16) << a;
    EXPECT_NEAR(law->eval(a).dN, 2 * c * a, 1e-12 * 2 * c * 1e-8) << a;
  }
}

TEST(NormalLaws, BadTablesAreRejectedNamingTheLine) {
  ContactParameters p;
  p.normal_law = "table";
  auto error_of = [&](const std::string& text) -> std::string {
    p.table_file = write_table("bad.csv", text);
    try {
      create_normal_law(p);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of("0,0\n1e-9,10\n2e-9,5\n").find("line 3: N decreases"), std::string::npos);
  EXPECT_NE(error_of("0,0\n1e-9,10\n2e-9,15\n3e-9,40\n").find("line 3: slope decreases"), std::string::npos);
  EXPECT_NE(error_of("0,0\n1e-9,x\n").find("line 2"), std::string::npos);
  EXPECT_NE(error_of("0,0\n2e-9,10\n1e-9,20\n").find("line 3: a must increase"), std::string::npos);
  p.table_file = "/nonexistent/table.csv";
  try {
    create_normal_law(p);
    ADD_FAILURE() << "missing file accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("-contact_table_file /nonexistent/table.csv"), std::string::npos);
  }
}

}  // namespace
}  // namespace vibrotherm::contact
