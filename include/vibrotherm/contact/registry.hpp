// Lookup in a name → factory table (normal laws, crack laws).
#pragma once

#include <string>
#include <vector>

#include "vibrotherm/contact/contact_parameters.hpp"

namespace vibrotherm::contact {

/// The entry called `name`; InputError "<option>: unknown law '<name>' (known: a|b|c)".
template <class Entry>
const Entry& find_entry(const std::vector<Entry>& table, const std::string& name, const char* option) {
  std::string known;
  for (const Entry& entry : table) {
    if (name == entry.name) return entry;
    known += known.empty() ? entry.name : std::string("|") + entry.name;
  }
  throw InputError(std::string(option) + ": unknown law '" + name + "' (known: " + known + ")");
}

}  // namespace vibrotherm::contact
