#include "vibrotherm/util/option_audit.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <sstream>

#include "vibrotherm/options/option_database.hpp"

namespace vibrotherm {
namespace {

/// The capture (PETSc's printer is global, see the header).
struct Capture {
  bool active = false, echo = false, added_help = false;
  bool in_help_line = false;  ///< a help line printed in pieces (PETSc's type lists) is not finished
  std::string text;
  PetscErrorCode (*original)(MPI_Comm, const char[], ...) = nullptr;
  PetscErrorCode (*original_vfprintf)(FILE*, const char[], va_list) = nullptr;
};
Capture& TheCapture() {
  static Capture capture;
  return capture;
}

PetscErrorCode CapturingHelpPrintf(MPI_Comm comm, const char format[], ...) {
  char buffer[4096];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  Capture& c = TheCapture();
  c.text += buffer;
  if (c.echo && c.original) return (*c.original)(comm, "%s", buffer);
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

/// Prefixes of options the program passes to PETSc objects, and PETSc's own options.
bool PetscOwned(const std::string& name) {
  static const char* prefixes[] = {
      "wave_ts_", "wave_snes_", "wave_ksp_", "wave_pc_", "heat_ts_", "heat_snes_", "heat_ksp_", "heat_pc_",
      "heat_free_", "heat_redundant_", "modes_eps_", "modes_st_", "modes_ksp_", "modes_pc_", "modes_mat_",
      "petscpartitioner_", "dm_", "mat_", "vec_", "log", "malloc", "options_", "info", "on_error", "history", "help",
      "version", "objects_", "checkstack", "fp_trap", "viewer_", "memory_view", "no_signal_handler", "skip_petscrc",
      "check_pointer_intensity", "mpi_", "start_in_debugger", "stop_for_debugger", "debugger", "display", "nox",
      "x_virtual", "saws", "use_gpu", "sys_view", "preload", "omp_", "blas_", "hypre_", "mumps_"};
  return std::any_of(std::begin(prefixes), std::end(prefixes),
                     [&](const char* p) { return name.rfind(p, 0) == 0; });
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

PetscErrorCode OptionAuditEnd(std::vector<DeclaredOption>* declared) {
  PetscFunctionBeginUser;
  Capture& c = TheCapture();
  if (c.added_help) PetscCall(PetscOptionsClearValue(nullptr, "-help"));
  PetscHelpPrintf = c.original;
  PetscVFPrintf = c.original_vfprintf;
  c.active = false;
  declared->clear();
  std::istringstream lines(c.text);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || start == 0 || line[start] != '-') continue;
    const std::size_t end = line.find_first_of(" <:", start);
    declared->push_back({line.substr(start, end - start), ShownValue(line)});
  }
  std::stable_sort(declared->begin(), declared->end());
  declared->erase(std::unique(declared->begin(), declared->end(),
                              [](const DeclaredOption& a, const DeclaredOption& b) { return a.name == b.name; }),
                  declared->end());
  PetscFunctionReturn(0);
}

PetscErrorCode CheckUnknownOptions(MPI_Comm comm, const std::vector<DeclaredOption>& declared_options,
                                   bool allow_unknown) {
  PetscFunctionBeginUser;
  std::vector<std::string> declared;
  for (const DeclaredOption& d : declared_options) declared.push_back(d.name);
  PetscInt n;
  char **names, **values;
  PetscCall(PetscOptionsLeftGet(nullptr, &n, &names, &values));
  std::string unknown, nearest;
  for (PetscInt i = 0; i < n && unknown.empty(); ++i) {
    const std::string name = names[i][0] == '-' ? names[i] + 1 : names[i];
    if (PetscOwned(name) || std::binary_search(declared.begin(), declared.end(), "-" + name)) continue;
    unknown = "-" + name;
    nearest = options::nearest_name(unknown, declared);
  }
  PetscCall(PetscOptionsLeftRestore(nullptr, &n, &names, &values));
  // Rank 0 saw the help (the declared list): it decides for all.
  int found = unknown.empty() ? 0 : 1;
  PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, comm));
  if (!found) PetscFunctionReturn(0);
  const std::string hint = nearest.empty() ? " (-help lists the options)" : "; did you mean " + nearest + "?";
  if (allow_unknown) {
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: %s is not an option of vibrotherm%s (-allow_unknown: ignored)\n",
                          unknown.c_str(), hint.c_str()));
    PetscFunctionReturn(0);
  }
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s is not an option of vibrotherm%s (-allow_unknown passes it on)",
          unknown.c_str(), hint.c_str());
}

PetscErrorCode CheckMissingValues(MPI_Comm comm, const std::vector<DeclaredOption>& declared) {
  PetscFunctionBeginUser;
  // PETSc takes "-mesh_h" without a value (or with "") as not given: the run would
  // go on with the default. Flags (shown TRUE or FALSE) need no value.
  std::string missing;
  for (const DeclaredOption& d : declared) {
    if (d.value == "TRUE" || d.value == "FALSE") continue;
    PetscBool given = PETSC_FALSE;
    PetscCall(PetscOptionsHasName(nullptr, nullptr, d.name.c_str(), &given));
    if (!given) continue;
    char value[8] = "";
    PetscCall(PetscOptionsGetString(nullptr, nullptr, d.name.c_str(), value, sizeof(value), nullptr));
    if (value[0] == '\0') {
      missing = d.name;
      break;
    }
  }
  // Rank 0 saw the help (the declared list): it decides for all.
  int found = missing.empty() ? 0 : 1;
  PetscCallMPI(MPI_Bcast(&found, 1, MPI_INT, 0, comm));
  PetscCheck(!found, comm, PETSC_ERR_USER_INPUT, "%s: needs a value", missing.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm
