#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/registry.hpp"

namespace vibrotherm::contact {

const std::vector<CrackLawEntry>& crack_laws() {
  static const std::vector<CrackLawEntry> table = {
      {"open", "no contact: traction-free crack faces", create_open_law, no_parameters},
      {"linear", "Schoenberg linear slip interface N = k_n a, T = k_t b (no dissipation)", create_linear_slip_law,
       linear_slip_law_parameters},
      {"clapping", "normal law only, frictionless (T = 0)", create_clapping_law, no_parameters},
      {"coulomb", "flat faces: stick with stiffness k_t until |T| = mu N, then sliding", create_coulomb_law,
       coulomb_law_parameters},
      {"mmd", "rough faces: Method of Memory Diagrams (partial slip, hysteresis, memory)", create_mmd_law,
       mmd_law_parameters},
  };
  return table;
}

std::unique_ptr<CrackLaw> create_crack_law(const ContactParameters& params) {
  params.validate();
  return find_entry(crack_laws(), params.crack_law, "-crack_law").create(params);
}

}  // namespace vibrotherm::contact
