// Biwa et al. (2004) pressure-dependent interface stiffness K = dN/d(2a) = C_B N^m,
// 0 < m < 1. Integrated: N = [(1 − m) C_B 2a]^{1/(1−m)}, i.e. a power law
// N = K0 a^r with r = 1/(1 − m) and K0 = (2 (1 − m) C_B)^r.
// m = 1/2 gives the quadratic law used for clapping by Delrue et al. (2018).
#include <cmath>
#include <sstream>

#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {

const ContactParameterList& biwa_law_parameters() {
  using P = ContactParameters;
  // Default: K = 1e14 Pa/m at N = 1 MPa with m = 1/2 (PHYSICS.md §3.2). The
  // unit of C_B depends on m: a C_B for another m is a new calibration. m <= 0.9
  // keeps the exponent of N(a) within the power law's p <= 10.
  static const ContactParameterList list = {
      real_parameter("-contact_biwa_C", &P::biwa_C, "1e11", Range::positive(), "Pa^(1-m)/m",
                     "biwa law: C_B in K = C_B N^m"),
      real_parameter("-contact_biwa_m", &P::biwa_m, "0.5", Range::open_closed(0.0, 0.9), "",
                     "biwa law: exponent m in K = C_B N^m"),
  };
  return list;
}

std::unique_ptr<NormalLaw> create_biwa_law(const ContactParameters& params) {
  const double m = params.biwa_m, r = 1.0 / (1.0 - m);
  const double K0 = std::pow(2.0 * (1.0 - m) * params.biwa_C, r);
  if (!(K0 < HUGE_VAL)) {
    std::ostringstream msg;
    msg << "-contact_biwa_C " << params.biwa_C << " with -contact_biwa_m " << m << " overflows N = K0 a^(1/(1-m))";
    throw InputError(msg.str());
  }
  return make_power_law(K0, r, "biwa");
}

}  // namespace vibrotherm::contact
