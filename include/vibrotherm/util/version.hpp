#pragma once
namespace vibrotherm {
/// Version string reported by -version and written to summary.json.
const char* version();
/// `git describe` of the sources when the build was configured.
const char* git_commit();
}  // namespace vibrotherm
