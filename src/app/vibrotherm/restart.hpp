// Restarting a run from its checkpoint (-restart DIR): the checkpoint is read
// and checked against this run's options before anything is written.
#pragma once

#include <petscsys.h>

#include <string>

#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/io/run_summary.hpp"

namespace vibrotherm::app {

/// The options a restart must share with the run it continues, as "name=value"
/// lines: those given (defaults may depend on the rank count), except those
/// that only say where and how often to write (rank 0).
std::string OptionFingerprint(const io::RunSummary& summary);

/// Reads DIR/checkpoint.h5 and refuses it, naming the first option that
/// differs, when it was written with other options. Collective.
PetscErrorCode ReadRestart(MPI_Comm comm, const std::string& dir, const std::string& fingerprint,
                           store::Checkpoint* checkpoint);

}  // namespace vibrotherm::app
