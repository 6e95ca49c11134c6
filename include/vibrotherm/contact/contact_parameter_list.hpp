// The declared contact options: the common ones here, each law's next to its
// factory (crack_law_<name>.cpp, normal_law_<name>.cpp) and in its registry entry.
#pragma once

#include <vector>

#include "vibrotherm/contact/contact_parameters.hpp"
#include "vibrotherm/contact/parameter_spec.hpp"

namespace vibrotherm::contact {

using ContactParameter = Parameter<ContactParameters>;
using ContactParameterList = std::vector<ContactParameter>;

/// -crack_law, -contact_normal_law, -contact_mu, -contact_a0.
const ContactParameterList& common_contact_parameters();

/// Every contact option, each once: the common ones, then each crack law's,
/// then each normal law's, in registry order (the order -help lists them).
const ContactParameterList& contact_parameters();

/// For laws without parameters of their own.
const ContactParameterList& no_parameters();

/// Retired option names (an error tells what replaced them).
const std::vector<RenamedOption>& renamed_contact_options();

}  // namespace vibrotherm::contact
