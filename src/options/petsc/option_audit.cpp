#include "vibrotherm/options/petsc/option_audit.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <set>
#include <sstream>

#include "vibrotherm/options/option_database.hpp"

namespace vibrotherm {
namespace {

/// The capture (PETSc's printer is global, see the header).
struct Capture {
  bool active = false, echo = false, added_help = false;
  bool in_help_line = false;  ///< a help line printed in pieces (PETSc's type lists) is not finished
  bool in_viewers = false;    ///< echoing a section of PETSc's viewer options (not echoed)
  std::set<std::string> echoed;  ///< options whose help line was shown (shown once)
  std::string text;
  PetscErrorCode (*original)(MPI_Comm, const char[], ...) = nullptr;
  PetscErrorCode (*original_vfprintf)(FILE*, const char[], va_list) = nullptr;
};
Capture& TheCapture() {
  static Capture capture;
  return capture;
}

/// Whether a piece of help is shown: not PETSc's sections of viewer options (ascii, binary,
/// draw, ... for every -*_view), and an option read by two modules (-material_nu by the
/// material and the mmd law, -force by the mesh and -modes) once.
bool ShowHelp(Capture& c, const std::string& piece) {
  if (piece.rfind("----", 0) == 0) c.in_viewers = piece.find("\nViewer (") != std::string::npos;
  if (c.in_viewers) return false;
  if (piece.rfind("  -", 0) != 0) return true;
  const std::string name = piece.substr(2, piece.find_first_of(" :<", 2) - 2);
  return c.echoed.insert(name).second;
}

PetscErrorCode CapturingHelpPrintf(MPI_Comm comm, const char format[], ...) {
  char buffer[4096];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  Capture& c = TheCapture();
  c.text += buffer;
  if (c.echo && c.original && ShowHelp(c, buffer)) return (*c.original)(comm, "%s", buffer);
  return 0;
}

/// PETSc prints the help of type lists (-petscpartitioner_type, -wave_ts_type) with
/// PetscFPrintf on stdout, not through PetscHelpPrintf: those pieces are help too.
PetscErrorCode CapturingVFPrintf(FILE* fd, const char format[], va_list args) {
  Capture& c = TheCapture();
  char buffer[4096];
  va_list copy;
  va_copy(copy, args);
  std::vsnprintf(buffer, sizeof(buffer), format, copy);
  va_end(copy);
  const std::string piece = buffer;
  if (fd == PETSC_STDOUT && (c.in_help_line || piece.rfind("  -", 0) == 0)) {
    c.text += piece;
    c.in_help_line = piece.find('\n') == std::string::npos;
    if (!c.echo) return 0;
  }
  return (*c.original_vfprintf)(fd, format, args);
}

/// Prefixes of the options of the PETSc objects vibrotherm creates (its solvers
/// and the partitioner): checked against what those objects read.
const char* const kSolverPrefixes[] = {
    "wave_ts_", "wave_snes_", "wave_ksp_", "wave_pc_", "heat_ts_", "heat_snes_", "heat_ksp_", "heat_pc_",
    "heat_free_", "heat_redundant_", "heat_psubcomm_", "modes_eps_", "modes_st_", "modes_ksp_", "modes_pc_",
    "modes_mat_", "wave_stability_", "wave_harmonic_", "petscpartitioner_"};
/// PETSc's own options (read by PetscInitialize, logging, viewers, the DM and matrix layers).
const char* const kPetscPrefixes[] = {
    "dm_", "mat_", "vec_", "log", "malloc", "options_", "info", "on_error", "history", "help",
    "version", "objects_", "checkstack", "fp_trap", "viewer_", "memory_view", "no_signal_handler", "skip_petscrc",
    "check_pointer_intensity", "mpi_", "start_in_debugger", "stop_for_debugger", "debugger", "display", "nox",
    "x_virtual", "saws", "use_gpu", "sys_view", "preload", "omp_", "blas_", "hypre_", "mumps_"};

bool StartsWithAny(const std::string& name, const char* const* begin, const char* const* end) {
  return std::any_of(begin, end, [&](const char* p) { return name.rfind(p, 0) == 0; });
}
/// The solver prefix an option is under ("" when none).
std::string SolverPrefix(const std::string& name) {
  for (const char* p : kSolverPrefixes)
    if (name.rfind(p, 0) == 0) return p;
  return "";
}
bool SolverOption(const std::string& name) { return !SolverPrefix(name).empty(); }
bool PetscOwned(const std::string& name) {
  return SolverOption(name) || StartsWithAny(name, std::begin(kPetscPrefixes), std::end(kPetscPrefixes));
}

/// Options PETSc reads only when a solve runs or ends (viewers, convergence
/// reasons; the heat's PCREDUNDANT, its subcommunicator and inner solver, made by the first
/// solve of each step length: heat/rung_solvers.hpp),
/// not when the object is set up: not held against the user before a step.
bool ReadWhileSolving(const std::string& name) {
  return name.find("view") != std::string::npos || name.find("converged_reason") != std::string::npos ||
         name.find("redundant_") != std::string::npos || name.find("psubcomm_") != std::string::npos;
}

/// The options given but never read (rank 0's list), as names without the dash.
std::vector<std::string> OptionsLeft() {
  std::vector<std::string> left;
  PetscInt n;
  char **names, **values;
  if (PetscOptionsLeftGet(nullptr, &n, &names, &values)) return left;
  for (PetscInt i = 0; i < n; ++i) left.push_back(names[i][0] == '-' ? names[i] + 1 : names[i]);
  PetscOptionsLeftRestore(nullptr, &n, &names, &values);
  return left;
}

/// One option nobody read: an error naming it and its nearest declared name, or
/// (allow_unknown) a warning. `what` says why it counts as unknown. Collective.
PetscErrorCode RefuseUnknown(MPI_Comm comm, const std::string& unknown, const std::string& nearest, const char* what,
                             bool allow_unknown) {
  PetscFunctionBeginUser;
  // Rank 0 saw the help (the declared list): it decides for all.
  int found = unknown.empty() ? 0 : 1;
  PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, comm));
  if (!found) PetscFunctionReturn(0);
  const std::string hint = nearest.empty() ? " (-help lists the options)" : "; did you mean " + nearest + "?";
  if (allow_unknown) {
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: %s %s%s (-allow_unknown: ignored)\n", unknown.c_str(), what,
                          hint.c_str()));
    PetscFunctionReturn(0);
  }
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s %s%s (-allow_unknown passes it on)", unknown.c_str(), what, hint.c_str());
}

}  // namespace

PetscErrorCode OptionAuditBegin(bool echo) {
  PetscFunctionBeginUser;
  Capture& c = TheCapture();
  c = Capture{};
  c.active = true;
  c.echo = echo;
  c.original = PetscHelpPrintf;
  c.original_vfprintf = PetscVFPrintf;
  PetscHelpPrintf = CapturingHelpPrintf;
  PetscVFPrintf = CapturingVFPrintf;
  PetscBool help = PETSC_FALSE;
  PetscCall(PetscOptionsHasName(nullptr, nullptr, "-help", &help));
  if (!help) PetscCall(PetscOptionsSetValue(nullptr, "-help", nullptr));
  c.added_help = !help;
  PetscFunctionReturn(0);
}

namespace {

/// The value a help line shows: "<now A : formerly B>" → A, "<A : B>" → A, "<A>" → A.
std::string ShownValue(const std::string& line) {
  const std::size_t open = line.find('<'), close = line.find('>', open);
  if (open == std::string::npos || close == std::string::npos) return "";
  std::string v = line.substr(open + 1, close - open - 1);
  if (v.rfind("now ", 0) == 0) v = v.substr(4);
  const std::size_t colon = v.find(" : ");
  return colon == std::string::npos ? v : v.substr(0, colon);
}

}  // namespace

namespace {

/// The options the help printed (name and shown value), sorted, each once.
std::vector<DeclaredOption> ParseDeclared(const std::string& text) {
  std::vector<DeclaredOption> declared;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || start == 0 || line[start] != '-') continue;
    const std::size_t end = line.find_first_of(" <:", start);
    declared.push_back({line.substr(start, end - start), ShownValue(line)});
  }
  std::stable_sort(declared.begin(), declared.end());
  declared.erase(std::unique(declared.begin(), declared.end(),
                             [](const DeclaredOption& a, const DeclaredOption& b) { return a.name == b.name; }),
                 declared.end());
  return declared;
}

std::vector<std::string> Names(const std::vector<DeclaredOption>& declared) {
  std::vector<std::string> names;
  for (const DeclaredOption& d : declared) names.push_back(d.name);
  return names;
}

}  // namespace

void OptionAuditDeclared(std::vector<DeclaredOption>* declared) { *declared = ParseDeclared(TheCapture().text); }

PetscErrorCode OptionAuditEnd(std::vector<DeclaredOption>* declared) {
  PetscFunctionBeginUser;
  Capture& c = TheCapture();
  if (c.added_help) PetscCall(PetscOptionsClearValue(nullptr, "-help"));
  PetscHelpPrintf = c.original;
  PetscVFPrintf = c.original_vfprintf;
  c.active = false;
  *declared = ParseDeclared(c.text);
  PetscFunctionReturn(0);
}

PetscErrorCode CheckUnknownOptions(MPI_Comm comm, const std::vector<std::string>& known, bool allow_unknown,
                                   bool likely_typos_only) {
  PetscFunctionBeginUser;
  std::string unknown, nearest;
  for (const std::string& name : OptionsLeft()) {
    if (PetscOwned(name) || std::binary_search(known.begin(), known.end(), "-" + name)) continue;
    const std::string near = options::nearest_name("-" + name, known);
    if (likely_typos_only && near.empty()) continue;
    unknown = "-" + name;
    nearest = near;
    break;
  }
  PetscCall(RefuseUnknown(comm, unknown, nearest, "is not an option of vibrotherm", allow_unknown));
  PetscFunctionReturn(0);
}

namespace {

/// Solver options given and not read yet: *unread, the first under the prefix of a
/// solver this scene has (it declared options); *absent, those under one it has not.
/// Before the steps, those read only while solving are not counted.
void UnreadSolverOptions(const std::vector<std::string>& declared, bool before_steps, std::string* unread,
                         std::string* absent) {
  unread->clear(), absent->clear();
  for (const std::string& name : OptionsLeft()) {
    if (!SolverOption(name) || (before_steps && ReadWhileSolving(name))) continue;
    const std::string prefix = "-" + SolverPrefix(name);
    const bool present = std::any_of(declared.begin(), declared.end(),
                                     [&](const std::string& d) { return d.rfind(prefix, 0) == 0; });
    if (!present) *absent += (absent->empty() ? "-" : ", -") + name;
    else if (unread->empty()) *unread = "-" + name;
  }
}

}  // namespace

PetscErrorCode CheckSolverOptionsRead(MPI_Comm comm, const std::vector<DeclaredOption>& declared_options,
                                      bool allow_unknown) {
  PetscFunctionBeginUser;
  const std::vector<std::string> declared = Names(declared_options);
  // Under the prefix of a solver this scene has: a typo. Under one it has not (-heat_*
  // with -heat off, -modes_* without -modes): an options file written for other scenes.
  std::string unknown, absent;
  UnreadSolverOptions(declared, true, &unknown, &absent);
  if (!absent.empty())  // rank 0's list is the one printed
    PetscCall(PetscPrintf(comm, "vibrotherm: note: %s ignored: no solver of this scene reads them\n", absent.c_str()));
  const std::string nearest = unknown.empty() ? "" : options::nearest_name(unknown, declared);
  PetscCall(RefuseUnknown(comm, unknown, nearest,
                          "was read by none of the PETSc solvers of this run (misspelt, or for a solver this scene does "
                          "not use)",
                          allow_unknown));
  PetscFunctionReturn(0);
}

PetscErrorCode WarnUnreadSolverOptions(MPI_Comm comm, const std::vector<DeclaredOption>& declared) {
  PetscFunctionBeginUser;
  std::string unread, absent;  // the absent ones were noted before the steps
  UnreadSolverOptions(Names(declared), false, &unread, &absent);
  // Rank 0 speaks for all.
  int found = unread.empty() ? 0 : 1;
  PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, comm));
  if (found)
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: %s was never read by a PETSc solver of this run (misspelt, or for "
                                "a solver this scene did not use)\n", unread.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckMissingValues(MPI_Comm comm, const std::vector<std::string>& names) {
  PetscFunctionBeginUser;
  // PETSc takes "-mesh_h" without a value (or with "") as not given: the run would
  // go on with the default.
  std::string missing;
  for (const std::string& name : names) {
    if (PetscOwned(name.substr(1))) continue;  // -dm_refine: PETSc's prefix, its reader checks
    PetscBool given = PETSC_FALSE;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &given));
    if (!given) continue;
    char value[8] = "";
    PetscCall(PetscOptionsGetString(nullptr, nullptr, name.c_str(), value, sizeof(value), nullptr));
    if (value[0] == '\0') {
      missing = name;
      break;
    }
  }
  // Every rank holds the same options and names: rank 0 decides for all.
  int found = missing.empty() ? 0 : 1;
  PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, comm));
  PetscCheck(!found, comm, PETSC_ERR_USER_INPUT, "%s: needs a value", missing.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm
