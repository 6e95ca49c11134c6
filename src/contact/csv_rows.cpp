#include "vibrotherm/contact/csv_rows.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <sstream>

#include "vibrotherm/contact/contact_parameters.hpp"

namespace vibrotherm::contact {

std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& option, std::size_t columns,
                                  const std::string& header_hint) {
  const std::string where = option + " " + path;
  std::ifstream in(path);
  if (!in) throw InputError(where + ": cannot open the file");
  std::vector<CsvRow> rows;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos || text[first] == '#') continue;
    if (rows.empty() && std::isalpha(static_cast<unsigned char>(text[first]))) continue;  // header
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream fields(text);
    CsvRow row{std::vector<double>(columns), line};
    bool ok = true;
    for (double& v : row.values) ok = ok && (fields >> v) && std::isfinite(v);
    if (!ok)
      throw InputError(where + " line " + std::to_string(line) + ": expected " + std::to_string(columns) +
                       " numbers '" + header_hint + "'");
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace vibrotherm::contact
