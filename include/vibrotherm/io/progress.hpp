// A progress line on stderr (rank 0, also in vibrotherm.log) about every two seconds:
//   wave: t = 1.23e-04 s, step 12345/116000 (10.6 %), 5.6e+03 steps/s, ETA 12 s
//   heat: t = 2.1e-02 s (61 % in log time), step 700, ETA 1 s
// The wave phase is estimated to end where it is expected to (the source
// duration plus the time the waves take to become quiet), not at -final_time,
// in steps taken plus those left at the current step (the contact may shrink it);
// past that end the line says the waves are not quiet yet. The count and its
// percentage are the same figure (steps taken of steps taken + left); the ETA is
// the steps left at the rate of about the last 10 s (since the phase, or the
// restart, began, for the first line).
// While a periodic continuation will skip most of the steps, the periodic outlook
// (coupling/continuation/periodic_outlook.hpp) gives the steps it expects to resolve and a
// note (the change per period against the tolerance):
//   wave: t = 3e-04 s, step 9000/13100 (68.7 %), 3.3e+03 steps/s, ETA ~1 s (resolved to the end: 260 s);
//         periodic: change 2.1e-03 per period (tolerance 3e-04), ~40 periods to go
// and, before it can tell (or when the change does not shrink), the resolved ETA as the bound
// it is: "ETA up to 260 s (resolved to the end); not periodic yet: change ..., not shrinking".
// The free heat phase takes steps evenly in log time, so it is measured there.
#pragma once

#include <petscsys.h>

#include <string>

namespace vibrotherm::io {

/// The wave phase's count: "step 21761/23120", the steps taken and those left to
/// t_end at the current step dt, or "step 21761, past the expected end (t = ...)"
/// once t_end is passed.
std::string StepCount(long long steps, double t, double t_end, double dt);
/// "step 810/852 (95.1 %)": steps taken of taken + left, and that share.
std::string StepShare(long long steps, double left);

class Progress {
 public:
  /// A phase from t_begin expected to end at t_end; log_time: measure progress in log t.
  void Start(MPI_Comm comm, std::string label, double t_begin, double t_end, double dt, bool log_time);
  /// The wave phase's steps still to resolve, expected from step `at` on (a periodic
  /// continuation skips the rest), and a note for the line; steps < 0: none (resolved to t_end).
  void SetOutlook(double steps, long long at, std::string note);
  PetscErrorCode Update(double t, long long steps);
  /// The line Update prints at (t, steps) after `elapsed` seconds of the phase: a count of
  /// steps for a phase started with a step (the waves), the fraction of the time (in log time
  /// if asked) otherwise (the free heat phase: no wave count, no "past the expected end").
  std::string Line(double t, long long steps, double elapsed) const;
  PetscErrorCode Done(double t, long long steps);

 private:
  double Fraction(double t) const;
  std::string WaveLine(double t, long long steps) const;
  std::string label_;
  double t_begin_ = 0, t_end_ = 1, dt_ = 0, wall_start_ = 0, wall_last_ = 0;
  bool log_time_ = false, counts_steps_ = false;  ///< counts_steps_: started with a step (the waves)
  long long steps_start_ = -1, steps_last_ = -1, steps_printed_ = -1;  ///< at Start, the last step, the last line
  double rate_ = 0.0;  ///< steps per wall second, over about the last 10 s
  double t_last_ = 0;
  bool speaker_ = false;
  double outlook_steps_ = -1.0;  ///< SetOutlook's steps (< 0: none)
  long long outlook_at_ = 0;
  std::string outlook_note_;
};

}  // namespace vibrotherm::io
