// source_power.csv, rank 0, written atomically: where the source's power goes,
// one row per source period while the waves run (or one row over the whole
// stretch where a periodic continuation skipped periods: `periods` > 1):
//   t_start,t_end,periods,frequency,amplitude,input_power,friction_power,damping_power,radiated_power,efficiency
// [s, s, 1, Hz, m or Pa, then W/m in 2D (W in 3D)]; efficiency = friction / input,
// the thermosonic efficiency (empty when nothing went in).
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>

#include "vibrotherm/store/atomic_file.hpp"

namespace vibrotherm::io {

/// What the source put in over [t_start, t_end] and where it went, as mean powers.
struct SourcePowerRow {
  double t_start = 0.0, t_end = 0.0;
  double periods = 0.0;    ///< source periods in the interval
  double frequency = 0.0;  ///< periods / (t_end − t_start) [Hz]
  double amplitude = 0.0;  ///< the source's amplitude at the interval's middle
  double input = 0.0, friction = 0.0, damping = 0.0, radiated = 0.0;  ///< mean powers
  double efficiency() const { return input > 0.0 ? friction / input : 0.0; }
};

class SourcePowerLog {
 public:
  /// Rank 0 opens path. resume_bytes >= 0: continue the interrupted run's file. Collective.
  PetscErrorCode Open(MPI_Comm comm, const std::string& path, long long resume_bytes = -1);
  /// Appends a row (rank 0; the others hold no file).
  void Record(const SourcePowerRow& row);
  long long bytes() const { return file_ ? file_->bytes() : 0; }
  void Keep() {
    if (file_) file_->keep();
  }
  bool open() const { return opened_; }
  PetscErrorCode Finish();

 private:
  std::unique_ptr<store::AtomicFile> file_;  ///< rank 0
  bool opened_ = false;
};

}  // namespace vibrotherm::io
