// The options of the PETSc objects vibrotherm makes (its TSs, KSPs, SNESs, the
// partitioner, SLEPc's EPS): PETSc declares them while each object reads its options,
// and with -help prints each one. While OptionAudit listens, those lines are captured
// (and shown only when the user asked for -help): the names and shown values of the
// PETSc objects' options, for the check that each was read ("-wave_ts_typ ... did you
// mean -wave_ts_type?") and for the run record. vibrotherm's own options are known from
// their declarations (option_registry.hpp), not from these lines.
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
/// The options declared so far, while listening (rank 0; empty elsewhere).
void OptionAuditDeclared(std::vector<DeclaredOption>* declared);

/// Options given but never read that are neither vibrotherm's (`known`: the registry's
/// sorted names, option_registry.hpp) nor under a PETSc solver prefix of the program
/// (-wave_ts_*, -heat_ksp_*, ...) nor PETSc's own: an error naming the first with the
/// nearest known name, or (allow_unknown) a warning. likely_typos_only: only names close
/// to a known one (before meshing, when PETSc's objects have not read theirs yet). Collective.
PetscErrorCode CheckUnknownOptions(MPI_Comm comm, const std::vector<std::string>& known, bool allow_unknown,
                                   bool likely_typos_only = false);

/// Options under the prefixes of vibrotherm's PETSc objects (-wave_ts_*,
/// -heat_ksp_*, -heat_free_*, -modes_eps_*, -petscpartitioner_*, ...) that no
/// object read once every solver is set up: under the prefix of a solver the
/// scene has, an error naming the first with the nearest declared name (PETSc's
/// printed options included), or (allow_unknown) a warning; under one it has not
/// (no heat, no -modes), a note that they are ignored. Viewers and convergence
/// reasons, read only while solving, are left to PETSc. Collective; call before
/// the first step.
PetscErrorCode CheckSolverOptionsRead(MPI_Comm comm, const std::vector<DeclaredOption>& declared, bool allow_unknown);
/// After a run: a warning naming a solver option that nothing read even while
/// solving (those CheckSolverOptionsRead leaves to the solves). Collective.
PetscErrorCode WarnUnreadSolverOptions(MPI_Comm comm, const std::vector<DeclaredOption>& declared);

/// One of `names` (vibrotherm's options that take a value, OptionRegistry::names_with_values)
/// given without a value ("-mesh_h" or "-mesh_h ''"), which PETSc's readers take as not
/// given: an error "<name>: needs a value". Collective.
PetscErrorCode CheckMissingValues(MPI_Comm comm, const std::vector<std::string>& names);

}  // namespace vibrotherm
