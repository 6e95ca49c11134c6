// Biwa et al. (2004) pressure-dependent interface stiffness K = dN/d(2a) = C_B N^m,
// 0 < m < 1. Integrated: N = [(1 − m) C_B 2a]^{1/(1−m)}, i.e. a power law
// N = K0 a^r with r = 1/(1 − m) and K0 = (2 (1 − m) C_B)^r.
// m = 1/2 gives the quadratic law used for clapping by Delrue et al. (2018).
#include <cmath>
#include <sstream>

#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {

std::unique_ptr<NormalLaw> create_biwa_law(const ContactParameters& params) {
  // Default C_B: K = 1e14 Pa/m at N = 1 MPa with m = 1/2 (PHYSICS.md §3.2).
  const double CB = params.normal_C < 0.0 ? 1e14 / std::pow(1e6, params.normal_m) : params.normal_C;
  const double m = params.normal_m;
  if (!(m > 0.0 && m < 1.0)) {
    std::ostringstream msg;
    msg << "-contact_normal_m must be in (0, 1) for the biwa law, got " << m;
    throw InputError(msg.str());
  }
  if (!(CB > 0.0) || !std::isfinite(CB)) throw InputError("-contact_normal_C must be > 0 for the biwa law");
  const double r = 1.0 / (1.0 - m);
  return make_power_law(std::pow(2.0 * (1.0 - m) * CB, r), r, "biwa");
}

}  // namespace vibrotherm::contact
