#include "vibrotherm/options/petsc/option_registry.hpp"

#include <algorithm>

namespace vibrotherm {
namespace {

std::vector<std::string> SortedUnique(std::vector<std::string> names) {
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

}  // namespace

OptionRegistry& OptionRegistry::Add(const std::vector<contact::ParameterSpec>& list) {
  specs_.insert(specs_.end(), list.begin(), list.end());
  return *this;
}

std::vector<std::string> OptionRegistry::names() const {
  std::vector<std::string> names;
  for (const contact::ParameterSpec& s : specs_) names.push_back(s.name);
  return SortedUnique(names);
}

std::vector<std::string> OptionRegistry::names_with_values() const {
  std::vector<std::string> names;
  for (const contact::ParameterSpec& s : specs_)
    if (s.type != contact::ParameterType::Flag) names.push_back(s.name);
  return SortedUnique(names);
}

}  // namespace vibrotherm
