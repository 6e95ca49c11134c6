#include "vibrotherm/modes/modes_run.hpp"

#include <algorithm>

namespace vibrotherm::modes {

PetscErrorCode ModesRun::Setup(const mesh::Specimen& specimen, const coupling::Scene& scene, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  const wave::ElasticMaterial& material = scene.material;
  const wave::Excitation& excitation = scene.excitation;
  const wave::WaveOptions& wave_options = scene.wave;
  double longest = 0.0;
  for (PetscInt i = 0; i < specimen.wave_cracks.crack_count(); ++i)
    longest = std::max(longest, specimen.wave_cracks.line(i).length());
  PetscCall(modes::ReadModesOptions(comm, excitation.signal.frequency, longest / 2, &options_));
  PetscLogStage stage;
  PetscCall(PetscLogStageRegister("Modes", &stage));
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(stage));
  PetscCall(analysis_.Setup(specimen.wave, wave_options.degree, material, excitation));
  PetscCall(PetscPrintf(comm, "Modes: %" PetscInt_FMT " free dofs (degree %" PetscInt_FMT "), %" PetscInt_FMT
                        " modes near %g Hz, defect radius %g m\n",
                        analysis_.dofs(), wave_options.degree, options_.n, options_.target_frequency,
                        options_.defect_radius));
  PetscCall(analysis_.Solve(options_, specimen.wave_cracks));
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
