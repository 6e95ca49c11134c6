// Output files that never look complete unless they are: content goes to
// "<path>.partial" and is renamed onto <path> only by commit(). A crash leaves
// at most a .partial file behind.
#pragma once

#include <fstream>
#include <string>

namespace vibrotherm::io {

class AtomicFile {
 public:
  /// Opens "<path>.partial" for writing; throws std::runtime_error naming the path.
  explicit AtomicFile(std::string path);
  ~AtomicFile();  ///< without commit(): removes the partial file
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  /// Flushes and renames onto the final path; throws on I/O failure.
  void commit();

  /// Renames an already written "<path>.partial" onto path (for files written
  /// by other libraries, e.g. HDF5).
  static void publish(const std::string& path);
  static std::string partial_name(const std::string& path) { return path + ".partial"; }

 private:
  std::string path_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace vibrotherm::io
