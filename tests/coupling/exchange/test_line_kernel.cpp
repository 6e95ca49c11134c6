// Requirement: the near-field kernel of the crack probes (line_kernel.hpp) is
// the continuum temperature of a line source to rounding: a uniform density on
// a straight crack of Q2 elements gives Carslaw & Jaeger's finite line source
// at its centre, and a density varying along one element gives, at a point off
// the line beyond its end, the brute-force double integral of the heat kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "vibrotherm/coupling/exchange/line_kernel.hpp"

namespace vibrotherm::coupling {
namespace {

const double kAlpha = 237.0 / (2700.0 * 900.0), kRhoC = 2700.0 * 900.0;

/// Composite Gauss–Legendre (8 points) of f over [a, b] in n pieces.
double Integrate(const std::function<double(double)>& f, double a, double b, int n) {
  static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double sum = 0.0, h = (b - a) / n;
  for (int i = 0; i < n; ++i) {
    const double m = a + (i + 0.5) * h;
    for (int q = 0; q < 4; ++q) sum += 0.5 * h * w[q] * (f(m - 0.5 * h * x[q]) + f(m + 0.5 * h * x[q]));
  }
  return sum;
}

/// A straight crack from (0, 0) at angle 20° in n Q2 elements; cells numbered ends first, then middles.
std::vector<KernelSegment> Crack(double L, int n) {
  const double c = std::cos(20 * M_PI / 180), s = std::sin(20 * M_PI / 180);
  std::vector<KernelSegment> out;
  for (int i = 0; i < n; ++i) {
    KernelSegment g;
    g.p0 = {c * L * i / n, s * L * i / n};
    g.p1 = {c * L * (i + 1) / n, s * L * (i + 1) / n};
    g.degree = 2;
    g.cell = {i, i + 1, n + 1 + i};
    out.push_back(g);
  }
  return out;
}

TEST(LineKernel, UniformLineSourceIsCarslawJaeger) {
  const double L = 0.004;
  const int n = 8, cells = 2 * n + 1;
  const double c = std::cos(20 * M_PI / 180), s = std::sin(20 * M_PI / 180);
  LineKernel kernel;
  kernel.Build({c * L / 2, s * L / 2}, Crack(L, n), cells, kAlpha, kRhoC, 3e-5);
  for (double tau : {1e-9, 4e-8, 1e-6, 1.7e-5, 3e-5}) {
    double sum = 0.0;  // q = 1 W/m² everywhere: Σ_c φ_c = 1
    for (int k = 0; k < cells; ++k) sum += kernel.Phi(k, tau);
    // ∫_0^τ erf(L/(4√(ατ')))/√(4πατ') dτ' / ρc, in s = √τ'
    const double exact = Integrate([&](double r) { return 2.0 * std::erf(L / (4 * std::sqrt(kAlpha) * r)) /
                                                           std::sqrt(4 * M_PI * kAlpha); },
                                   0.0, std::sqrt(tau), 200) / kRhoC;
    EXPECT_NEAR(sum / exact, 1.0, 1e-10) << "tau = " << tau;
  }
}

TEST(LineKernel, VaryingDensityOffTheLineIsTheDoubleIntegral) {
  const double ell = 5e-4;
  KernelSegment g;
  g.p0 = {0.0, 0.0};
  g.p1 = {ell, 0.0};
  g.degree = 2;
  g.cell = {0, 1, 2};
  const double q[3] = {1.0, -0.4, 2.5};  // at σ = 0, ℓ, ℓ/2
  const std::array<double, 2> x = {ell + 1e-5, 5e-6};
  LineKernel kernel;
  kernel.Build(x, {g}, 3, kAlpha, kRhoC, 2e-5);
  const auto density = [&](double sigma) {
    const double t = sigma / ell;
    return q[0] * (1 - t) * (1 - 2 * t) + q[1] * t * (2 * t - 1) + q[2] * 4 * t * (1 - t);
  };
  for (double tau : {1e-7, 4e-6, 2e-5}) {
    const double got = q[0] * kernel.Phi(0, tau) + q[1] * kernel.Phi(1, tau) + q[2] * kernel.Phi(2, tau);
    const double exact = Integrate(
        [&](double r) {
          const double t = r * r;
          const double space = Integrate(
              [&](double sigma) {
                const double d2 = (x[0] - sigma) * (x[0] - sigma) + x[1] * x[1];
                return density(sigma) * std::exp(-d2 / (4 * kAlpha * t)) / (4 * M_PI * kAlpha * t);
              },
              0.0, ell, 400);
          return 2.0 * r * space;
        },
        0.0, std::sqrt(tau), 400) / kRhoC;
    EXPECT_NEAR(got / exact, 1.0, 1e-7) << "tau = " << tau;
  }
}

}  // namespace
}  // namespace vibrotherm::coupling
