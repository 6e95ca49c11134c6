#include "vibrotherm/contact/normal_law_registry.hpp"
#include "vibrotherm/contact/registry.hpp"

namespace vibrotherm::contact {

const std::vector<NormalLawEntry>& normal_laws() {
  static const std::vector<NormalLawEntry> table = {
      {"power", "N = C a^p (Hertz: p = 3/2)", create_power_law, power_law_parameters},
      {"biwa", "interface stiffness K = C_B N^m (Biwa 2004)", create_biwa_law, biwa_law_parameters},
      {"linear", "N = k a", create_linear_law, linear_law_parameters},
      {"table", "monotone convex C1 interpolation of (a, N) pairs from a CSV file", create_table_law,
       table_law_parameters},
  };
  return table;
}

std::unique_ptr<NormalLaw> create_normal_law(const ContactParameters& params) {
  return find_entry(normal_laws(), params.normal_law, "-contact_normal_law").create(params);
}

}  // namespace vibrotherm::contact
