// A run's output directory: checked before anything is built (a file where the
// directory should be, another run working there, an interrupted run's checkpoint,
// an earlier run's results), then made and locked before meshing (a second run
// started at the same time is refused at once; io/output_lock.hpp), and cleared of
// an earlier run's outputs (-overwrite) once all input is checked. Nothing of an
// earlier run is deleted without -overwrite; a checkpoint is deleted only by the
// complete run it belongs to (a restart that finished) or at the user's word.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/io/output_lock.hpp"

namespace vibrotherm::app {

/// Refuses (exit 2, one line) a path that is not a directory, a directory a live run
/// holds, one holding an interrupted run's checkpoint when the run neither restarts it
/// nor was given -overwrite, one holding an earlier run's outputs without -overwrite (a
/// restart continues them), and a restart without a checkpoint. Creates nothing. Collective.
PetscErrorCode CheckOutputDirectory(MPI_Comm comm, const std::string& dir, bool restart, bool overwrite);

/// The directory from before meshing to the end of the run.
class OutputDirectory {
 public:
  OutputDirectory() = default;
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;
  /// Releases the lock; a directory this run created is removed again when the run
  /// wrote nothing into it (bad input found after meshing leaves nothing behind).
  ~OutputDirectory();

  /// Creates the directory (rank 0) and takes its lock; a path that cannot be a
  /// directory or cannot be written is refused now, naming the reason. Collective.
  PetscErrorCode Claim(MPI_Comm comm, const std::string& dir);
  /// All input is checked: an earlier run's outputs are removed (the check allowed it:
  /// -overwrite); a restart keeps what its checkpoint continues and renames the
  /// interrupted run's log vibrotherm.before-restart.log. The directory is the run's
  /// from now on. Collective.
  PetscErrorCode Prepare(MPI_Comm comm, bool restart);
  /// A file the setup wrote into the directory (the mesh gmsh made of a .geo): removed again
  /// when the run stops before Prepare, so that refused input leaves nothing behind.
  void AddSetupFile(const std::string& path) { setup_files_.push_back(path); }
  const std::string& dir() const { return dir_; }

 private:
  MPI_Comm comm_ = MPI_COMM_NULL;
  std::string dir_;
  bool created_ = false;  ///< by this run
  bool written_ = false;  ///< Prepare()d: the run writes into it
  io::OutputLock lock_;
  std::vector<std::string> setup_files_;
};

/// A complete run needs no checkpoint: removed, so that no -restart repeats its end.
PetscErrorCode RemoveCheckpoint(MPI_Comm comm, const std::string& dir);
/// Whether two spellings name one directory (relative or absolute, links, "..").
bool SameDirectory(const std::string& a, const std::string& b);

}  // namespace vibrotherm::app
