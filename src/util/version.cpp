#include "vibrotherm/util/version.hpp"

namespace vibrotherm {
const char* version() { return "0.2.0"; }
const char* git_commit() { return VIBROTHERM_GIT; }
}  // namespace vibrotherm
