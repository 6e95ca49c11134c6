#include "vibrotherm/interface/approach_profile.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "vibrotherm/contact/contact_parameters.hpp"
#include "vibrotherm/contact/csv_rows.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::interface {

double ApproachProfile::at(double xi) const {
  double profile = shape == ApproachShape::Elliptic ? max * std::sqrt(std::max(0.0, 1.0 - (2.0 * xi - 1.0) * (2.0 * xi - 1.0))) : 0.0;
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

const std::vector<OptionSpec<ApproachProfile>>& ApproachProfileOptionSpecs() {
  using P = ApproachProfile;
  using contact::Range;
  static const std::vector<OptionSpec<P>> specs = {
      RealOption("-crack_a0", &P::uniform, Range::any(), "m", "Uniform initial approach a0 (> 0: pre-closed)"),
      ChoiceOption("-crack_a0_profile", &P::shape, {"uniform", "elliptic", "file"},
                   "Shape of a0 along the crack added to -crack_a0"),
      RealOption("-crack_a0_max", &P::max, Range::any(), "m", "Elliptic profile: a0 at the crack centre"),
      TextOption("-crack_a0_file", &P::file, "file profile: CSV with columns xi,a0 (xi in [0,1] along the crack)"),
  };
  return specs;
}

PetscErrorCode ReadApproachProfile(MPI_Comm comm, ApproachProfile* p, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "Initial approach of the crack faces", ApproachProfileOptionSpecs(), p, values));
  const std::string& file = p->file;
  if (p->shape == ApproachShape::File) {
    PetscCheck(!file.empty(), comm, PETSC_ERR_USER_INPUT, "-crack_a0_profile file needs -crack_a0_file FILE");
    VibrothermCallCpp(comm, {
      for (const contact::CsvRow& r : contact::read_csv_rows(file, "-crack_a0_file", {"xi", "a0"})) {
        if (!(r.values[0] >= 0.0 && r.values[0] <= 1.0))
          throw contact::InputError("-crack_a0_file " + file + " line " + std::to_string(r.line) +
                                    ": xi = " + std::to_string(r.values[0]) + " outside [0, 1]");
        if (!p->table.empty() && !(r.values[0] > p->table.back().first))
          throw contact::InputError("-crack_a0_file " + file + " line " + std::to_string(r.line) +
                                    ": xi must increase");
        p->table.emplace_back(r.values[0], r.values[1]);
      }
      if (p->table.empty()) throw contact::InputError("-crack_a0_file " + file + ": no data rows");
    });
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::interface
