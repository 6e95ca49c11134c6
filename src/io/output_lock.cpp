#include "vibrotherm/io/output_lock.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "vibrotherm/util/root_task.hpp"
#include "vibrotherm/util/stop_signals.hpp"

namespace vibrotherm::io {
namespace {

struct Holder {
  long pid = 0;
  std::string host;
};

std::string ThisHost() {
  char host[256] = "";
  gethostname(host, sizeof(host) - 1);
  return host;
}

std::string OurContent() { return std::to_string(static_cast<long>(getpid())) + " " + ThisHost() + "\n"; }

std::string LockPath(const std::string& dir) { return dir + "/" + OutputLock::kFileName; }

/// The lock's text ("" when there is none).
std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return in ? text.str() : "";
}

Holder Parse(const std::string& text) {
  Holder h;
  std::istringstream in(text);
  in >> h.pid >> h.host;
  return h;
}

/// Whether the holder may still be running: always when on another host (it
/// cannot be checked from here); on this one, while its pid runs a vibrotherm
/// (a reused pid runs something else) that is not a zombie.
bool Alive(const Holder& h) {
  if (h.host != ThisHost()) return true;
  if (h.pid <= 0) return false;
  if (kill(static_cast<pid_t>(h.pid), 0) != 0 && errno == ESRCH) return false;
  // A killed process not yet reaped by its parent (an MPI launcher) is a zombie: dead.
  std::ifstream stat("/proc/" + std::to_string(h.pid) + "/stat");
  std::string pid, name, state;
  if (stat >> pid >> name >> state && state == "Z") return false;
  std::ifstream comm("/proc/" + std::to_string(h.pid) + "/comm");
  if (comm >> name) return name.rfind("vibrotherm", 0) == 0;
  return true;
}

std::string Refusal(const std::string& dir, const Holder& h) {
  const std::string who = "pid " + std::to_string(h.pid) + " on host " + (h.host.empty() ? "?" : h.host);
  if (h.host != ThisHost())
    return "-output_dir " + dir + " is in use by another run (" + who + "); if that run has ended, remove " +
           LockPath(dir);
  return "-output_dir " + dir + " is in use by another run (" + who + "): wait for it to end, or choose another -output_dir";
}

/// Rank 0: throws the refusal when a live run holds the lock; *stale: a note
/// when a dead run's lock is there ("" otherwise).
void CheckHolder(const std::string& dir, std::string* stale) {
  stale->clear();
  const std::string text = ReadText(LockPath(dir));
  if (text.empty()) return;
  const Holder h = Parse(text);
  if (Alive(h)) throw std::invalid_argument(Refusal(dir, h));
  *stale = "vibrotherm: note: " + LockPath(dir) + " was left by pid " + std::to_string(h.pid) + " on " + h.host +
           ", which no longer runs (a crash?): taken over\n";
}

/// Rank 0: creates the lock, taking over a stale one; the note to print.
std::string Take(const std::string& dir, const std::string& content) {
  std::string note;
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int fd = open(LockPath(dir).c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd >= 0) {
      const bool written = write(fd, content.data(), content.size()) == static_cast<ssize_t>(content.size());
      close(fd);
      if (!written) throw std::invalid_argument("-output_dir " + dir + ": cannot write " + LockPath(dir));
      return note;
    }
    if (errno != EEXIST)
      throw std::invalid_argument("-output_dir " + dir + ": cannot create " + LockPath(dir) + ": " + std::strerror(errno));
    CheckHolder(dir, &note);
    std::remove(LockPath(dir).c_str());  // stale (or gone meanwhile): try again
  }
  throw std::invalid_argument("-output_dir " + dir + ": another run is taking " + LockPath(dir) + " at the same time");
}

}  // namespace

OutputLock::~OutputLock() { Release(); }

void OutputLock::Release() {
  if (held_) stop_signals::SetLock("");
  held_ = false;
  // Only our own: a lock some other run took over after ours was judged stale stays.
  if (!path_.empty() && ReadText(path_) == content_) std::remove(path_.c_str());
  path_.clear();
}

PetscErrorCode OutputLock::CheckFree(MPI_Comm comm, const std::string& dir) {
  PetscFunctionBeginUser;
  std::string stale;  // a stale lock is taken over later, when the directory is made
  PetscCall(RunOnRoot(comm, [&] { CheckHolder(dir, &stale); }));
  PetscFunctionReturn(0);
}

PetscErrorCode OutputLock::Acquire(MPI_Comm comm, const std::string& dir) {
  PetscFunctionBeginUser;
  std::string note;
  const std::string content = OurContent();
  PetscCall(RunOnRoot(comm, [&] { note = Take(dir, content); }));
  // A process ended at once by a signal or a runtime failure removes it too (every rank: any may end first).
  held_ = true;
  stop_signals::SetLock(LockPath(dir));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    path_ = LockPath(dir);
    content_ = content;
    if (!note.empty()) PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s", note.c_str()));
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
