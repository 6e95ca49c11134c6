#include "vibrotherm/wave/block_kernel.hpp"

#include <petsc/private/petscimpl.h>  // PetscObjectStateGet: has A changed since the copy?

#include <algorithm>

namespace vibrotherm::wave {
namespace {

/// Calls append(row, columns, values, blocks) for each block row of a SeqBAIJ part of
/// block size bs. compress: only the block rows with entries (the off-process part touches few rows).
template <class Append>
PetscErrorCode ReadBlockRows(Mat seq, PetscInt bs, bool compress, Append append) {
  PetscFunctionBeginUser;
  PetscInt rows;
  const PetscInt *ia, *ja;
  PetscBool done;
  PetscCall(MatGetRowIJ(seq, 0, PETSC_FALSE, PETSC_TRUE, &rows, &ia, &ja, &done));  // block rows
  PetscCheck(done, PetscObjectComm((PetscObject)seq), PETSC_ERR_SUP, "block kernel: no row structure of the matrix");
  PetscScalar* a;
  PetscCall(MatSeqBAIJGetArray(seq, &a));
  PetscInt columns;
  PetscCall(MatGetSize(seq, nullptr, &columns));
  PetscCheck(columns / bs < kMaxBlockColumns, PETSC_COMM_SELF, PETSC_ERR_SUP,
             "block kernel: %" PetscInt_FMT " block columns on one rank, more than its 32-bit offsets reach",
             columns / bs);
  static_assert(sizeof(PetscInt) == sizeof(std::int32_t), "block kernel: PETSc with 32-bit indices (petsc-dev)");
  for (PetscInt r = 0; r < rows; ++r) {
    const auto blocks = static_cast<std::int32_t>(ia[r + 1] - ia[r]);
    if (!compress || blocks > 0) append(static_cast<std::int32_t>(r), ja + ia[r], a + bs * bs * ia[r], blocks);
  }
  PetscCall(MatSeqBAIJRestoreArray(seq, &a));
  PetscCall(MatRestoreRowIJ(seq, 0, PETSC_FALSE, PETSC_TRUE, &rows, &ia, &ja, &done));
  PetscFunctionReturn(0);
}

/// One part's arrays from a SeqBAIJ matrix of block size 2 or 3 (into part2 or part3).
PetscErrorCode CopyPart(Mat seq, PetscInt bs, bool compress, BlockCsr* part2, BlockCsr3* part3) {
  PetscFunctionBeginUser;
  if (bs == 2) {
    *part2 = BlockCsr();
    PetscCall(ReadBlockRows(seq, 2, compress, [&](std::int32_t r, const PetscInt* columns, const double* a,
                                                  std::int32_t blocks) {
      AppendBlockRow(r, columns, a, blocks, compress, part2);
    }));
  } else {
    *part3 = BlockCsr3();
    PetscCall(ReadBlockRows(seq, 3, compress, [&](std::int32_t r, const PetscInt* columns, const double* a,
                                                  std::int32_t blocks) {
      AppendBlockRow3(r, columns, a, blocks, compress, part3);
    }));
    FinishBlockCsr3(part3);
  }
  PetscFunctionReturn(0);
}

}  // namespace

BlockKernel::~BlockKernel() {
  (void)VecDestroy(&product_);
  (void)VecScatterDestroy(&scatter_);
  (void)VecDestroy(&ghosts_);
}

PetscErrorCode BlockKernel::Setup(Mat A, bool allow_wide, bool compress_rows) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)A);
  PetscInt bs;
  PetscBool mpi, seq;
  PetscCall(MatGetBlockSize(A, &bs));
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATMPIBAIJ, &mpi));
  PetscCall(PetscObjectTypeCompare((PetscObject)A, MATSEQBAIJ, &seq));
  PetscCheck(mpi || seq, comm, PETSC_ERR_SUP, "block kernel: needs a BAIJ matrix");
  A_ = A;
  bs_ = bs;
  compress_rows_ = compress_rows;
  fallback_ = bs != 2 && bs != 3;
  if (fallback_) {
    PetscCall(FallbackSetup());
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventGetId("WaveBlockMult", &event_));
  if (event_ < 0) PetscCall(PetscLogEventRegister("WaveBlockMult", MAT_CLASSID, &event_));
  wide_ = allow_wide && WideKernelAvailable();
  PetscCall(VecScatterDestroy(&scatter_));
  PetscCall(VecDestroy(&ghosts_));
  PetscCall(CopyArrays());
  PetscInt local_columns;
  PetscCall(MatGetLocalSize(A, nullptr, &local_columns));
  if (bs == 2) spread_.resize(local_columns / 2);
  if (!mpi) PetscFunctionReturn(0);
  // The ghosts: every block column of the off-process part, in its compressed order.
  Mat diagonal, off_process;
  const PetscInt* ghost_blocks;
  PetscInt ghost_columns;
  PetscCall(MatMPIBAIJGetSeqBAIJ(A, &diagonal, &off_process, &ghost_blocks));
  PetscCall(MatGetSize(off_process, nullptr, &ghost_columns));
  IS from;
  Vec x;
  PetscCall(ISCreateBlock(PETSC_COMM_SELF, bs, ghost_columns / bs, ghost_blocks, PETSC_COPY_VALUES, &from));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, ghost_columns, &ghosts_));
  if (bs == 2) spread_ghosts_.resize(ghost_columns / 2);
  PetscCall(MatCreateVecs(A, &x, nullptr));
  PetscCall(VecScatterCreate(x, from, ghosts_, nullptr, &scatter_));
  PetscCall(VecDestroy(&x));
  PetscCall(ISDestroy(&from));
  PetscFunctionReturn(0);
}

PetscErrorCode BlockKernel::CopyArrays() const {
  PetscFunctionBeginUser;
  PetscBool mpi;
  PetscCall(PetscObjectTypeCompare((PetscObject)A_, MATMPIBAIJ, &mpi));
  if (mpi) {
    Mat diagonal, off_process;
    PetscInt ghost_columns;
    PetscCall(MatMPIBAIJGetSeqBAIJ(A_, &diagonal, &off_process, nullptr));
    PetscCall(MatGetSize(off_process, nullptr, &ghost_columns));
    PetscInt ghosts_now = 0;
    if (ghosts_) PetscCall(VecGetSize(ghosts_, &ghosts_now));
    PetscCheck(!scatter_ || ghost_columns == ghosts_now, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONGSTATE,
               "block kernel: the matrix has new ghost columns since Setup: call Setup again");
    PetscCall(CopyPart(diagonal, bs_, compress_rows_, &diagonal_, &diagonal3_));
    PetscCall(CopyPart(off_process, bs_, true, &off_process_, &off_process3_));
  } else {
    PetscCall(CopyPart(A_, bs_, compress_rows_, &diagonal_, &diagonal3_));
  }
  used_columns_.clear();
  if (compress_rows_ && bs_ == 2) {  // a level of local time stepping: spread only what its rows read
    for (std::int32_t offset : diagonal_.x_offset) used_columns_.push_back(offset / static_cast<std::int32_t>(sizeof(Quad)));
    std::sort(used_columns_.begin(), used_columns_.end());
    used_columns_.erase(std::unique(used_columns_.begin(), used_columns_.end()), used_columns_.end());
  }
  PetscCall(PetscObjectStateGet((PetscObject)A_, &state_));
  PetscFunctionReturn(0);
}

PetscErrorCode BlockKernel::FallbackSetup() {
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&product_));
  rows_with_entries_.clear();
  if (!compress_rows_) PetscFunctionReturn(0);
  PetscCall(MatCreateVecs(A_, nullptr, &product_));
  PetscInt start, end;
  PetscCall(MatGetOwnershipRange(A_, &start, &end));
  for (PetscInt r = start; r < end; ++r) {
    PetscInt entries;
    PetscCall(MatGetRow(A_, r, &entries, nullptr, nullptr));
    if (entries > 0) rows_with_entries_.push_back(r - start);
    PetscCall(MatRestoreRow(A_, r, &entries, nullptr, nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode BlockKernel::FallbackApply(Vec x, Vec y) const {
  PetscFunctionBeginUser;
  if (!compress_rows_) {
    PetscCall(MatMult(A_, x, y));
    PetscFunctionReturn(0);
  }
  // Only the rows with entries are written, as the blocked loop does.
  PetscCall(MatMult(A_, x, product_));
  const PetscScalar* p;
  PetscScalar* ya;
  PetscCall(VecGetArrayRead(product_, &p));
  PetscCall(VecGetArray(y, &ya));
  for (PetscInt i : rows_with_entries_) ya[i] = p[i];
  PetscCall(VecRestoreArray(y, &ya));
  PetscCall(VecRestoreArrayRead(product_, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode BlockKernel::Apply(Vec x, Vec y) const {
  PetscFunctionBeginUser;
  PetscCheck(A_, PetscObjectComm((PetscObject)x), PETSC_ERR_ORDER, "block kernel: Apply before Setup");
  PetscCheck(x != y, PetscObjectComm((PetscObject)x), PETSC_ERR_ARG_IDN, "block kernel: x and y must differ");
  if (fallback_) {
    PetscCall(FallbackApply(x, y));
    PetscFunctionReturn(0);
  }
  PetscObjectState state;
  PetscCall(PetscObjectStateGet((PetscObject)A_, &state));
  if (state != state_) PetscCall(CopyArrays());  // A was rescaled or reassembled since
  PetscCall(PetscLogEventBegin(event_, A_, x, y, 0));
  if (bs_ == 3) {
    PetscCall(ApplyBlocks3(x, y));
    PetscCall(PetscLogEventEnd(event_, A_, x, y, 0));
    PetscFunctionReturn(0);
  }
  // Ghosts travel while the diagonal part is summed.
  if (scatter_) PetscCall(VecScatterBegin(scatter_, x, ghosts_, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* xa;
  PetscScalar* ya;
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArrayWrite(y, &ya));
  if (compress_rows_) SpreadPairsAt(xa, used_columns_, spread_.data());
  else SpreadPairs(xa, static_cast<std::int32_t>(spread_.size()), spread_.data());
  BlockCsrApply(diagonal_, spread_.data(), ya, false, wide_);
  if (scatter_) {
    const PetscScalar* ghost;
    PetscCall(VecScatterEnd(scatter_, x, ghosts_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(ghosts_, &ghost));
    SpreadPairs(ghost, static_cast<std::int32_t>(spread_ghosts_.size()), spread_ghosts_.data());
    BlockCsrApply(off_process_, spread_ghosts_.data(), ya, true, wide_);
    PetscCall(VecRestoreArrayRead(ghosts_, &ghost));
  }
  PetscCall(VecRestoreArrayWrite(y, &ya));
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(PetscLogFlops(8.0 * (diagonal_.value.size() + off_process_.value.size())));
  PetscCall(PetscLogEventEnd(event_, A_, x, y, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode BlockKernel::ApplyBlocks3(Vec x, Vec y) const {
  PetscFunctionBeginUser;
  // Ghosts travel while the diagonal part is summed; a compressed part writes only its rows.
  if (scatter_) PetscCall(VecScatterBegin(scatter_, x, ghosts_, INSERT_VALUES, SCATTER_FORWARD));
  const PetscScalar* xa;
  PetscScalar* ya;
  PetscCall(VecGetArrayRead(x, &xa));
  PetscCall(VecGetArray(y, &ya));
  BlockCsr3Apply(diagonal3_, xa, ya, false, wide_);
  if (scatter_) {
    const PetscScalar* ghost;
    PetscCall(VecScatterEnd(scatter_, x, ghosts_, INSERT_VALUES, SCATTER_FORWARD));
    PetscCall(VecGetArrayRead(ghosts_, &ghost));
    BlockCsr3Apply(off_process3_, ghost, ya, true, wide_);
    PetscCall(VecRestoreArrayRead(ghosts_, &ghost));
  }
  PetscCall(VecRestoreArray(y, &ya));
  PetscCall(VecRestoreArrayRead(x, &xa));
  PetscCall(PetscLogFlops(18.0 * (diagonal3_.x_index.size() + off_process3_.x_index.size())));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
