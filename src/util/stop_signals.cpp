#include "vibrotherm/util/stop_signals.hpp"

#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace vibrotherm::stop_signals {
namespace {

constexpr std::size_t kText = 1024;

/// A text the main thread replaces while a handler may read it: written into the slot not
/// in use, then the slot flipped (an int store, atomic for a handler).
struct SharedText {
  char slots[2][kText] = {};
  volatile std::sig_atomic_t current = 0;
  void Set(const std::string& text) {
    const int next = 1 - current;
    std::snprintf(slots[next], kText, "%s", text.c_str());
    current = next;
  }
  const char* Get() const { return slots[current]; }
};

/// Everything a handler reads or writes (see the header: the process's signal state).
struct State {
  volatile std::sig_atomic_t stop = 0;        ///< the first stop signal
  volatile std::sig_atomic_t running = 0;     ///< 0: setting up (end at once), 1: stepping (remember)
  volatile std::sig_atomic_t continues = 0;   ///< SIGCONTs received
  volatile std::sig_atomic_t continues_taken = 0;  ///< ... of which the run has seen (TakeContinue)
  volatile std::sig_atomic_t insured = 0;     ///< the SIGCONT count a checkpoint was written for
  volatile std::sig_atomic_t timer_armed = 0;
  volatile std::sig_atomic_t said = 0;         ///< the run has said where it stopped (Stopping)
  std::atomic<long long> continue_ms{0};      ///< when the last SIGCONT came (monotonic clock)
  const char* volatile setup_what = "setting up";
  int rank = 0;
  bool under_mpiexec = false;
  double grace = 1.0;  ///< mpiexec's delay between SIGTERM and SIGKILL [s]
  SharedText lock, created_dir, resume;
};
static_assert(std::atomic<long long>::is_always_lock_free, "a handler reads it");

State g_state;  // the process's signal state: a handler can reach nothing else

long long NowMs() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<long long>(ts.tv_sec) * 1000 + ts.tv_nsec / 1000000;
}

/// write(2) of a C string (async-signal-safe).
void Say(const char* text) {
  std::size_t n = std::strlen(text);
  while (n > 0) {
    const ssize_t w = write(STDERR_FILENO, text, n);
    if (w <= 0 && errno != EINTR) return;
    if (w > 0) text += w, n -= static_cast<std::size_t>(w);
  }
}

void RemoveLock() {
  const char* lock = g_state.lock.Get();
  if (lock[0]) unlink(lock);
  const char* dir = g_state.created_dir.Get();
  if (dir[0]) rmdir(dir);  // only when empty
}

/// Ends the process from a handler: one line "vibrotherm: <signal><a><b><c>", the lock
/// removed, exit 128 + signal.
[[noreturn]] void EndAtOnce(int signal, const char* a, const char* b, const char* c = "") {
  if (g_state.rank == 0 && !g_state.said) {
    for (const char* part : {"vibrotherm: ", Name(signal), a, b, c, "\n"}) Say(part);
  }
  RemoveLock();
  _exit(128 + signal);
}

extern "C" void OnStop(int signal) {
  if (!g_state.running)
    EndAtOnce(signal, " during ", g_state.setup_what, ": stopped before the run began stepping (nothing to resume)");
  if (!g_state.stop) g_state.stop = signal;
  if (!g_state.under_mpiexec || signal == SIGUSR1) return;
  // mpiexec's SIGKILL follows: end now from the checkpoint its SIGCONT made, or after a while.
  const bool fresh = NowMs() - g_state.continue_ms.load() < static_cast<long long>((2.0 * g_state.grace + 1.0) * 1000.0);
  if (g_state.insured > 0 && g_state.insured == g_state.continues && fresh)
    EndAtOnce(signal, " from mpiexec: stopped at once (its SIGKILL follows); ", g_state.resume.Get());
  if (g_state.timer_armed) return;
  g_state.timer_armed = 1;
  const double wait = 0.8 * g_state.grace;  // a margin for a busy machine to run the handler
  itimerval timer = {};
  timer.it_value.tv_sec = static_cast<time_t>(wait);
  timer.it_value.tv_usec = static_cast<suseconds_t>((wait - static_cast<double>(timer.it_value.tv_sec)) * 1e6);
  if (timer.it_value.tv_sec == 0 && timer.it_value.tv_usec == 0) timer.it_value.tv_usec = 1;
  setitimer(ITIMER_REAL, &timer, nullptr);
}

extern "C" void OnAlarm(int) {
  if (g_state.running && g_state.stop)
    EndAtOnce(g_state.stop, " from mpiexec: the next coupling interval is too far for its SIGKILL; stopped at once: ",
              g_state.resume.Get());
}

extern "C" void OnContinue(int) {
  g_state.continue_ms.store(NowMs());
  g_state.continues = g_state.continues + 1;
}

}  // namespace

void Install(int rank) {
  g_state.rank = rank;
  g_state.under_mpiexec = std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr;
  if (const char* grace = std::getenv("OMPI_MCA_odls_base_sigkill_timeout")) g_state.grace = std::max(0.0, std::atof(grace));
  g_state.resume.Set("no checkpoint was written yet: the run cannot be resumed (SIGUSR1 to mpiexec stops it at its "
                     "next coupling interval, without a deadline)");
  struct sigaction action = {};
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes interrupted by a signal go on
  action.sa_handler = OnStop;
  for (int signal : {SIGTERM, SIGINT, SIGUSR1}) sigaction(signal, &action, nullptr);
  action.sa_handler = OnContinue;
  sigaction(SIGCONT, &action, nullptr);
  action.sa_handler = OnAlarm;
  sigaction(SIGALRM, &action, nullptr);
}

void EnterSetup(const char* what) {
  g_state.setup_what = what;
  g_state.running = 0;
}

void EnterRun() { g_state.running = 1; }

void Stopping() { g_state.said = 1; }

int Received() { return g_state.stop; }

bool TakeContinue() {
  const std::sig_atomic_t seen = g_state.continues;
  const bool news = g_state.under_mpiexec && seen != g_state.continues_taken;
  g_state.continues_taken = seen;
  return news;
}

void CheckpointWritten(double t, const std::string& dir, bool after_continue) {
  char text[kText];
  std::snprintf(text, sizeof(text), "-restart %s resumes from its checkpoint at t = %.6g s", dir.c_str(), t);
  g_state.resume.Set(text);
  if (after_continue) g_state.insured = g_state.continues_taken;
}

void SetLock(const std::string& path) { g_state.lock.Set(path); }

void SetCreatedDirectory(const std::string& path) { g_state.created_dir.Set(path); }

std::string LockPath() { return g_state.lock.Get(); }

void RemoveLockNow() { RemoveLock(); }

const char* Name(int signal) {
  switch (signal) {
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGUSR1: return "SIGUSR1";
    case SIGCONT: return "SIGCONT";
    default: return "a signal";
  }
}

bool UnderMpiexec() { return g_state.under_mpiexec; }

double MpiexecGrace() { return g_state.grace; }

}  // namespace vibrotherm::stop_signals
