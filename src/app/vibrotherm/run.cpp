#include "run.hpp"

#include <algorithm>
#include <filesystem>
#include <string>

#include "vibrotherm/coupling/driver.hpp"
#include "vibrotherm/interface/contact_options.hpp"
#include "vibrotherm/io/mesh_output.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/mesh_summary.hpp"
#include "vibrotherm/mesh/crack_line.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/modes/modal_analysis.hpp"

namespace vibrotherm::app {
namespace {

/// Creates the output directory on rank 0; a failure is an error on every rank.
PetscErrorCode MakeOutputDirectory(MPI_Comm comm, const std::string& dir) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int failed = 0;
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    failed = !std::filesystem::is_directory(dir);
  }
  PetscCallMPI(MPI_Bcast(&failed, 1, MPI_INT, 0, comm));
  PetscCheck(!failed, comm, PETSC_ERR_FILE_OPEN, "-output_dir %s: cannot create the directory", dir.c_str());
  PetscFunctionReturn(0);
}

/// -modes: natural frequencies and defect participation instead of a time run.
class ModesRun {
 public:
  PetscErrorCode Setup(const mesh::Specimen& specimen, io::RunSummary* summary) {
    PetscFunctionBeginUser;
    MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
    wave::ElasticMaterial material;
    wave::Excitation excitation;
    wave::WaveOptions wave_options;
    PetscCall(wave::ReadElasticMaterial(comm, &material));
    PetscCall(wave::ReadExcitation(comm, &excitation));
    PetscCall(wave::ReadWaveOptions(comm, &wave_options));
    cracks_.resize(specimen.cracks.size());
    double longest = 0.0;
    for (std::size_t i = 0; i < cracks_.size(); ++i) {
      PetscCall(cracks_[i].Setup(specimen.wave, static_cast<PetscInt>(i)));
      longest = std::max(longest, cracks_[i].length());
    }
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
    PetscCall(analysis_.Solve(options_, cracks_));
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
  PetscErrorCode Write(const std::string& dir) const { return analysis_.Write(dir); }

 private:
  std::vector<mesh::CrackLine> cracks_;
  modes::ModesOptions options_;
  modes::ModalAnalysis analysis_;
};

}  // namespace

PetscErrorCode Run(MPI_Comm comm) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscBool mesh_only = PETSC_FALSE, modes = PETSC_FALSE;
  char output_dir[PETSC_MAX_PATH_LEN] = "results/run";
  PetscOptionsBegin(comm, nullptr, "vibrotherm", nullptr);
  PetscCall(PetscOptionsBool("-mesh_only", "Build the specimen mesh, write it and stop", nullptr, mesh_only,
                             &mesh_only, nullptr));
  PetscCall(PetscOptionsBool("-modes", "Natural modes of the cracked specimen (SLEPc) instead of a time run", nullptr,
                             modes, &modes, nullptr));
  PetscCall(PetscOptionsString("-output_dir", "Output directory (scripts/run: results/<options-file-stem>)", nullptr,
                               output_dir, output_dir, sizeof(output_dir), nullptr));
  PetscOptionsEnd();
  const std::string dir = output_dir;

  // All input is checked before anything is written.
  contact::ContactParameters contact_params;
  PetscCall(ReadContactOptions(comm, contact_params));
  io::RunSummary summary;
  mesh::Specimen specimen;
  double t = MPI_Wtime();
  PetscCall(mesh::SpecimenCreate(comm, &specimen));
  summary.stages["mesh"] = MPI_Wtime() - t;
  PetscCall(mesh::ComputeMeshSummary(specimen, &summary.mesh));
  PetscCall(mesh::PrintMeshSummary(comm, summary.mesh));
  coupling::Simulation simulation;
  ModesRun modes_run;
  if (modes && !mesh_only) PetscCall(modes_run.Setup(specimen, &summary));
  else if (!mesh_only) PetscCall(simulation.Setup(specimen, &summary));

  // Everything has been checked: outputs from here on.
  PetscCall(MakeOutputDirectory(comm, dir));
  PetscLogStage output_stage;
  PetscCall(PetscLogStageRegister("Output", &output_stage));
  t = MPI_Wtime();
  PetscCall(PetscLogStagePush(output_stage));
  PetscCall(io::WriteMesh(specimen.wave, dir + "/mesh.h5"));
  PetscCall(PetscLogStagePop());
  summary.stages["output"] = MPI_Wtime() - t;
  if (modes && !mesh_only) PetscCall(modes_run.Write(dir));
  else if (!mesh_only) PetscCall(simulation.Run(dir, &summary));
  summary.wall_time_s = MPI_Wtime() - t0;
  PetscCall(io::WriteRunSummary(comm, dir + "/summary.json", summary));
  PetscCall(PetscPrintf(comm, "outputs in %s\n", dir.c_str()));
  PetscCall(mesh::SpecimenDestroy(&specimen));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::app
