#include "vibrotherm/modes/modes_run.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::modes {
namespace {

/// The distance to the specimen's cracks (empty without one) and the longest crack's
/// length: the 2D cracks as gathered lines, a 3D box's as the rectangles of its options (a
/// 3D mesh file: none).
PetscErrorCode CrackDistanceOf(const mesh::Specimen& specimen, const mesh::SpecimenOptions& options,
                               CrackDistance* distance, double* longest) {
  PetscFunctionBeginUser;
  *longest = 0.0;
  PetscInt dim;
  PetscCall(DMGetDimension(specimen.wave, &dim));
  if (dim == 2) {
    const mesh::CrackSurface& cracks = specimen.wave_cracks;
    for (PetscInt i = 0; i < cracks.crack_count(); ++i) *longest = std::max(*longest, cracks.line(i).length());
    if (cracks.crack_count() > 0)
      *distance = [&cracks](const std::array<double, 3>& p) {
        double nearest = INFINITY;
        for (const mesh::CrackLine& crack : cracks.lines()) nearest = std::min(nearest, crack.Distance(p[0], p[1]));
        return nearest;
      };
    PetscFunctionReturn(0);
  }
  if (options.source.from_file) PetscFunctionReturn(0);  // a 3D mesh file's cracks are surfaces of its own: no distance yet
  const std::vector<mesh::Crack> rectangles = options.geometry.cracks;
  for (const mesh::Crack& c : rectangles) *longest = std::max(*longest, c.length);
  if (!rectangles.empty())
    *distance = [rectangles](const std::array<double, 3>& p) {
      double nearest = INFINITY;
      for (const mesh::Crack& crack : rectangles) nearest = std::min(nearest, crack.distance_to(p));
      return nearest;
    };
  PetscFunctionReturn(0);
}

/// The crack's contact linearised at its initial state (interface::CrackInterface::TangentStiffness,
/// as the harmonic start): nothing for a law without contact or a specimen without a crack.
ModalAnalysis::ExtraStiffness LinearisedContact(const mesh::Specimen& specimen, const coupling::Scene& scene) {
  return [&specimen, &scene](const fe::LagrangeSpace& space, Vec mass, std::vector<PetscInt>* rows,
                             std::vector<PetscInt>* cols, std::vector<double>* values) -> PetscErrorCode {
    PetscFunctionBeginUser;
    MPI_Comm comm = PetscObjectComm((PetscObject)space.dm());
    std::unique_ptr<contact::CrackLaw> law;
    VibrothermCallCpp(comm, law = contact::create_crack_law(scene.contact));
    if (specimen.cracks.empty() || !law->has_contact()) PetscFunctionReturn(0);
    interface::CrackInterface crack;
    PetscCall(crack.Setup(space, specimen.wave_cracks, mass, std::move(law), scene.a0));
    PetscCall(crack.TangentStiffness(rows, cols, values));
    PetscFunctionReturn(0);
  };
}

}  // namespace

PetscErrorCode ModesRun::Setup(const mesh::Specimen& specimen, const coupling::Scene& scene, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  const wave::ElasticMaterial& material = scene.material;
  const wave::Excitation& excitation = scene.excitation;
  const wave::WaveOptions& wave_options = scene.wave;
  CrackDistance crack_distance;
  double longest;
  PetscCall(CrackDistanceOf(specimen, scene.specimen, &crack_distance, &longest));
  PetscCall(modes::ReadModesOptions(comm, excitation.signal.frequency, longest / 2, &options_));
  options_.force = scene.specimen.source.force;
  PetscLogStage stage;
  PetscCall(PetscLogStageRegister("Modes", &stage));
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(stage));
  ModalAnalysis::ExtraStiffness contact;
  if (options_.contact) contact = LinearisedContact(specimen, scene);
  PetscCall(analysis_.Setup(specimen.wave, wave_options.degree, material, excitation, contact));
  PetscCall(PetscPrintf(comm, "Modes: %" PetscInt_FMT " free dofs (degree %" PetscInt_FMT "), %" PetscInt_FMT
                        " modes near %g Hz, defect radius %g m, the crack %s\n",
                        analysis_.dofs(), wave_options.degree, options_.n, options_.target_frequency,
                        options_.defect_radius, options_.contact ? "in contact (linearised at -crack_a0)" : "open"));
  PetscCall(analysis_.Solve(options_, crack_distance));
  PetscCall(PetscLogStagePop());
  summary->stages["modes"] = MPI_Wtime() - t0;
  summary->physics_ran = {"modes"};
  summary->dofs_wave = analysis_.dofs();
  for (const modes::Mode& m : analysis_.modes()) {
    summary->modes.emplace_back(m.frequency, m.participation);
    PetscCall(PetscPrintf(comm, "  %12.2f Hz   defect participation %.3f   residual %.1e\n", m.frequency,
                          m.participation, m.error));
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::modes
