// Numeric CSV rows for the small input files (normal-law tables, cell
// histories, the simulator's -crack_a0_file).
//
// The reader never changes data: fields are separated by commas only, each
// field is one finite number in plain decimal notation (parse_real), every row
// has exactly the declared columns. Blank lines and lines starting with '#' are
// skipped; the first other line is a header only if its fields are the column
// names (case-insensitive), e.g. "t,a,b". Anything else is an InputError
// "<option> <path> line L: ..." — one line naming the file and line.
#pragma once

#include <string>
#include <vector>

namespace vibrotherm::contact {

struct CsvRow {
  std::vector<double> values;
  int line;  ///< 1-based line number in the file, for error messages
};

/// Reads the rows of the file at path; `option` is the option that named it.
/// Errors: "cannot open the file", "line L: expected 3 fields t,a,b, got 4 (a
/// decimal comma?)", "line L: field 2 (a): expected a number, got '1e-9x'".
std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& option,
                                  const std::vector<std::string>& columns);

/// The same, where a header line may add the `optional` columns after `columns`
/// (e.g. "t,a,b,b2"); the rows then have all of them. Without such a header the
/// rows have `columns` only.
std::vector<CsvRow> read_csv_rows(const std::string& path, const std::string& option,
                                  std::vector<std::string> columns, const std::vector<std::string>& optional);

}  // namespace vibrotherm::contact
