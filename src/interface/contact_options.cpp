#include "vibrotherm/interface/contact_options.hpp"

#include <string>
#include <vector>

#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm {
namespace {

/// -name choice from a registry, with an error listing the known names.
template <class Entry>
PetscErrorCode ReadChoice(MPI_Comm comm, PetscOptionItems* PetscOptionsObject, const char* option, const char* text,
                          const std::vector<Entry>& entries, std::string& value) {
  PetscFunctionBeginUser;
  std::vector<const char*> names;
  std::string known;
  for (const Entry& e : entries) {
    names.push_back(e.name);
    known += known.empty() ? e.name : std::string("|") + e.name;
  }
  char buf[256];
  PetscBool set = PETSC_FALSE;
  PetscCall(PetscStrncpy(buf, value.c_str(), sizeof(buf)));
  PetscCall(PetscOptionsString(option, text, nullptr, value.c_str(), buf, sizeof(buf), &set));
  if (!set) PetscFunctionReturn(0);
  for (const char* n : names) {
    if (std::string(buf) == n) {
      value = buf;
      PetscFunctionReturn(0);
    }
  }
  SETERRQ(comm, PETSC_ERR_USER_INPUT, "%s: unknown value '%s' (known: %s)", option, buf, known.c_str());
}

}  // namespace

PetscErrorCode ReadContactOptions(MPI_Comm comm, contact::ContactParameters& p) {
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, nullptr, "Crack contact law (PHYSICS.md section 3)", nullptr);
  PetscCall(ReadChoice(comm, PetscOptionsObject, "-crack_law", "Crack law", contact::crack_laws(), p.crack_law));
  PetscCall(PetscOptionsReal("-contact_mu", "Friction coefficient", nullptr, p.mu, &p.mu, nullptr));
  PetscCall(PetscOptionsReal("-contact_nu", "Poisson ratio in Mindlin's theta", nullptr, p.nu, &p.nu, nullptr));
  PetscCall(ReadChoice(comm, PetscOptionsObject, "-contact_normal_law", "Normal law N(a)", contact::normal_laws(),
                       p.normal_law));
  PetscCall(PetscOptionsReal("-contact_normal_C",
                             "power: C in N = C a^p [Pa/m^p] (default 1e18); biwa: C_B in K = C_B N^m [Pa^(1-m)/m] (default: K = 1e14 Pa/m at 1 MPa, 1e11 for m = 1/2)", nullptr,
                             p.normal_C, &p.normal_C, nullptr));
  PetscCall(PetscOptionsReal("-contact_normal_p", "power: exponent p >= 1", nullptr, p.normal_p, &p.normal_p, nullptr));
  PetscCall(PetscOptionsReal("-contact_normal_m", "biwa: exponent m in (0,1)", nullptr, p.normal_m, &p.normal_m, nullptr));
  PetscCall(PetscOptionsReal("-contact_normal_k", "linear: N = k a [Pa/m]", nullptr, p.normal_k, &p.normal_k, nullptr));
  char table[PETSC_MAX_PATH_LEN] = "";
  PetscBool has_table = PETSC_FALSE;
  PetscCall(PetscOptionsString("-contact_normal_table", "table: CSV file of a,N pairs", nullptr, p.normal_table.c_str(),
                               table, sizeof(table), &has_table));
  if (has_table) p.normal_table = table;
  PetscCall(PetscOptionsReal("-contact_a0", "Initial approach added to a [m]", nullptr, p.a0, &p.a0, nullptr));
  PetscCall(PetscOptionsReal("-contact_tangential_k", "linear, coulomb: tangential stiffness [Pa/m]", nullptr,
                             p.tangential_k, &p.tangential_k, nullptr));
  PetscCall(PetscOptionsReal("-contact_mmd_tol", "mmd: shortest kept diagram segment relative to a", nullptr,
                             p.mmd_rel_tol, &p.mmd_rel_tol, nullptr));
  PetscCall(PetscOptionsInt("-contact_mmd_max_breakpoints", "mmd: hard bound on breakpoints per cell", nullptr,
                            p.mmd_max_breakpoints, &p.mmd_max_breakpoints, nullptr));
  PetscOptionsEnd();
  VibrothermCallCpp(comm, p.validate());
  VibrothermCallCpp(comm, (void)contact::create_crack_law(p));  // checks law-specific values and table files
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm
