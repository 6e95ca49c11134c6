// A progress line on stderr (rank 0, also in vibrotherm.log) about every two seconds:
//   wave: t = 1.23e-04 s, step 12345/116000 (10.6 %), 5.6e+03 steps/s, ETA 12 s
//   heat: t = 2.1e-02 s (61 % in log time), step 700, ETA 1 s
// The wave phase is estimated to end where it is expected to (the source
// duration plus the time the waves take to become quiet), not at -final_time,
// in steps taken plus those left at the current step (the contact may shrink it);
// past that end the line says the waves are not quiet yet. The free heat phase
// takes steps evenly in log time, so it is measured there.
#pragma once

#include <petscsys.h>

#include <string>

namespace vibrotherm::io {

/// The wave phase's count: "step 21761/23120", the steps taken and those left to
/// t_end at the current step dt, or "step 21761, past the expected end (t = ...)"
/// once t_end is passed.
std::string StepCount(long long steps, double t, double t_end, double dt);

class Progress {
 public:
  /// A phase from t_begin expected to end at t_end; log_time: measure progress in log t.
  void Start(MPI_Comm comm, std::string label, double t_begin, double t_end, double dt, bool log_time);
  PetscErrorCode Update(double t, long long steps);
  /// The line Update prints at (t, steps) after `elapsed` seconds of the phase: a count of
  /// steps for a phase started with a step (the waves), the fraction of the time (in log time
  /// if asked) otherwise (the free heat phase: no "past the expected end" there).
  std::string Line(double t, long long steps, double elapsed) const;
  PetscErrorCode Done(double t, long long steps);

 private:
  double Fraction(double t) const;
  std::string label_;
  double t_begin_ = 0, t_end_ = 1, dt_ = 0, wall_start_ = 0, wall_last_ = 0;
  bool log_time_ = false, counts_steps_ = false;
  long long steps_start_ = -1, steps_last_ = -1;
  double t_last_ = 0;
  bool speaker_ = false;
};

}  // namespace vibrotherm::io
