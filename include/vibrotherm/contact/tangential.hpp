// A tangential vector of a contact cell (PHYSICS.md §3.5): the half tangential
// displacement b, a slip offset b0 or the traction T in the crack plane. One
// component in 2D (along the crack), two in 3D (on the tangents s₁, s₂).
//
// Fixed capacity, so a law never allocates per cell and step. The helpers below
// reduce, for one component, to exactly the scalar operations the 2D laws used
// (|t| is std::abs, t/|t| is ±1), which keeps 2D results bit for bit.
#pragma once

#include <array>

namespace vibrotherm::contact {

class Tangential {
 public:
  static constexpr int kMaxComponents = 2;

  /// One component, zero: the 2D default.
  Tangential() = default;
  /// The 2D value t (one component).
  explicit Tangential(double t) : values_{t, 0.0} {}
  /// The 3D vector (t1, t2) (two components).
  Tangential(double t1, double t2) : components_(2), values_{t1, t2} {}
  /// Zero with `components` components; std::invalid_argument unless 1 or 2.
  static Tangential zero(int components);

  int components() const { return components_; }
  double operator[](int k) const { return values_[k]; }
  double& operator[](int k) { return values_[k]; }

 private:
  int components_ = 1;
  std::array<double, kMaxComponents> values_{};
};

/// Euclidean length; std::abs(t[0]) for one component.
double norm(const Tangential& t);
/// |x − y|.
double distance(const Tangential& x, const Tangential& y);
/// x · y; x[0] * y[0] for one component.
double dot(const Tangential& x, const Tangential& y);
/// The unit vector along t ≠ 0; for one component exactly ±1 (also for t = ±∞).
Tangential direction(const Tangential& t);

}  // namespace vibrotherm::contact
