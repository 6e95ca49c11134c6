#include "restart.hpp"

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

/// The first line of a that b lacks (or the reverse), or "".
std::string FirstDifference(const std::string& a, const std::string& b) {
  std::istringstream in_a(a), in_b(b);
  std::string line_a, line_b;
  while (true) {
    const bool more_a = static_cast<bool>(std::getline(in_a, line_a));
    const bool more_b = static_cast<bool>(std::getline(in_b, line_b));
    if (!more_a && !more_b) return "";
    if (line_a != line_b) return "checkpoint '" + (more_a ? line_a : "(none)") + "', now '" + (more_b ? line_b : "(none)") + "'";
  }
}

}  // namespace

std::string OptionFingerprint(const io::RunSummary& summary) {
  std::string text;
  for (const io::OptionRecord& o : summary.option_values)
    if (o.source != "default" && !MayChangeOnRestart(o.name)) text += o.name + "=" + o.value + "\n";
  return text;
}

PetscErrorCode ReadRestart(MPI_Comm comm, const std::string& dir, const std::string& fingerprint,
                           store::Checkpoint* checkpoint) {
  PetscFunctionBeginUser;
  PetscCall(checkpoint->Read(dir + "/checkpoint.h5"));
  std::string written;
  PetscCall(checkpoint->GetText("run/fingerprint", &written));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string difference = rank == 0 ? FirstDifference(written, fingerprint) : "";  // rank 0 knows the options
  int length = static_cast<int>(difference.size());
  PetscCallMPI(MPI_Bcast(&length, 1, MPI_INT, 0, comm));
  difference.resize(static_cast<std::size_t>(length));
  PetscCallMPI(MPI_Bcast(difference.data(), length, MPI_CHAR, 0, comm));
  PetscCheck(difference.empty(), comm, PETSC_ERR_USER_INPUT,
             "-restart %s: the checkpoint was written with other options (%s): restart with the options of that run",
             dir.c_str(), difference.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::app
