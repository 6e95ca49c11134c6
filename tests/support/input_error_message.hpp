// The message of the InputError an action throws, "" if it throws none.
#pragma once

#include <string>

#include "vibrotherm/contact/contact_parameters.hpp"

namespace vibrotherm::contact::testing {

template <class Action>
std::string input_error_message(Action&& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace vibrotherm::contact::testing
