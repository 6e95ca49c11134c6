// A progress line on stderr (rank 0, also in vibrotherm.log) about every two seconds:
//   wave: t = 1.23e-04 s, step 12345/116000 (10.6 %), 5.6e+03 steps/s, ETA 12 s
//   heat: t = 2.1e-02 s (61 % in log time), step 700, ETA 1 s
// The wave phase is estimated to end where it is expected to (the source
// duration plus the time the waves take to become quiet), not at -final_time;
// the free heat phase takes steps evenly in log time, so it is measured there.
#pragma once

#include <petscsys.h>

#include <string>

namespace vibrotherm::io {

class Progress {
 public:
  /// A phase from t_begin expected to end at t_end; log_time: measure progress in log t.
  void Start(MPI_Comm comm, std::string label, double t_begin, double t_end, double dt, bool log_time);
  PetscErrorCode Update(double t, long long steps);
  PetscErrorCode Done(double t, long long steps);

 private:
  double Fraction(double t) const;
  std::string label_;
  double t_begin_ = 0, t_end_ = 1, dt_ = 0, wall_start_ = 0, wall_last_ = 0;
  bool log_time_ = false;
  long long steps_start_ = -1;
  bool speaker_ = false;
};

}  // namespace vibrotherm::io
