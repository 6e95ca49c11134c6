#include "vibrotherm/interface/approach_profile.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vibrotherm/contact/contact_parameters.hpp"
#include "vibrotherm/contact/csv_rows.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/options/petsc/option_choice.hpp"

namespace vibrotherm::interface {

double ApproachProfile::at(double xi) const {
  double profile = elliptic ? max * std::sqrt(std::max(0.0, 1.0 - (2.0 * xi - 1.0) * (2.0 * xi - 1.0))) : 0.0;
  if (!table.empty()) {
    const auto it = std::lower_bound(table.begin(), table.end(), std::make_pair(xi, -1e300));
    if (it == table.begin()) profile = table.front().second;
    else if (it == table.end()) profile = table.back().second;
    else {
      const auto& [x1, y1] = *it;
      const auto& [x0, y0] = *(it - 1);
      profile = y0 + (y1 - y0) * (xi - x0) / (x1 - x0);
    }
  }
  return uniform + profile;
}

PetscErrorCode ReadApproachProfile(MPI_Comm comm, ApproachProfile* p) {
  PetscFunctionBeginUser;
  char file[PETSC_MAX_PATH_LEN] = "";
  PetscInt kind = 0;  // uniform
  PetscOptionsBegin(comm, nullptr, "Initial approach of the crack faces", nullptr);
  PetscCall(PetscOptionsReal("-crack_a0", "Uniform initial approach a0 [m] (> 0: pre-closed)", nullptr, p->uniform,
                             &p->uniform, nullptr));
  PetscCall(OptionsChoice(PetscOptionsObject, "-crack_a0_profile", "Shape of a0 along the crack added to -crack_a0",
                          {"uniform", "elliptic", "file"}, &kind, nullptr));
  PetscCall(PetscOptionsReal("-crack_a0_max", "Elliptic profile: a0 at the crack centre [m]", nullptr, p->max, &p->max,
                             nullptr));
  PetscCall(PetscOptionsString("-crack_a0_file", "file profile: CSV with columns xi,a0 (xi in [0,1] along the crack)",
                               nullptr, file, file, sizeof(file), nullptr));
  PetscOptionsEnd();
  p->elliptic = kind == 1;
  if (kind == 2) {
    PetscCheck(file[0], comm, PETSC_ERR_USER_INPUT, "-crack_a0_profile file needs -crack_a0_file FILE");
    VibrothermCallCpp(comm, {
      for (const contact::CsvRow& r : contact::read_csv_rows(file, "-crack_a0_file", {"xi", "a0"})) {
        if (!(r.values[0] >= 0.0 && r.values[0] <= 1.0))
          throw contact::InputError(std::string("-crack_a0_file ") + file + " line " + std::to_string(r.line) +
                                    ": xi = " + std::to_string(r.values[0]) + " outside [0, 1]");
        if (!p->table.empty() && !(r.values[0] > p->table.back().first))
          throw contact::InputError(std::string("-crack_a0_file ") + file + " line " + std::to_string(r.line) +
                                    ": xi must increase");
        p->table.emplace_back(r.values[0], r.values[1]);
      }
      if (p->table.empty()) throw contact::InputError(std::string("-crack_a0_file ") + file + ": no data rows");
    });
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface
