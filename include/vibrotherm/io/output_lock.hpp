// One run at a time in an output directory: DIR/vibrotherm.lock, created
// atomically (O_CREAT | O_EXCL) by rank 0 and holding "pid host", is the
// directory's for the whole run. Another run into DIR is refused, naming that
// pid and host. A lock whose process is gone (same host: no such process, or
// the pid is no longer a vibrotherm) is stale, left by a crash: taken over with
// a note. A lock from another host cannot be checked: refused, saying which file
// to remove if that run is dead. Without a lock, two runs into one directory
// removed each other's .partial files and renamed each other's outputs.
#pragma once

#include <petscsys.h>

#include <string>

namespace vibrotherm::io {

class OutputLock {
 public:
  OutputLock() = default;
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  ~OutputLock();  ///< removes the lock if this run holds it (also when a run stops on bad input)

  /// Before anything is built: refuses (exit 2) when a live run holds dir's lock.
  /// Creates nothing. Collective.
  static PetscErrorCode CheckFree(MPI_Comm comm, const std::string& dir);
  /// Takes dir's lock (the directory exists), taking over a stale one; refuses
  /// like CheckFree. Collective.
  PetscErrorCode Acquire(MPI_Comm comm, const std::string& dir);
  /// Removes the lock if this run holds it (what the destructor does).
  void Release();

  static constexpr const char* kFileName = "vibrotherm.lock";

 private:
  std::string path_;  ///< the lock this run holds (rank 0), "" when none
  std::string content_;
  bool held_ = false;  ///< this run holds it (every rank)
};

}  // namespace vibrotherm::io
