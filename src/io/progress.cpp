#include "vibrotherm/io/progress.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::io {

void Progress::Start(MPI_Comm comm, std::string label, double t_begin, double t_end, double dt, bool log_time) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  speaker_ = rank == 0;
  label_ = std::move(label);
  t_begin_ = t_begin;
  t_end_ = t_end;
  dt_ = dt;
  log_time_ = log_time && t_begin > 0.0;
  wall_start_ = wall_last_ = MPI_Wtime();
  steps_start_ = -1;
}

double Progress::Fraction(double t) const {
  if (t_end_ <= t_begin_) return 1.0;
  const double f = log_time_ ? std::log(t / t_begin_) / std::log(t_end_ / t_begin_) : (t - t_begin_) / (t_end_ - t_begin_);
  return std::clamp(f, 0.0, 1.0);
}

PetscErrorCode Progress::Update(double t, long long steps) {
  PetscFunctionBeginUser;
  if (steps_start_ < 0) steps_start_ = steps;
  const double now = MPI_Wtime();
  if (!speaker_ || now - wall_last_ < 2.0) PetscFunctionReturn(0);
  wall_last_ = now;
  const double done = Fraction(t), elapsed = now - wall_start_;
  const double rate = (steps - steps_start_) / elapsed, eta = done > 0 ? elapsed * (1.0 - done) / done : 0.0;
  if (dt_ > 0.0)
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR,
                           "%s: t = %.4g s, step %lld/%.0f (%.1f %%), %.3g steps/s, ETA %.0f s\n", label_.c_str(), t,
                           steps, std::ceil((t_end_ - t_begin_) / dt_), 100.0 * done, rate, eta));
  else
    PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "%s: t = %.4g s (%.1f %%%s), step %lld, ETA %.0f s\n",
                           label_.c_str(), t, 100.0 * done, log_time_ ? " in log time" : "", steps, eta));
  PetscFunctionReturn(0);
}

PetscErrorCode Progress::Done(double t, long long steps) {
  PetscFunctionBeginUser;
  if (!speaker_) PetscFunctionReturn(0);
  const double elapsed = MPI_Wtime() - wall_start_;
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "%s: done, t = %.4g s, %lld steps in %.2f s\n", label_.c_str(), t,
                         steps, elapsed));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
