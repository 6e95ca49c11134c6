#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {

const std::vector<NormalLawEntry>& normal_laws() {
  static const std::vector<NormalLawEntry> table = {
      {"power", "N = C a^p (Hertz: p = 3/2)", create_power_law},
      {"biwa", "interface stiffness K = C_B N^m (Biwa 2004)", create_biwa_law},
      {"linear", "N = k a", create_linear_law},
      {"table", "monotone convex C1 interpolation of (a, N) pairs from a CSV file", create_table_law},
  };
  return table;
}

std::unique_ptr<NormalLaw> create_normal_law(const ContactParameters& params) {
  std::string known;
  for (const auto& entry : normal_laws()) {
    if (params.normal_law == entry.name) return entry.create(params);
    known += known.empty() ? entry.name : std::string("|") + entry.name;
  }
  throw InputError("-contact_normal_law: unknown law '" + params.normal_law + "' (known: " + known + ")");
}

}  // namespace vibrotherm::contact
