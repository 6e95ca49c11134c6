#include "vibrotherm/contact/csv_rows.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "vibrotherm/contact/parameter_spec.hpp"

namespace vibrotherm::contact {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> split_fields(const std::string& text) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    fields.push_back(trimmed(text.substr(start, comma - start)));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

bool same_name(const std::string& a, const std::string& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

bool is_header(const std::vector<std::string>& fields, const std::vector<std::string>& columns) {
  return fields.size() == columns.size() && std::equal(fields.begin(), fields.end(), columns.begin(), same_name);
}

std::string joined(const std::vector<std::string>& columns) {
  std::string text;
  for (const std::string& c : columns) text += (text.empty() ? "" : ",") + c;
  return text;
}

/// The numbers of one data row; InputError prefixed with `where` (file and line).
std::vector<double> parse_row(const std::vector<std::string>& fields, const std::vector<std::string>& columns,
                              const std::string& where) {
  if (fields.size() != columns.size())
    throw InputError(where + ": expected " + std::to_string(columns.size()) + " fields " + joined(columns) + ", got " +
                     std::to_string(fields.size()) + (fields.size() > columns.size() ? " (a decimal comma?)" : ""));
  std::vector<double> values;
  for (std::size_t i = 0; i < fields.size(); ++i)
    values.push_back(parse_real(fields[i], where + ": field " + std::to_string(i + 1) + " (" + columns[i] + ")"));
  return values;
}

}  // namespace

std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& option,
                                  const std::vector<std::string>& columns) {
  return read_csv_rows(path, option, columns, {});
}

std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& option,
                                  std::vector<std::string> columns, const std::vector<std::string>& optional) {
  std::vector<std::string> extended = columns;
  extended.insert(extended.end(), optional.begin(), optional.end());
  const std::string file = option + " " + path;
  std::ifstream in(path);
  if (!in) throw InputError(file + ": cannot open the file");
  std::vector<CsvRow> rows;
  bool first = true;  // the first non-comment line may be the header
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 byte-order mark
    const std::string content = trimmed(text);
    if (content.empty() || content[0] == '#') continue;
    const std::vector<std::string> fields = split_fields(content);
    // Only a header names the optional columns: a headerless row with one field
    // too many stays an error (a decimal comma), never a silent extra column.
    const bool extends = first && !optional.empty() && is_header(fields, extended);
    if (extends) columns = extended;
    const bool header = extends || (first && is_header(fields, columns));
    first = false;
    if (!header) rows.push_back({parse_row(fields, columns, file + " line " + std::to_string(line)), line});
  }
  if (in.bad()) throw InputError(file + ": read error");
  return rows;
}

}  // namespace vibrotherm::contact
