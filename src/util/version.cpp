namespace vibrotherm {
/// Version string reported by -version and written to summary.json.
const char* version() { return "0.1.0"; }
}  // namespace vibrotherm
