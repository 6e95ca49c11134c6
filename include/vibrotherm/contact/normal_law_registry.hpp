// Registry of normal laws: name → factory and parameters. Adding a law is one
// new file with its factory and parameter list, and one line in the table of
// normal_law_registry.cpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/contact/contact_parameter_list.hpp"
#include "vibrotherm/contact/normal_law.hpp"

namespace vibrotherm::contact {

using NormalLawFactory = std::unique_ptr<NormalLaw> (*)(const ContactParameters&);

struct NormalLawEntry {
  const char* name;
  const char* help;
  NormalLawFactory create;
  const ContactParameterList& (*parameters)();  ///< the options this law reads
};

/// All registered normal laws, in the order -help lists them.
const std::vector<NormalLawEntry>& normal_laws();

/// The law named by params.normal_law; InputError naming -contact_normal_law
/// if unknown, or the offending parameter if invalid.
std::unique_ptr<NormalLaw> create_normal_law(const ContactParameters& params);

// Factories (one file each).
std::unique_ptr<NormalLaw> create_power_law(const ContactParameters&);
std::unique_ptr<NormalLaw> create_biwa_law(const ContactParameters&);
std::unique_ptr<NormalLaw> create_linear_law(const ContactParameters&);
std::unique_ptr<NormalLaw> create_table_law(const ContactParameters&);

const ContactParameterList& power_law_parameters();
const ContactParameterList& biwa_law_parameters();
const ContactParameterList& linear_law_parameters();
const ContactParameterList& table_law_parameters();

/// N = C a^p with p >= 1 (Hertz: p = 3/2). Exposed for the Biwa law.
std::unique_ptr<NormalLaw> make_power_law(double C, double p, std::string name);

}  // namespace vibrotherm::contact
