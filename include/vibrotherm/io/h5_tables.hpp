// Small serial HDF5 files of 2D double tables (rank 0 only; HDF5 C API), written
// to "<path>.partial" and renamed when complete: a crash never leaves a file
// that looks complete.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace vibrotherm::io {

struct H5Table {
  std::size_t rows = 0, cols = 1;
  std::vector<double> values;  ///< row-major, rows × cols
  std::string units;           ///< stored as the string attribute "units" (if not empty)
};

/// Writes every table as a dataset named by its key (flat names) and commits
/// the file. Throws std::runtime_error naming the path.
void WriteH5Tables(const std::string& path, const std::map<std::string, H5Table>& tables);

}  // namespace vibrotherm::io
