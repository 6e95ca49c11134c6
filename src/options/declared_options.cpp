#include "vibrotherm/options/declared_options.hpp"

#include <algorithm>

namespace vibrotherm::options {

std::string help_line(const contact::ParameterSpec& spec) {
  std::string line = "  " + spec.name + " <" + spec.default_value + ">";
  line.resize(std::max<std::size_t>(line.size() + 1, 40), ' ');
  return line + spec.describe();
}

std::optional<std::string> given_value(const OptionDatabase& db, const contact::ParameterSpec& spec) {
  std::optional<std::string> text = db.value(spec.name);
  if (text && text->empty()) throw contact::InputError(spec.name + ": needs a value");
  return text;
}

void reject_unknown(const OptionDatabase& db, const std::vector<std::string>& known,
                    const std::vector<contact::RenamedOption>& renamed) {
  for (const std::string& name : db.names()) {
    for (const contact::RenamedOption& r : renamed)
      if (name == r.old_name) throw contact::InputError(contact::renamed_message(r));
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    const std::string nearest = nearest_name(name, known);
    throw contact::InputError("unknown option " + name +
                              (nearest.empty() ? " (-help lists the options)" : "; did you mean " + nearest + "?"));
  }
}

}  // namespace vibrotherm::options
