// Where the model stops meaning what its user wants, said at setup (or when it
// happens) instead of a "complete" run with absurd numbers. The model is linear
// elasticity with small strains, constant material properties, and a mesh that
// must carry the source's waves:
//   strain  the source's strain amplitude (2π f A / c for a displacement source,
//           A / (ρ c²) for a traction): above 1e-3 (metals yield near it) a
//           warning, above 1e-2 (small strain itself fails) refused, naming
//           -source_amplitude;
//   mesh    nodes per shear wavelength c_s / f over the coarsest element's node
//           spacing: below 8 a warning, below 2 (the mesh cannot carry the wave
//           at all) refused, naming -source_frequency and -mesh_h;
//   heat    a rise above kConstantPropertyRise (field_peak.hpp): a warning, once (FieldPeak);
//   response the strain the waves reach, not only the source's: max |v| / c_s over the
//           specimen (a plane wave's strain amplitude, the larger of the two wave
//           speeds' estimates), checked once per coupling interval: above 1e-3 and
//           above 1e-2 a warning each, once (a resonance can strain a specimen far
//           beyond what its source alone would: ResponseStrain).
// Warnings are also kept in summary.json "warnings".
#pragma once

#include <petscsys.h>

#include <vector>

#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/io/run_summary.hpp"

namespace vibrotherm::coupling {

/// Before meshing: the strain check, and the mesh check against the finest element the options
/// ask for (finest_h [m]; 0: unknown, a mesh file). Collective.
PetscErrorCode CheckSourceBeforeMeshing(MPI_Comm comm, const Scene& scene, double finest_h, io::RunSummary* summary);
/// Once meshed: the mesh check; h_max: the largest element edge [m]. Collective.
PetscErrorCode CheckSourceValidity(MPI_Comm comm, const Scene& scene, double h_max, io::RunSummary* summary);

/// The response's strain (above): the largest estimate so far, a warning when it crosses a limit.
class ResponseStrain {
 public:
  explicit ResponseStrain(double shear_speed) : shear_speed_(shear_speed) {}
  /// max |v| / c_s now; warns (once per limit) at t. Collective.
  PetscErrorCode Check(const wave::WaveSolver& waves, io::RunSummary* summary);
  double peak() const { return peak_; }
  /// The peak so far and the limits warned about: a restart continues them.
  std::vector<double> state() const { return {peak_, static_cast<double>(warned_)}; }
  void Restore(const std::vector<double>& state) {
    peak_ = state.at(0);
    warned_ = static_cast<int>(state.at(1));
  }

 private:
  double shear_speed_, peak_ = 0.0;
  int warned_ = 0;  ///< limits already warned about
};

/// Prints "vibrotherm: warning: <text>" and keeps it for summary.json. Collective.
PetscErrorCode WarnValidity(MPI_Comm comm, const std::string& text, io::RunSummary* summary);

}  // namespace vibrotherm::coupling
