// A progress line on stderr (rank 0) about every two seconds:
//   wave: t = 1.23e-04 s (12.3 %), 1234 steps, 5.6e+03 steps/s, ETA 12 s
#pragma once

#include <petscsys.h>

#include <string>

namespace vibrotherm::io {

class Progress {
 public:
  void Start(MPI_Comm comm, std::string label, double t_begin, double t_end);
  void Update(double t, long long steps);
  void Done(double t, long long steps);

 private:
  std::string label_;
  double t_begin_ = 0, t_end_ = 1, wall_start_ = 0, wall_last_ = 0;
  long long steps_start_ = -1;
  bool speaker_ = false;
};

}  // namespace vibrotherm::io
