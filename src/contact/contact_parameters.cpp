#include <cmath>
#include <sstream>

#include "vibrotherm/contact/contact_parameters.hpp"

namespace vibrotherm::contact {

namespace {
[[noreturn]] void reject(const char* option, double value, const char* rule) {
  std::ostringstream msg;
  msg << option << " " << rule << ", got " << value;
  throw InputError(msg.str());
}
}  // namespace

void ContactParameters::validate() const {
  if (!(mu >= 0.0) || !std::isfinite(mu)) reject("-contact_mu", mu, "must be >= 0");
  if (!(nu > -1.0 && nu < 0.5)) reject("-contact_nu", nu, "must be in (-1, 0.5)");
  if (!(tangential_k > 0.0) || !std::isfinite(tangential_k))
    reject("-contact_tangential_k", tangential_k, "must be > 0");
  if (!std::isfinite(a0)) reject("-contact_a0", a0, "must be finite");
  if (!(mmd_rel_tol > 0.0 && mmd_rel_tol < 1e-2)) reject("-contact_mmd_tol", mmd_rel_tol, "must be in (0, 1e-2)");
  if (mmd_max_breakpoints < 3) reject("-contact_mmd_max_breakpoints", mmd_max_breakpoints, "must be >= 3");
}

}  // namespace vibrotherm::contact
