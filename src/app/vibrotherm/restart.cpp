#include "restart.hpp"

#include <map>
#include <sstream>

namespace vibrotherm::app {
namespace {

/// Options that may change between a run and its restart.
bool MayChangeOnRestart(const std::string& name) {
  for (const char* prefix : {"-restart", "-output_dir", "-checkpoint_every_s", "-log_", "-help", "-force",
                             "-allow_unknown", "-options_left", "-debug", "-overwrite"})
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

/// "name=value" lines as a map.
std::map<std::string, std::string> Parse(const std::string& fingerprint) {
  std::map<std::string, std::string> options;
  std::istringstream in(fingerprint);
  for (std::string line; std::getline(in, line);) {
    const std::size_t eq = line.find('=');
    if (eq != std::string::npos) options[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return options;
}

/// Compares the checkpoint's fingerprint with `fingerprint` (rank 0 knows the options) and
/// refuses a difference on every rank.
PetscErrorCode Compare(MPI_Comm comm, const std::string& dir, const std::string& fingerprint,
                       const std::set<std::string>* names, const store::Checkpoint& checkpoint) {
  PetscFunctionBeginUser;
  std::string written;
  PetscCall(checkpoint.GetText("run/fingerprint", &written));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string difference = rank == 0 ? FirstDifference(written, fingerprint, names) : "";
  int length = static_cast<int>(difference.size());
  PetscCallMPI(MPI_Bcast(&length, 1, MPI_INT, 0, comm));
  difference.resize(static_cast<std::size_t>(length));
  PetscCallMPI(MPI_Bcast(difference.data(), length, MPI_CHAR, 0, comm));
  PetscCheck(difference.empty(), comm, PETSC_ERR_USER_INPUT,
             "-restart %s: the checkpoint was written with other options (%s): restart with the options of that run",
             dir.c_str(), difference.c_str());
  PetscFunctionReturn(0);
}

}  // namespace

std::string OptionFingerprint(const std::vector<io::OptionRecord>& options) {
  std::string text;
  for (const io::OptionRecord& o : options)
    if (o.source != "default" && !MayChangeOnRestart(o.name)) text += o.name + "=" + o.value + "\n";
  return text;
}

std::string FirstDifference(const std::string& checkpoint, const std::string& now, const std::set<std::string>* names) {
  const std::map<std::string, std::string> then_options = Parse(checkpoint), now_options = Parse(now);
  std::set<std::string> all;
  for (const auto& [name, value] : then_options) all.insert(name);
  for (const auto& [name, value] : now_options) all.insert(name);
  for (const std::string& name : all) {
    if (names && !names->count(name)) continue;
    const auto a = then_options.find(name), b = now_options.find(name);
    const std::string before = a == then_options.end() ? "not given" : a->second;
    const std::string after = b == now_options.end() ? "not given" : b->second;
    if (before != after) return name + ": " + before + " in the checkpoint, " + after + " now";
  }
  return "";
}

PetscErrorCode ReadRestart(MPI_Comm comm, const std::string& dir, const std::string& fingerprint,
                           const std::set<std::string>& names, store::Checkpoint* checkpoint) {
  PetscFunctionBeginUser;
  PetscCall(checkpoint->Read(dir + "/checkpoint.h5"));
  PetscCall(Compare(comm, dir, fingerprint, &names, *checkpoint));
  PetscFunctionReturn(0);
}

PetscErrorCode CheckRestartOptions(MPI_Comm comm, const std::string& dir, const std::string& fingerprint,
                                   const store::Checkpoint& checkpoint) {
  PetscFunctionBeginUser;
  PetscCall(Compare(comm, dir, fingerprint, nullptr, checkpoint));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::app
