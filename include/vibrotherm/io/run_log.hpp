// vibrotherm.log: everything the run prints (stdout and stderr of rank 0), in
// the output directory. Printing starts before the directory exists (it is
// created only once all input is checked): the text is held until Open, then
// written as it comes, to vibrotherm.log.partial, renamed by Close. A killed run
// leaves only the .partial.
//
// PETSc prints through one process-wide function pointer (PetscVFPrintf); the
// log wraps it between Install and Close, one log at a time.
#pragma once

#include <petscsys.h>

#include <string>

namespace vibrotherm::io {

/// Starts holding what rank 0 prints.
PetscErrorCode RunLogInstall();
/// The output directory exists: write what was held, and the rest as it comes.
PetscErrorCode RunLogOpen(MPI_Comm comm, const std::string& path);
/// Renames the log onto its final name now, writing on into it: a run says
/// "complete" in summary.json only once its log is in place.
PetscErrorCode RunLogPublish();
/// Publishes the log (unless done) and restores PETSc's printer.
PetscErrorCode RunLogClose();

}  // namespace vibrotherm::io
