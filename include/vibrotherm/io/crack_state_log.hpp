// crack_state.csv, rank 0, written atomically: every contact cell every
// -crack_state_every steps, for space-time maps along the cracks.
//   t,crack,xi,x,y,a,b,N,T,state,power,W     (crack 1-based; 9 significant digits)
// 3D: keyed by the position on the crack plane, s1 and s2 the distances [m] from
// the crack's centre along its tangents t1 (the strike) and t2 (= −z), and the
// second tangential components:
//   t,crack,s1,s2,x,y,z,a,b1,b2,N,T1,T2,state,power,W
#pragma once

#include <petscsys.h>

#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/interface/crack_record.hpp"
#include "vibrotherm/store/atomic_file.hpp"

namespace vibrotherm::io {

class CrackStateLog {
 public:
  /// Rank 0 opens path. Collective.
  /// resume_bytes >= 0: continue the interrupted run's file (checkpoint restart).
  PetscErrorCode Open(MPI_Comm comm, const std::string& path, long long resume_bytes = -1, int dimension = 2);
  /// Checkpoints: bytes written (rank 0), and leaving the file for a restart.
  long long bytes() const { return file_ ? file_->bytes() : 0; }
  void Keep() { if (file_) file_->keep(); }
  /// Appends the rows of one time (rank 0's records; others pass theirs empty).
  void Record(double t, const std::vector<interface::CrackCellRecord>& records);
  PetscErrorCode Finish();

 private:
  std::unique_ptr<store::AtomicFile> file_;  ///< rank 0
  std::string block_;                 ///< the rows of one time, formatted (capacity kept)
  int dimension_ = 2;
};

}  // namespace vibrotherm::io
