// A run's output directory: checked before anything is built (another run
// working there, an interrupted run's checkpoint), then made, locked for the
// run (io/output_lock.hpp) and cleared of an earlier run's outputs once all
// input is checked. A checkpoint is deleted only by the complete run it belongs
// to (a restart that finished) or at the user's word (-overwrite).
#pragma once

#include <petscsys.h>

#include <string>

#include "vibrotherm/io/output_lock.hpp"

namespace vibrotherm::app {

/// Refuses (exit 2, one line) a directory a live run holds, one holding an
/// interrupted run's checkpoint when the run neither restarts it nor was given
/// -overwrite, and a restart without a checkpoint. Creates nothing. Collective.
PetscErrorCode CheckOutputDirectory(MPI_Comm comm, const std::string& dir, bool restart, bool overwrite);
/// Creates the directory (rank 0), takes its lock, and removes an earlier run's
/// outputs; a restart keeps what its checkpoint continues. Collective.
PetscErrorCode MakeOutputDirectory(MPI_Comm comm, const std::string& dir, bool restart, io::OutputLock* lock);
/// A complete run needs no checkpoint: removed, so that no -restart repeats its end.
PetscErrorCode RemoveCheckpoint(MPI_Comm comm, const std::string& dir);
/// Whether two spellings name one directory (relative or absolute, links, "..").
bool SameDirectory(const std::string& a, const std::string& b);

}  // namespace vibrotherm::app
