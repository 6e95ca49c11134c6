#include "vibrotherm/contact/tangential.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace vibrotherm::contact {

Tangential Tangential::zero(int components) {
  if (components == 1) return Tangential(0.0);
  if (components == 2) return Tangential(0.0, 0.0);
  throw std::invalid_argument("a tangential vector has 1 or 2 components, not " + std::to_string(components));
}

double norm(const Tangential& t) { return t.components() == 1 ? std::abs(t[0]) : std::hypot(t[0], t[1]); }

double distance(const Tangential& x, const Tangential& y) {
  return x.components() == 1 ? std::abs(x[0] - y[0]) : std::hypot(x[0] - y[0], x[1] - y[1]);
}

double dot(const Tangential& x, const Tangential& y) {
  double sum = x[0] * y[0];
  for (int k = 1; k < x.components(); ++k) sum += x[k] * y[k];
  return sum;
}

Tangential direction(const Tangential& t) {
  // One component: the sign, as the 2D laws had it (t/|t| would give NaN at ±∞).
  if (t.components() == 1) return Tangential(t[0] > 0.0 ? 1.0 : -1.0);
  const double length = norm(t);
  return Tangential(t[0] / length, t[1] / length);
}

}  // namespace vibrotherm::contact
