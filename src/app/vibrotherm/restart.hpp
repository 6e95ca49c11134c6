// Restarting a run from its checkpoint (-restart DIR): the checkpoint is read and
// checked against this run's options before meshing (so that nothing expensive, not
// the harmonic start's factorisation, is done for a restart that cannot be), and
// against the options of PETSc's objects once they are set up.
#pragma once

#include <petscsys.h>

#include <set>
#include <string>
#include <vector>

#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/store/checkpoint.hpp"

namespace vibrotherm::app {

/// The options a restart must share with the run it continues, as "name=value"
/// lines: those given (defaults may depend on the rank count), except those
/// that only say where and how often to write (rank 0).
std::string OptionFingerprint(const std::vector<io::OptionRecord>& options);

/// The first option whose value differs between two fingerprints, both sides named
/// ("-source_amplitude: 1e-07 in the checkpoint, 2e-07 now"; "" when none); only the
/// options in `names` when it is given.
std::string FirstDifference(const std::string& checkpoint, const std::string& now,
                            const std::set<std::string>* names = nullptr);

/// Reads DIR/checkpoint.h5 and refuses it, naming the first option that differs, when
/// it was written with other options; before meshing, only the options in `names` (those
/// declared so far: PETSc's objects declare theirs at their setup) are compared.
/// Collective.
PetscErrorCode ReadRestart(MPI_Comm comm, const std::string& dir, const std::string& fingerprint,
                           const std::set<std::string>& names, store::Checkpoint* checkpoint);
/// Once every option is declared: the whole fingerprint compared. Collective.
PetscErrorCode CheckRestartOptions(MPI_Comm comm, const std::string& dir, const std::string& fingerprint,
                                   const store::Checkpoint& checkpoint);

}  // namespace vibrotherm::app
