// Command-line options without PETSc, with PETSc's syntax: "-name value" or
// "-name" alone, "-options_file FILE" inserting a file's options (one
// "-name [value]" per line, '#' comments) at its place; a later occurrence of
// a name overrides an earlier one. A token is a value unless it starts with
// '-' followed by a letter or '_' ("-1e-9", "-.5", "-nan" are values). A file
// included by another is found relative to the including file's directory (or,
// for files written before that rule, relative to the working directory when
// only that holds it); an error in it names the including file and line too.
//
// Used by vibrotherm-contact, which must run where PETSc is not installed, and
// by vibrotherm to expand its options files before PETSc reads the command line
// (PETSc resolves includes relative to the working directory).
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
  void set(const std::string& name, const std::string& value);

  std::map<std::string, std::string> values_;
  std::vector<std::string> order_;
};

/// True for "-name" tokens (option names), false for values such as "-1".
bool is_option_name(const std::string& token);

/// The command line (without the program name) with every -options_file FILE replaced
/// by FILE's options, in place, nested files too (keep_yaml: YAML files, PETSc's, are left
/// as they are). InputError naming the file (and the including file and line).
std::vector<std::string> expand_options_files(const std::vector<std::string>& args, bool keep_yaml = true);

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
