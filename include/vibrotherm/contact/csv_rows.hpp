// Numeric CSV rows for the small input files of the contact library (normal-law
// tables, cell histories): '#' comments, blank lines and one header line allowed.
#pragma once

#include <string>
#include <vector>

namespace vibrotherm::contact {

struct CsvRow {
  std::vector<double> values;
  int line;  ///< 1-based line number in the file, for error messages
};

/// Reads rows of exactly `columns` finite numbers. Errors (InputError) start
/// with `option` and the path: "<option> <path>: cannot open the file",
/// "<option> <path> line L: expected N numbers '<header_hint>'".
std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& option, std::size_t columns,
                                  const std::string& header_hint);

}  // namespace vibrotherm::contact
