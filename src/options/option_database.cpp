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

OptionDatabase::OptionDatabase(const std::vector<std::string>& args) { insert_tokens(args, 0); }

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

void OptionDatabase::insert_tokens(const std::vector<std::string>& tokens, int depth) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!is_option_name(tokens[i]))
      throw InputError("'" + tokens[i] + "' is not an option name (options are -name value)");
    const bool has_value = i + 1 < tokens.size() && !is_option_name(tokens[i + 1]);
    const std::string value = has_value ? tokens[i + 1] : "";
    if (tokens[i] == "-options_file") {
      if (!has_value) throw InputError("-options_file: needs a file name");
      insert_file(value, depth + 1);
    } else {
      set(tokens[i], value);
    }
    if (has_value) ++i;
  }
}

void OptionDatabase::insert_file(const std::string& path, int depth) {
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
    insert_tokens(tokens, depth);
  }
  if (in.bad()) throw InputError(where + ": read error");
}

std::string options_file_error(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "-options_file") continue;
    if (i + 1 >= args.size() || is_option_name(args[i + 1])) return "-options_file: needs a file name";
    const std::string& file = args[i + 1];
    const bool yaml = file.size() > 4 && (file.rfind(".yml") == file.size() - 4 || file.rfind(".yaml") == file.size() - 5);
    if (yaml) continue;  // PETSc's YAML reader, not this one
    try {
      OptionDatabase({"-options_file", file});
    } catch (const InputError& e) {
      return e.what();
    }
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
