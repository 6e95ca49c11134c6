#include "output_directory.hpp"

#include <filesystem>
#include <stdexcept>
#include <vector>

#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::app {
namespace {

/// Everything a run (and scripts/plot after it) writes into its output directory.
const std::vector<std::string>& RunOutputFiles() {
  static const std::vector<std::string> files = {
      "summary.json", "mesh.h5", "mesh.xmf", "fields.h5", "fields_wave.xmf", "fields_heat.xmf", "fields_cracks.xmf",
      "fields.xmf" /* before fields_<grid>.xmf */, "probes.csv", "energy.csv", "checkpoint.h5",
      "crack_state.csv", "crack_heat.h5", "camera.h5", "camera.xmf", "modes.csv", "modes.h5", "modes.xmf",
      "vibrotherm.log", "traction_loop.png", "crack_temperature.png", "temperature_maps.png", "energy_budget.png",
      "crack_spacetime.png", "camera.png", "modes.png"};
  return files;
}

}  // namespace

bool SameDirectory(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (std::filesystem::equivalent(a, b, ec)) return true;
  const auto normal = [](const std::string& p) {
    std::error_code e;
    return std::filesystem::weakly_canonical(std::filesystem::absolute(p, e), e).lexically_normal();
  };
  return normal(a) == normal(b);
}

PetscErrorCode CheckOutputDirectory(MPI_Comm comm, const std::string& dir, bool restart, bool overwrite) {
  PetscFunctionBeginUser;
  PetscCall(io::OutputLock::CheckFree(comm, dir));
  PetscCall(RunOnRoot(comm, [&] {
    std::error_code ec;
    const bool checkpoint = std::filesystem::exists(dir + "/checkpoint.h5", ec);
    if (restart && !checkpoint)
      throw std::invalid_argument("-restart " + dir + ": no checkpoint.h5 there, nothing to continue (a complete run "
                                  "removes its checkpoint)");
    if (checkpoint && !restart && !overwrite)
      throw std::invalid_argument("-output_dir " + dir + " holds the checkpoint of an interrupted run (checkpoint.h5): "
                                  "continue it with -restart " + dir + " and that run's options, or give -overwrite "
                                  "to discard it");
  }));
  PetscFunctionReturn(0);
}

PetscErrorCode MakeOutputDirectory(MPI_Comm comm, const std::string& dir, bool restart, io::OutputLock* lock) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int failed = 0, removed = 0;
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    failed = !std::filesystem::is_directory(dir);
  }
  PetscCallMPI(MPI_Bcast(&failed, 1, MPI_INT, 0, comm));
  PetscCheck(!failed, comm, PETSC_ERR_FILE_OPEN, "-output_dir %s: cannot create the directory", dir.c_str());
  PetscCall(lock->Acquire(comm, dir));  // before anything of an earlier run is touched
  if (rank == 0) {
    // A restart keeps what its checkpoint continues: the checkpoint, the .partial
    // files, and the interrupted run's log as vibrotherm.before-restart.log.
    std::error_code ec;
    if (restart) std::filesystem::rename(dir + "/vibrotherm.log", dir + "/vibrotherm.before-restart.log", ec);
    for (const std::string& name : RunOutputFiles()) {
      if (restart && name == "checkpoint.h5") continue;
      const std::string file = dir + "/" + name;
      for (const std::string& path : {file, file + ".partial"}) {
        if (restart && path != file) continue;
        if (std::filesystem::remove(path, ec)) ++removed;
        failed = failed || static_cast<bool>(ec);
      }
    }
  }
  PetscCallMPI(MPI_Bcast(&failed, 1, MPI_INT, 0, comm));
  PetscCheck(!failed, comm, PETSC_ERR_FILE_OPEN, "-output_dir %s: cannot remove the outputs of an earlier run",
             dir.c_str());
  if (removed) PetscCall(PetscPrintf(comm, "removed %d outputs of an earlier run from %s\n", removed, dir.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode RemoveCheckpoint(MPI_Comm comm, const std::string& dir) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::error_code ec;
  if (rank == 0) std::filesystem::remove(dir + "/checkpoint.h5", ec);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::app
