// How signals stop a run. SIGTERM and SIGINT (Ctrl-C, timeout, a scheduler) and
// SIGUSR1 (a scheduler's warning) are caught from the start of the program:
//   - while it sets up (options, meshing, -modes, the harmonic start) there is nothing to
//     save: the process ends at once, one line saying so, its output lock removed, exit
//     128 + the signal;
//   - while the run steps (EnterRun) the signal is remembered; the run polls Received()
//     between coupling intervals, writes a checkpoint and stops (coupling/run/checkpoint_schedule).
// Open MPI's mpiexec (4.1, orte odls), when it is itself sent SIGTERM or SIGINT, does not
// forward them: it sends each rank SIGCONT, then T seconds later SIGTERM, then T seconds
// later SIGKILL (T = the MCA parameter odls_base_sigkill_timeout, default 1 s), and exits 1.
// Under it (OMPI_COMM_WORLD_SIZE set) the ranks therefore
//   - take a SIGCONT as the warning it is: a checkpoint at the next coupling interval
//     (TakeContinue), whatever comes next (a job resumed after Ctrl-Z gets one too);
//   - on SIGTERM, when that checkpoint is written, end at once from it (the work since is
//     T seconds at most); otherwise try to stop at the next interval, and end at once from
//     the latest checkpoint when 0.8 T have passed (a timer): never killed by SIGKILL with
//     the lock left, always with a line saying where a restart resumes.
// SIGUSR1 is forwarded by mpiexec and has no deadline: the way to stop a long interval.
//
// Signal handlers can reach only process-wide state: this file holds all of it (the
// signals seen, the phase, the texts and paths a handler uses), written by the main
// thread and read by handlers with async-signal-safe calls only.
#pragma once

#include <string>

namespace vibrotherm::stop_signals {

/// Catches SIGTERM, SIGINT, SIGUSR1, SIGCONT and SIGALRM from now on (after PETSc's
/// initialisation, which installs handlers of its own). Only rank 0 prints. Starts in the
/// setup phase ("setting up").
void Install(int rank);
/// The setup phase: a stop signal ends the process at once, saying it came during `what`
/// (a string that lives for the whole program, e.g. "meshing").
void EnterSetup(const char* what);
/// The stepping phase: stop signals are remembered for Received().
void EnterRun();
/// The run has written its last checkpoint and said where it resumes: ended at once after
/// this (mpiexec's deadline), it ends without another line.
void Stopping();
/// The first stop signal received (SIGTERM, SIGINT, SIGUSR1), 0 when none.
int Received();
/// Whether a SIGCONT arrived under Open MPI's mpiexec since the last call (the warning
/// mpiexec sends before SIGTERM).
bool TakeContinue();
/// A checkpoint at simulated time t is on disk in dir: a stop at once from now on resumes
/// there; `after_continue`: it was written because of a SIGCONT (TakeContinue).
void CheckpointWritten(double t, const std::string& dir, bool after_continue);
/// The run's lock file (rank 0; "" when released) and the output directory if this run
/// created it (removed when the process ends at once and it holds nothing else).
void SetLock(const std::string& path);
void SetCreatedDirectory(const std::string& path);
/// The lock this run holds ("" when none): the output directory's vibrotherm.lock.
std::string LockPath();
/// Removes the lock (and the created, empty directory): a runtime failure ends the job.
void RemoveLockNow();
/// "SIGTERM", "SIGINT", "SIGUSR1", "SIGCONT" (or "a signal").
const char* Name(int signal);
/// Whether the process runs under Open MPI's launcher, and its SIGTERM-to-SIGKILL delay [s].
bool UnderMpiexec();
double MpiexecGrace();

}  // namespace vibrotherm::stop_signals
