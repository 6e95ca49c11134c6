#pragma once
namespace vibrotherm {
/// Version string reported in summary.json.
const char* version();
}  // namespace vibrotherm
