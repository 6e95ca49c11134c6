#include "vibrotherm/coupling/run/model_validity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace vibrotherm::coupling {
namespace {

constexpr double kYieldStrain = 1e-3, kSmallStrain = 1e-2;
constexpr double kWellResolved = 8.0, kUnresolved = 2.0;  // nodes per shear wavelength

std::string Format(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char text[512];
  std::snprintf(text, sizeof(text), format, a, b, c, d);
  return text;
}

/// Strain amplitude of the source: ω A / c (displacement) or A / (ρ c²) (traction),
/// c the speed of the wave the source component launches.
double SourceStrain(const Scene& scene) {
  const wave::ElasticMaterial& m = scene.material;
  const bool shear = scene.excitation.component == wave::SourceComponent::Tangential;
  const double c = shear ? m.cs() : m.cp(), A = std::abs(scene.excitation.signal.amplitude);
  if (scene.excitation.type == wave::SourceType::Traction) return A / (m.density * c * c);
  return 2.0 * M_PI * scene.excitation.signal.frequency * A / c;
}

}  // namespace

PetscErrorCode WarnValidity(MPI_Comm comm, const std::string& text, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "vibrotherm: warning: %s\n", text.c_str()));
  summary->warnings.push_back(text);
  PetscFunctionReturn(0);
}

namespace {

/// Refuses a mesh that cannot carry the source's shear waves, warns about one that under-resolves them.
PetscErrorCode CheckResolution(MPI_Comm comm, const Scene& scene, double h_max, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  const double f = scene.excitation.signal.frequency, degree = static_cast<double>(scene.wave.degree);
  if (f <= 0.0 || h_max <= 0.0) PetscFunctionReturn(0);
  const double wavelength = scene.material.cs() / f, nodes = wavelength / (h_max / degree);
  PetscCheck(nodes >= kUnresolved, comm, PETSC_ERR_USER_INPUT, "%s",
             Format("-source_frequency %g Hz: the shear wavelength %.3g m is shorter than two node spacings of the "
                    "mesh (elements up to %.3g m, degree %g): the mesh cannot carry these waves; lower "
                    "-source_frequency or refine -mesh_h",
                    f, wavelength, h_max, degree).c_str());
  if (nodes < kWellResolved)
    PetscCall(WarnValidity(comm,
                           Format("-source_frequency %g Hz: %.2g nodes per shear wavelength in the coarsest elements "
                                  "(%.3g m): the waves there are under-resolved (aim for 8 or more: refine -mesh_h)",
                                  f, nodes, h_max),
                           summary));
  PetscFunctionReturn(0);
}

/// Refuses a source beyond small strain, warns about one beyond the metals' elastic range.
PetscErrorCode CheckStrain(MPI_Comm comm, const Scene& scene, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  const double strain = SourceStrain(scene), f = scene.excitation.signal.frequency;
  const double A = scene.excitation.signal.amplitude;
  PetscCheck(strain <= kSmallStrain, comm, PETSC_ERR_USER_INPUT, "%s",
             Format("-source_amplitude %g strains the specimen by about %.3g at %g Hz, beyond small-strain "
                    "elasticity (the model holds below ~0.01; metals yield near 0.001): lower -source_amplitude",
                    A, strain, f).c_str());
  if (strain > kYieldStrain)
    PetscCall(WarnValidity(comm,
                           Format("-source_amplitude %g strains the specimen by about %.3g at %g Hz: metals yield near "
                                  "0.001, beyond which this linear elastic model overstates the waves and the heat",
                                  A, strain, f),
                           summary));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ResponseStrain::Check(const wave::WaveSolver& waves, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  Vec u, v;
  PetscReal speed;
  PetscCall(waves.GetFields(&u, &v));
  PetscCall(VecNorm(v, NORM_INFINITY, &speed));
  PetscCall(waves.RestoreFields(&u, &v));
  const double strain = speed / shear_speed_;
  peak_ = std::max(peak_, strain);
  const double limits[2] = {kYieldStrain, kSmallStrain};
  while (warned_ < 2 && strain > limits[warned_]) {
    const char* meaning = warned_ == 0 ? "metals yield near 0.001, beyond which this linear elastic model overstates "
                                         "the waves and the heat"
                                       : "beyond small-strain elasticity (~0.01): the waves and heat here mean nothing; "
                                         "lower -source_amplitude";
    PetscCall(WarnValidity(PetscObjectComm((PetscObject)waves.space().dm()),
                           Format("the response strains the specimen by about %.3g at t = %.4g s (peak velocity %.3g "
                                  "m/s over the shear speed %.4g m/s)",
                                  strain, waves.time(), speed, shear_speed_)
                               + ": " + meaning,
                           summary));
    ++warned_;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CheckSourceBeforeMeshing(MPI_Comm comm, const Scene& scene, double finest_h, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  // First: at 1 GHz the mesh is the real problem. Even the finest elements asked for cannot carry
  // the waves: no mesh of these sizes can (the coarsest elements are checked once meshed).
  const double f = scene.excitation.signal.frequency, degree = static_cast<double>(scene.wave.degree);
  const double wavelength = scene.material.cs() / f;
  PetscCheck(!(finest_h > 0.0) || wavelength / (finest_h / degree) >= kUnresolved, comm, PETSC_ERR_USER_INPUT, "%s",
             Format("-source_frequency %g Hz: the shear wavelength %.3g m is shorter than two node spacings of the "
                    "finest elements asked for (%.3g m, degree %g): no mesh of these sizes can carry these waves; "
                    "lower -source_frequency or refine -mesh_h and -mesh_h_crack",
                    f, wavelength, finest_h, degree).c_str());
  PetscCall(CheckStrain(comm, scene, summary));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckSourceValidity(MPI_Comm comm, const Scene& scene, double h_max, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  PetscCall(CheckResolution(comm, scene, h_max, summary));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
