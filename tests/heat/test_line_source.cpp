// Requirement: the heat solver reproduces Carslaw & Jaeger's continuous finite
// line source: constant power q per unit length on a crack segment of length L
// in a plate much larger than the diffusion length. Centre temperature
//   ΔT(t) = q/(ρ c_p) ∫_0^t erf(L / (4√(α s))) / √(4π α s) ds
// within 2 % once the diffusion length exceeds the crack element size, and the
// heat content equals q L t exactly while no heat has reached the sinks.
#include <cmath>

#include "mesh_test_support.hpp"
#include "vibrotherm/heat/crack_power.hpp"
#include "vibrotherm/heat/heat_probes.hpp"
#include "vibrotherm/heat/heat_solver.hpp"

namespace vibrotherm::testing {
namespace {

double LineSourceCentre(double q, double L, double rho_c, double alpha, double t) {
  // s = u²: ∫_0^t f(s) ds/√s = 2 ∫_0^√t f(u²) du, Simpson on a smooth integrand.
  const int n = 4000;
  const double b = std::sqrt(t), h = b / n;
  auto g = [&](double u) {
    if (u == 0.0) return 1.0 / std::sqrt(4.0 * M_PI * alpha);  // erf → 1
    return std::erf(L / (4.0 * std::sqrt(alpha) * u)) / std::sqrt(4.0 * M_PI * alpha);
  };
  double sum = g(0) + g(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(i * h);
  return q / rho_c * 2.0 * sum * h / 3.0;
}

TEST(HeatLineSource, MatchesCarslawJaeger) {
  const double L = 0.004, q = 1e6;
  ScopedSpecimen s("-specimen_width 0.04 -specimen_height 0.04 -mesh_h 0.002 -mesh_h_crack 1e-4 "
                   "-crack_center 0.02,0.02 -crack_length 0.004 -crack_angle 0 -heat_free_ts_adapt_dt_max 2e-4");
  ASSERT_EQ(s.status, 0);
  heat::HeatOptions options;
  ASSERT_EQ(heat::ReadHeatOptions(PETSC_COMM_WORLD, 2700.0, &options), 0);
  const heat::HeatMaterial& mat = options.material;
  heat::HeatSolver solver;
  ASSERT_EQ(solver.Setup(s.specimen.heat, options), 0);
  Vec load;
  ASSERT_EQ(DMCreateGlobalVector(s.specimen.heat, &load), 0);
  ASSERT_EQ(heat::CrackPowerLoad(solver.space(), {q}, load), 0);
  ASSERT_EQ(solver.SetSourceLoad(load), 0);
  ASSERT_EQ(VecDestroy(&load), 0);
  const double rho_c = mat.density * mat.capacity, alpha = mat.diffusivity();
  for (double t : {1e-4, 3e-4, 1e-3, 3e-3, 1e-2}) {
    ASSERT_EQ(solver.AdvanceTo(t), 0);
    double T;
    const double centre[2] = {0.02, 0.02};
    ASSERT_EQ(heat::TemperatureAt(solver, centre, &T), 0);
    const double exact = LineSourceCentre(q, L, rho_c, alpha, t);
    // Once the diffusion length √(α t) exceeds a few crack elements: 2 %.
    const double tol = std::sqrt(alpha * t) > 3e-4 ? 0.02 : 0.05;
    EXPECT_NEAR(T - mat.T0, exact, tol * exact) << "t = " << t;
    RecordProperty("t" + std::to_string(t), std::to_string((T - mat.T0) / exact - 1.0));
    if (t <= 3e-3) {  // no heat has reached the sink edges 18 mm away
      heat::HeatAccounts accounts;
      ASSERT_EQ(solver.Accounts(&accounts), 0);
      EXPECT_NEAR(accounts.content, q * L * t, 1e-6 * q * L * t) << "t = " << t;
    }
  }
}

}  // namespace
}  // namespace vibrotherm::testing
