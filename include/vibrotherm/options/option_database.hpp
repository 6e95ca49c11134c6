// Command-line options without PETSc, with PETSc's syntax: "-name value" or
// "-name" alone, "-options_file FILE" inserting a file's options (one
// "-name [value]" per line, '#' comments) at its place; a later occurrence of
// a name overrides an earlier one. A token is a value unless it starts with
// '-' followed by a letter or '_' ("-1e-9", "-.5", "-nan" are values).
//
// Used by vibrotherm-contact, which must run where PETSc is not installed.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vibrotherm::options {

class OptionDatabase {
 public:
  /// args: the command line without the program name. InputError naming the
  /// file and line for unreadable or malformed option files.
  explicit OptionDatabase(const std::vector<std::string>& args);
  static OptionDatabase from_argv(int argc, const char* const argv[]);

  bool has(const std::string& name) const { return values_.count(name) > 0; }
  /// Value of the last occurrence: nullopt if absent, "" if given without a value.
  std::optional<std::string> value(const std::string& name) const;
  /// Every name given, in order of first appearance.
  const std::vector<std::string>& names() const { return order_; }

 private:
  void insert_tokens(const std::vector<std::string>& tokens, int depth);
  void insert_file(const std::string& path, int depth);
  void set(const std::string& name, const std::string& value);

  std::map<std::string, std::string> values_;
  std::vector<std::string> order_;
};

/// True for "-name" tokens (option names), false for values such as "-1".
bool is_option_name(const std::string& token);

/// The first problem with the -options_file files of a command line (args
/// without the program name; nested files too), "" when they read: a missing
/// file, a directory, several options on one line. For programs whose options
/// PETSc reads: PETSc would stop at these with a trace, before any handler of
/// the program's could turn it into one line.
std::string options_file_error(const std::vector<std::string>& args);

/// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b);

/// The name of `known` closest to `name` if it is a likely typo of it, else "".
std::string nearest_name(const std::string& name, const std::vector<std::string>& known);

}  // namespace vibrotherm::options
