// Output files that never look complete unless they are: content goes to
// "<path>.partial" and is renamed onto <path> only by commit(). A crash leaves
// at most a .partial file behind.
#pragma once

#include <fstream>
#include <memory>
#include <string>

namespace vibrotherm::store {

class AtomicFile {
 public:
  /// Opens "<path>.partial" for writing; throws std::runtime_error naming the path.
  explicit AtomicFile(std::string path);
  /// Reopens "<path>.partial" left by an interrupted run, cut back to
  /// `resume_bytes` (its length at the checkpoint), to append to it; throws
  /// naming the file when it is missing or shorter.
  AtomicFile(std::string path, long long resume_bytes);
  ~AtomicFile();  ///< without commit(): removes the partial file
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ofstream& stream() { return out_; }
  /// Flushes and renames onto the final path; throws on I/O failure.
  void commit();
  /// Flushes and renames onto the final path, the stream staying open to write
  /// more (an open file survives its rename); commit() then only closes it.
  void publish_open();
  /// Its length so far, flushed [bytes] (what a checkpoint records).
  long long bytes();
  /// Flushes and leaves the .partial file for a restart instead of removing it.
  void keep();

  /// Renames an already written "<path>.partial" onto path (for files written
  /// by other libraries, e.g. HDF5).
  static void publish(const std::string& path);
  static std::string partial_name(const std::string& path) { return path + ".partial"; }

 private:
  std::string path_;
  std::ofstream out_;
  bool committed_ = false;
  bool published_ = false;  ///< renamed by publish_open()
};

/// A new AtomicFile, or (resume_bytes >= 0) the interrupted run's cut back to resume_bytes.
std::unique_ptr<AtomicFile> OpenAtomicFile(const std::string& path, long long resume_bytes);

}  // namespace vibrotherm::store
