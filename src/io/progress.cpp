#include "vibrotherm/io/progress.hpp"

#include <cstdio>

namespace vibrotherm::io {

void Progress::Start(MPI_Comm comm, std::string label, double t_begin, double t_end) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  speaker_ = rank == 0;
  label_ = std::move(label);
  t_begin_ = t_begin;
  t_end_ = t_end;
  wall_start_ = wall_last_ = MPI_Wtime();
  steps_start_ = -1;
}

void Progress::Update(double t, long long steps) {
  if (steps_start_ < 0) steps_start_ = steps;
  const double now = MPI_Wtime();
  if (!speaker_ || now - wall_last_ < 2.0) return;
  wall_last_ = now;
  const double done = (t - t_begin_) / (t_end_ - t_begin_), elapsed = now - wall_start_;
  const double rate = (steps - steps_start_) / elapsed, eta = done > 0 ? elapsed * (1.0 - done) / done : 0.0;
  std::fprintf(stderr, "%s: t = %.4g s (%.1f %%), %lld steps, %.3g steps/s, ETA %.0f s\n", label_.c_str(), t,
               100.0 * done, steps, rate, eta);
}

void Progress::Done(double t, long long steps) {
  if (!speaker_) return;
  const double elapsed = MPI_Wtime() - wall_start_;
  std::fprintf(stderr, "%s: done, t = %.4g s, %lld steps in %.2f s\n", label_.c_str(), t, steps, elapsed);
}

}  // namespace vibrotherm::io
