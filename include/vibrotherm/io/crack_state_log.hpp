// crack_state.csv, rank 0, written atomically: every contact cell every
// -crack_state_every steps, for space-time maps along the cracks. One schema in
// both dimensions (crack 1-based; 9 significant digits):
//   t,crack,xi,s1,s2,x,y,z,a,b,b2,N,T,T2,state,power,W
// the cell's position as named columns: xi the fraction along a 2D crack line (nan
// on a 3D crack surface, which has none), s1 and s2 the distances [m] from the crack's
// centre (its cells' centroid) along its tangents t1 and t2 (2D: s2 = 0; 3D: t1 the
// strike, t2 = n x t1), x, y, z (2D: z = 0); b, T along t1 and b2, T2 along t2 (2D: 0).
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
  PetscErrorCode Open(MPI_Comm comm, const std::string& path, long long resume_bytes = -1);
  /// Checkpoints: bytes written (rank 0), and leaving the file for a restart.
  long long bytes() const { return file_ ? file_->bytes() : 0; }
  void Keep() { if (file_) file_->keep(); }
  /// Appends the rows of one time (rank 0's records; others pass theirs empty).
  void Record(double t, const std::vector<interface::CrackCellRecord>& records);
  PetscErrorCode Finish();

 private:
  std::unique_ptr<store::AtomicFile> file_;  ///< rank 0
  std::string block_;                 ///< the rows of one time, formatted (capacity kept)
};

}  // namespace vibrotherm::io
