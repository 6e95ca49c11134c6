// What options the program knows: every reader declares its options to PETSc
// inside PetscOptionsBegin/End blocks; with -help PETSc prints each one. While
// OptionAudit listens, those lines are captured (and shown only when the user
// asked for -help), which gives the list of declared names to check the
// command line against ("-crak_angle: unknown option; did you mean -crack_angle?").
//
// PETSc's help printer is a process-wide function pointer, so the capture is
// too: one audit at a time, between Begin and End, on rank 0.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vibrotherm {

/// An option a reader declared, with the value the help showed (the effective one).
struct DeclaredOption {
  std::string name, value;
  bool operator<(const DeclaredOption& o) const { return name < o.name; }
};

/// Starts listening. echo: the user gave -help (print the help too).
PetscErrorCode OptionAuditBegin(bool echo);
/// Stops listening; declared: every option printed meanwhile, by name (rank 0; empty elsewhere).
PetscErrorCode OptionAuditEnd(std::vector<DeclaredOption>* declared);

/// Options given but never read that are neither declared nor under a PETSc solver
/// prefix of the program (-wave_ts_*, -heat_ksp_*, ...) nor PETSc's own: an error
/// naming the first with the nearest declared name, or (allow_unknown) a warning. Collective.
PetscErrorCode CheckUnknownOptions(MPI_Comm comm, const std::vector<DeclaredOption>& declared, bool allow_unknown);

/// A declared option given without a value ("-mesh_h" or "-mesh_h ''"), which
/// PETSc's readers take as not given: an error "<name>: needs a value" (flags,
/// shown TRUE or FALSE, excepted). Collective.
PetscErrorCode CheckMissingValues(MPI_Comm comm, const std::vector<DeclaredOption>& declared);

}  // namespace vibrotherm
