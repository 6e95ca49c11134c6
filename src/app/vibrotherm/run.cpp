#include "run.hpp"

#include <filesystem>
#include <string>

#include "vibrotherm/coupling/driver.hpp"
#include "vibrotherm/interface/contact_options.hpp"
#include "vibrotherm/io/mesh_output.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/mesh_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"

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

}  // namespace

PetscErrorCode Run(MPI_Comm comm) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscBool mesh_only = PETSC_FALSE;
  char output_dir[PETSC_MAX_PATH_LEN] = "results/run";
  PetscOptionsBegin(comm, nullptr, "vibrotherm", nullptr);
  PetscCall(PetscOptionsBool("-mesh_only", "Build the specimen mesh, write it and stop", nullptr, mesh_only,
                             &mesh_only, nullptr));
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
  if (!mesh_only) PetscCall(simulation.Setup(specimen, &summary));

  // Everything has been checked: outputs from here on.
  PetscCall(MakeOutputDirectory(comm, dir));
  PetscLogStage output_stage;
  PetscCall(PetscLogStageRegister("Output", &output_stage));
  t = MPI_Wtime();
  PetscCall(PetscLogStagePush(output_stage));
  PetscCall(io::WriteMesh(specimen.wave, dir + "/mesh.h5"));
  PetscCall(PetscLogStagePop());
  summary.stages["output"] = MPI_Wtime() - t;
  if (!mesh_only) PetscCall(simulation.Run(dir, &summary));
  summary.wall_time_s = MPI_Wtime() - t0;
  PetscCall(io::WriteRunSummary(comm, dir + "/summary.json", summary));
  PetscCall(PetscPrintf(comm, "outputs in %s\n", dir.c_str()));
  PetscCall(mesh::SpecimenDestroy(&specimen));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::app
