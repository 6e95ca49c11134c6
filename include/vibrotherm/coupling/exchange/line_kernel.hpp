// The continuum temperature a line heat source makes near a point, exactly
// (plain C++, no PETSc: unit-tested alone). It is what the crack probes add to
// the heat mesh's temperature for the friction heat of the last few heat steps
// (crack_near_field.hpp; README "The temperature at the crack").
//
// A straight crack element carrying the Lagrange line density
// q(σ) = Σ_c q_c φ_c(σ) [W/m²] heats the infinite plate at x by
//   θ(x, t) = 1/(ρ c_p) ∫∫ q(σ, t') G(x − y(σ), t − t') dσ dt',
//   G(r, τ) = exp(−r²/(4ατ)) / (4πατ).
// For a density held constant over an interval the answer is a difference of
//   Φ_c(τ) = 1/(ρ c_p) ∫_0^τ ∫ φ_c(σ) G(x − y(σ), τ') dσ dτ'
// at the interval's two ages. The space integral is closed form (Gaussian
// moments of a quadratic, as scripts/lib/line_source.py); Φ_c is integrated in
// s = √τ, where the integrand 2s K(s²) is smooth (the kernel on the line goes
// as τ^(−1/2)), by 8-point Gauss per grid cell, and kept as a cubic Hermite
// interpolant in s with the exact dΦ/ds at the grid points.
#pragma once

#include <array>
#include <vector>

namespace vibrotherm::coupling {

/// A straight element of a crack with up to three Lagrange nodes (ends, middle).
struct KernelSegment {
  std::array<double, 2> p0{}, p1{};  ///< end points (node 0 at p0, node 1 at p1)
  int degree = 1;                    ///< 1 or 2 (node 2 at the middle)
  std::array<int, 3> cell = {-1, -1, -1};  ///< the kernel's cell index of each node; −1: not one of its cells
};

class LineKernel {
 public:
  /// Φ_c for the point x and every cell (0 .. cells − 1) that some segment's
  /// node maps to, for ages up to tau_max, on `intervals` cells in √τ.
  void Build(const std::array<double, 2>& x, const std::vector<KernelSegment>& segments, int cells, double alpha,
             double rho_c, double tau_max, int intervals = 1024);
  /// The same for ages up to a new tau_max.
  void Rebuild(double tau_max) { Build(x_, segments_, cells_, alpha_, rho_c_, tau_max, intervals_); }
  /// Φ_c(τ) [K per W/m² of density held for τ, i.e. K m² s/J]; τ ≤ tau_max.
  double Phi(int cell, double tau) const;
  /// Σ_c weight[c] Φ_c(τ) over all cells (one interpolation in τ for all of them).
  double Combine(const double* weight, double tau) const;
  int cells() const { return cells_; }
  double tau_max() const { return s_max_ * s_max_; }

 private:
  /// ∫ φ_c(σ) G(x − y(σ), τ) dσ / (ρ c_p), summed into k[cell] (size cells_).
  void Kernel(double tau, std::vector<double>* k) const;
  std::array<double, 2> x_{};
  std::vector<KernelSegment> segments_;
  int cells_ = 0, intervals_ = 0;
  double alpha_ = 1.0, rho_c_ = 1.0, s_max_ = 0.0, h_ = 1.0;
  /// [grid point][cell]: Φ and h dΦ/ds (a point's cells side by side: Combine reads them in a row)
  std::vector<double> value_, slope_;
};

}  // namespace vibrotherm::coupling
