#include "vibrotherm/contact/contact_parameter_list.hpp"

#include <set>

#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"

namespace vibrotherm::contact {
namespace {

template <class Entry>
std::vector<std::string> names_of(const std::vector<Entry>& table) {
  std::vector<std::string> names;
  for (const Entry& e : table) names.emplace_back(e.name);
  return names;
}

/// Appends the parameters not listed yet (a law may share another's, e.g. -material_nu).
void append_new(ContactParameterList& all, std::set<std::string>& seen, const ContactParameterList& more) {
  for (const ContactParameter& p : more)
    if (seen.insert(p.spec.name).second) all.push_back(p);
}

}  // namespace

const ContactParameterList& common_contact_parameters() {
  using P = ContactParameters;
  static const ContactParameterList list = {
      choice_parameter("-crack_law", &P::crack_law, "mmd", names_of(crack_laws()), "Crack law"),
      choice_parameter("-contact_normal_law", &P::normal_law, "biwa", names_of(normal_laws()),
                       "Normal law N(a) of the clapping, coulomb and mmd crack laws"),
      real_parameter("-contact_mu", &P::mu, "1", Range::at_least(0.0), "",
                     "Friction coefficient (coulomb, mmd)"),
      real_parameter("-contact_a0", &P::a0, "0", Range::any(), "m",
                     "Initial approach added to a (> 0: faces pre-pressed, < 0: gap)"),
  };
  return list;
}

const ContactParameterList& no_parameters() {
  static const ContactParameterList list;
  return list;
}

const ContactParameterList& contact_parameters() {
  static const ContactParameterList list = [] {
    ContactParameterList all;
    std::set<std::string> seen;
    append_new(all, seen, common_contact_parameters());
    for (const CrackLawEntry& e : crack_laws()) append_new(all, seen, e.parameters());
    for (const NormalLawEntry& e : normal_laws()) append_new(all, seen, e.parameters());
    return all;
  }();
  return list;
}

const std::vector<RenamedOption>& renamed_contact_options() {
  static const std::vector<RenamedOption> list = {
      {"-contact_normal_C", "-contact_power_C (power law) or -contact_biwa_C (biwa law)"},
      {"-contact_normal_p", "-contact_power_p"},
      {"-contact_normal_m", "-contact_biwa_m"},
      {"-contact_normal_k", "-contact_linear_k (normal law linear) or -crack_linear_kn (crack law linear)"},
      {"-contact_normal_table", "-contact_table_file"},
      {"-contact_nu", "-material_nu (the material's Poisson ratio)"},
      {"-contact_tangential_k", "-crack_linear_kt (crack law linear) or -crack_coulomb_kt (crack law coulomb)"},
      {"-contact_mmd_tol", "-crack_mmd_tol"},
      {"-contact_mmd_max_breakpoints", "-crack_mmd_max_breakpoints"},
  };
  return list;
}

ContactParameters::ContactParameters() { assign_defaults(contact_parameters(), *this); }

void ContactParameters::validate() const {
  for (const ContactParameter& p : contact_parameters()) check_value(p, *this);
}

}  // namespace vibrotherm::contact
