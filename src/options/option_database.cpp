#include "vibrotherm/options/option_database.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "vibrotherm/contact/contact_parameters.hpp"

namespace vibrotherm::options {
namespace {

using contact::InputError;

constexpr int kMaxFileDepth = 8;  // -options_file nesting: stops a file that includes itself

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/// Whitespace-separated tokens of a line, '#' and what follows dropped.
std::vector<std::string> line_tokens(const std::string& line) {
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

}  // namespace

bool is_option_name(const std::string& token) {
  if (token.size() < 2 || token[0] != '-') return false;
  const unsigned char c = token[1];
  if (!(std::isalpha(c) || c == '_')) return false;
  const std::string word = lowercase(token.substr(1));
  return word != "nan" && word != "inf" && word != "infinity";  // negative non-numbers are values (then refused)
}

namespace {

bool is_yaml(const std::string& file) {
  const auto ends = [&](const std::string& tail) {
    return file.size() > tail.size() && file.compare(file.size() - tail.size(), tail.size(), tail) == 0;
  };
  return ends(".yml") || ends(".yaml");
}

/// The file an include in `including` names: relative to the including file's directory;
/// for files written when includes were relative to the working directory, there when only
/// that holds it.
std::string resolve_include(const std::string& name, const std::string& including) {
  namespace fs = std::filesystem;
  if (fs::path(name).is_absolute()) return name;
  const std::string beside = (fs::path(including).parent_path() / name).lexically_normal().string();
  std::error_code ec;
  return !fs::exists(beside, ec) && fs::exists(name, ec) ? name : beside;
}

/// Appends the tokens of args to `out`, each -options_file replaced by its file's
/// tokens (`including`: the file args come from, "" for the command line).
void expand(const std::vector<std::string>& args, const std::string& including, int depth, bool keep_yaml,
            std::vector<std::string>* out);

/// Appends the tokens of the options file `path`.
void expand_file(const std::string& path, int depth, bool keep_yaml, std::vector<std::string>* out) {
  const std::string where = "-options_file " + path;
  if (depth > kMaxFileDepth) throw InputError(where + ": files nested more than 8 deep (a file including itself?)");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(where + ": is a directory, not a file of options");
  std::ifstream in(path);
  if (!in) throw InputError(where + ": cannot open the file");
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::vector<std::string> tokens = line_tokens(line);
    if (tokens.empty()) continue;
    const std::string at = where + " line " + std::to_string(number);
    const bool several = std::count_if(tokens.begin(), tokens.end(), is_option_name) > 1;
    if (several) throw InputError(at + ": several options on one line ('" + line + "'): one '-name value' per line");
    if (!is_option_name(tokens[0]) || tokens.size() > 2)
      throw InputError(at + ": expected '-name value' or '-name', got '" + line + "'");
    if (tokens[0] != "-options_file") {
      out->insert(out->end(), tokens.begin(), tokens.end());
      continue;
    }
    try {  // an include: its errors name this file and line too
      expand(tokens, path, depth, keep_yaml, out);
    } catch (const InputError& e) {
      throw InputError(at + ": " + e.what());
    }
  }
  if (in.bad()) throw InputError(where + ": read error");
}

void expand(const std::vector<std::string>& args, const std::string& including, int depth, bool keep_yaml,
            std::vector<std::string>* out) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "-options_file") {
      out->push_back(args[i]);
      continue;
    }
    if (i + 1 >= args.size() || is_option_name(args[i + 1])) throw InputError("-options_file: needs a file name");
    const std::string file = including.empty() ? args[i + 1] : resolve_include(args[i + 1], including);
    ++i;
    if (keep_yaml && is_yaml(file)) {  // PETSc's YAML reader, not this one
      out->insert(out->end(), {"-options_file", file});
      continue;
    }
    expand_file(file, depth + 1, keep_yaml, out);
  }
}

}  // namespace

std::vector<std::string> expand_options_files(const std::vector<std::string>& args, bool keep_yaml) {
  std::vector<std::string> out;
  expand(args, "", 0, keep_yaml, &out);
  return out;
}

OptionDatabase::OptionDatabase(const std::vector<std::string>& args) {
  const std::vector<std::string> tokens = expand_options_files(args, false);
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!is_option_name(tokens[i]))
      throw InputError("'" + tokens[i] + "' is not an option name (options are -name value)");
    const bool has_value = i + 1 < tokens.size() && !is_option_name(tokens[i + 1]);
    set(tokens[i], has_value ? tokens[i + 1] : "");
    if (has_value) ++i;
  }
}

OptionDatabase OptionDatabase::from_argv(int argc, const char* const argv[]) {
  return OptionDatabase(std::vector<std::string>(argv + std::min(argc, 1), argv + argc));
}

std::optional<std::string> OptionDatabase::value(const std::string& name) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return std::nullopt;
  return it->second;
}

void OptionDatabase::set(const std::string& name, const std::string& value) {
  if (!has(name)) order_.push_back(name);
  values_[name] = value;
}

std::string options_file_error(const std::vector<std::string>& args) {
  try {
    expand_options_files(args);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

std::string nearest_name(const std::string& name, const std::vector<std::string>& known) {
  // A typo changes a few characters; more than a third of the name is another word.
  std::size_t best = std::max<std::size_t>(2, name.size() / 3) + 1;
  std::string nearest;
  for (const std::string& k : known) {
    const std::size_t d = edit_distance(name, k);
    if (d < best) {
      best = d;
      nearest = k;
    }
  }
  return nearest;
}

}  // namespace vibrotherm::options
