#include "output_directory.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "vibrotherm/util/root_task.hpp"
#include "vibrotherm/util/stop_signals.hpp"

namespace vibrotherm::app {
namespace {

/// Everything a run (and scripts/plot after it) writes into its output directory.
const std::vector<std::string>& RunOutputFiles() {
  static const std::vector<std::string> files = {
      "summary.json", "mesh.h5", "mesh.xmf", "fields.h5", "fields_wave.xmf", "fields_heat.xmf", "fields_cracks.xmf",
      "fields.xmf" /* before fields_<grid>.xmf */, "probes.csv", "energy.csv", "periodic.csv", "checkpoint.h5",
      "crack_state.csv", "crack_heat.h5", "camera.h5", "camera.xmf", "modes.csv", "modes.h5", "modes.xmf",
      "vibrotherm.log", "vibrotherm.before-restart.log", "traction_loop.png", "crack_temperature.png",
      "temperature_maps.png", "energy_budget.png", "crack_spacetime.png", "crack_maps.png", "periodic.png",
      "camera.png", "modes.png"};
  return files;
}

/// The outputs of an earlier run in dir (final names and .partial files).
std::vector<std::string> EarlierOutputs(const std::string& dir) {
  std::vector<std::string> found;
  std::error_code ec;
  for (const std::string& name : RunOutputFiles())
    for (const std::string& file : {name, name + ".partial"})
      if (std::filesystem::exists(dir + "/" + file, ec)) found.push_back(file);
  return found;
}

/// Whether dir/summary.json records a complete run.
bool CompleteRun(const std::string& dir) {
  std::ifstream in(dir + "/summary.json");
  std::stringstream text;
  text << in.rdbuf();
  return text.str().find("\"complete\": true") != std::string::npos;
}

/// Rank 0: throws the refusal for an earlier run's outputs in dir.
void RefuseEarlierOutputs(const std::string& dir) {
  const std::vector<std::string> found = EarlierOutputs(dir);
  if (found.empty()) return;
  const std::string what = CompleteRun(dir) ? "the results of a complete run (summary.json, " +
                                                  std::to_string(found.size()) + " files)"
                                            : "the outputs of an earlier run that did not finish (" +
                                                  std::to_string(found.size()) + " files, e.g. " + found.front() +
                                                  "; no checkpoint to continue it)";
  throw std::invalid_argument("-output_dir " + dir + " holds " + what + ": choose another -output_dir, or give "
                              "-overwrite to replace them");
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
  PetscCall(RunOnRoot(comm, [&] {
    std::error_code ec;
    if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
      throw std::invalid_argument("-output_dir " + dir + " is a file, not a directory");
  }));
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
    if (!restart && !overwrite) RefuseEarlierOutputs(dir);
  }));
  PetscFunctionReturn(0);
}

OutputDirectory::~OutputDirectory() {
  lock_.Release();
  PetscMPIInt rank = 0;
  if (comm_ != MPI_COMM_NULL) MPI_Comm_rank(comm_, &rank);
  std::error_code ec;
  if (rank == 0 && !written_)
    for (const std::string& file : setup_files_) std::filesystem::remove(file, ec);
  if (!created_) return;
  stop_signals::SetCreatedDirectory("");
  if (rank == 0 && !written_) std::filesystem::remove(dir_, ec);  // only when empty
}

PetscErrorCode OutputDirectory::Claim(MPI_Comm comm, const std::string& dir) {
  PetscFunctionBeginUser;
  comm_ = comm;
  dir_ = dir;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string error;
  int created = 0;
  if (rank == 0) {
    std::error_code ec;
    const bool existed = std::filesystem::exists(dir, ec);
    std::filesystem::create_directories(dir, ec);
    if (ec) error = "-output_dir " + dir + ": cannot create the directory: " + ec.message();
    else if (!std::filesystem::is_directory(dir, ec)) error = "-output_dir " + dir + " is a file, not a directory";
    created = !existed && error.empty();
  }
  PetscCall(RunOnRoot(comm, [&] {
    if (!error.empty()) throw std::invalid_argument(error);
  }));
  PetscCallMPI(MPI_Bcast(&created, 1, MPI_INT, 0, comm));
  created_ = created;
  if (created) stop_signals::SetCreatedDirectory(dir);  // a signal during the setup removes it again
  PetscCall(lock_.Acquire(comm, dir));  // a read-only directory is refused here, with the reason
  PetscFunctionReturn(0);
}

PetscErrorCode OutputDirectory::Prepare(MPI_Comm comm, bool restart) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  int failed = 0, removed = 0;
  if (rank == 0) {
    // A restart keeps what its checkpoint continues: the checkpoint, the .partial
    // files, and the interrupted run's log as vibrotherm.before-restart.log.
    std::error_code ec;
    if (restart) std::filesystem::rename(dir_ + "/vibrotherm.log", dir_ + "/vibrotherm.before-restart.log", ec);
    for (const std::string& name : RunOutputFiles()) {
      if (restart && (name == "checkpoint.h5" || name == "vibrotherm.before-restart.log")) continue;
      const std::string file = dir_ + "/" + name;
      for (const std::string& path : {file, file + ".partial"}) {
        if (restart && path != file) continue;
        if (std::filesystem::remove(path, ec)) ++removed;
        failed = failed || static_cast<bool>(ec);
      }
    }
  }
  PetscCallMPI(MPI_Bcast(&failed, 1, MPI_INT, 0, comm));
  PetscCheck(!failed, comm, PETSC_ERR_FILE_OPEN, "-output_dir %s: cannot remove the outputs of an earlier run",
             dir_.c_str());
  if (removed)
    PetscCall(PetscPrintf(comm, restart ? "-restart: removed %d final outputs of the interrupted run (its summary, plots) from %s\n"
                                        : "-overwrite: removed %d outputs of an earlier run from %s\n",
                          removed, dir_.c_str()));
  written_ = true;
  if (created_) stop_signals::SetCreatedDirectory("");
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
