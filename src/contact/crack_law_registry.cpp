#include "vibrotherm/contact/crack_law.hpp"

namespace vibrotherm::contact {

const std::vector<CrackLawEntry>& crack_laws() {
  static const std::vector<CrackLawEntry> table = {
      {"open", "no contact: traction-free crack faces", create_open_law},
      {"linear", "Schoenberg linear slip interface N = k_n a, T = k_t b (no dissipation)", create_linear_slip_law},
      {"clapping", "normal law only, frictionless (T = 0)", create_clapping_law},
      {"coulomb", "flat faces: stick with stiffness k_t until |T| = mu N, then sliding", create_coulomb_law},
      {"mmd", "rough faces: Method of Memory Diagrams (partial slip, hysteresis, memory)", create_mmd_law},
  };
  return table;
}

std::unique_ptr<CrackLaw> create_crack_law(const ContactParameters& params) {
  params.validate();
  std::string known;
  for (const auto& entry : crack_laws()) {
    if (params.crack_law == entry.name) return entry.create(params);
    known += known.empty() ? entry.name : std::string("|") + entry.name;
  }
  throw InputError("-crack_law: unknown law '" + params.crack_law + "' (known: " + known + ")");
}

}  // namespace vibrotherm::contact
