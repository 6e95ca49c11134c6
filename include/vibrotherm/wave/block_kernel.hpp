// y = A x for a BAIJ matrix of block size 2 (the wave's stepping operator
// A = −M⁻¹K), by a hand-written 2×2-block CSR loop (block_csr.hpp) instead of MatMult.
//
// Why: Debian's PETSc is built without AVX kernels; its MatMult_SeqBAIJ_2 is
// scalar, about 14 instructions a block, one dependent chain per component.
// On the paper's matrix the rate per block is the same at a tenth of its
// size: instructions bound it, not memory. block_csr.hpp needs fewer per
// block, and uses AVX2 where the machine has it (chosen at run time: the
// default build stays portable).
//
// Parallel layout as MPIBAIJ: the owned rows times the owned columns (diagonal
// part), plus the rows that touch ghost columns times those ghosts
// (off-process part, its columns compressed to the ghosts); the ghosts come by
// a VecScatter of our own, started before the diagonal part and finished
// after it, as MatMult does. Sums run diagonal part first, then ghosts, as in
// MatMult; within a row in two interleaved chains, so the result agrees with
// MatMult to rounding (not bit for bit).
//
// The arrays are copied from A when it is set, and copied again by Apply when
// A's object state has changed since (values rescaled or reassembled; a new
// nonzero pattern with other ghost columns needs Setup again, and is refused).
//
// Block size 3 (3D) runs the 3×3-block loop of block_csr3.hpp, the same way (no
// spread x: its 4-wide path broadcasts x). Other block sizes fall back to MatMult,
// with the same contract (compress_rows: only the rows with entries are written).
#pragma once

#include <petscmat.h>

#include <vector>

#include "vibrotherm/wave/block_csr.hpp"
#include "vibrotherm/wave/block_csr3.hpp"

namespace vibrotherm::wave {

class BlockKernel {
 public:
  BlockKernel() = default;
  BlockKernel(const BlockKernel&) = delete;
  BlockKernel& operator=(const BlockKernel&) = delete;
  ~BlockKernel();

  /// Takes A's pattern and values and builds the ghost scatter (collective).
  /// A: SEQBAIJ or MPIBAIJ, square, assembled; the blocked loop for block
  /// sizes 2 and 3, MatMult for the others. allow_wide:
  /// the AVX2 path where the machine has it (false: the portable path, for tests).
  /// compress_rows: only the block rows with entries are written by Apply (the
  /// others keep their values): a level of local time stepping.
  PetscErrorCode Setup(Mat A, bool allow_wide = true, bool compress_rows = false);
  /// Whether Apply runs the AVX2 path.
  bool wide() const { return wide_; }
  /// y = A x; x and y have A's layout and must not alias (collective). Const
  /// as a product is: the copy of A it may renew and its scratch are caches.
  PetscErrorCode Apply(Vec x, Vec y) const;

 private:
  PetscErrorCode CopyArrays() const;
  /// Block sizes other than 2: MatMult (and the rows it may write, if compressed).
  PetscErrorCode FallbackSetup();
  PetscErrorCode FallbackApply(Vec x, Vec y) const;
  /// y = A x with the 3×3 blocks.
  PetscErrorCode ApplyBlocks3(Vec x, Vec y) const;

  Mat A_ = nullptr;  ///< referenced
  mutable PetscObjectState state_ = -1;
  mutable BlockCsr diagonal_, off_process_;     ///< block size 2
  mutable BlockCsr3 diagonal3_, off_process3_;  ///< block size 3
  PetscInt bs_ = 2;
  VecScatter scatter_ = nullptr;  ///< x → ghosts (null on one rank)
  Vec ghosts_ = nullptr;
  mutable std::vector<Quad> spread_, spread_ghosts_;  ///< x and the ghosts, spread
  mutable std::vector<std::int32_t> used_columns_;    ///< compressed rows: the owned block columns they read
  PetscLogEvent event_ = -1;
  bool wide_ = false, compress_rows_ = false, fallback_ = false;
  Vec product_ = nullptr;                    ///< fallback with compressed rows: A x before the copy
  std::vector<PetscInt> rows_with_entries_;  ///< fallback with compressed rows: local rows to write
};

}  // namespace vibrotherm::wave
