// The arithmetic of the 3×3-block kernel (block_kernel.hpp, 3D elasticity): y = P x
// over the block rows of one part P in 3×3-block CSR form, no PETSc.
//
// In 3D the assembled operator streams from memory (~1.5 kB a dof for Q2 hexes), and
// Debian's PETSc multiplies its blocks with scalar code (MatMult_SeqBAIJ_3: 9 loads,
// 9 multiplies, 9 adds, 3 x loads a block), which reaches ~40 % of the memory
// bandwidth (scripts/bench wave3d). Here a block is 9 doubles in PETSc's column-major
// order, and the 4-wide path (AVX2, chosen at run time) takes each column as one
// unaligned 4-wide load (its 3 values and the next one, whose lane is dropped) times
// the broadcast x value: 3 loads, 3 multiplies, 3 adds a block. The portable path
// sums the same products in scalars. Both agree with MatMult to rounding.
#pragma once

#include <cstdint>
#include <vector>

namespace vibrotherm::wave {

/// 3×3-block CSR arrays of one part.
struct BlockCsr3 {
  std::vector<std::int32_t> row_start;  ///< per block row, its first block; size rows + 1
  std::vector<std::int32_t> rows;       ///< the block row of each row entry (compressed part); empty: row r is r
  std::vector<std::int32_t> x_index;    ///< per block: index of its column's first x value (3 × column)
  std::vector<double> value;            ///< 9 per block (column-major), then one pad (the last 4-wide load)
};

/// Appends block row `row` (its columns and values, 9 per block, PETSc's order) to part.
void AppendBlockRow3(std::int32_t row, const std::int32_t* columns, const double* values, std::int32_t blocks,
                     bool compressed, BlockCsr3* part);
/// After the last row: the pad the 4-wide path reads past the last block.
void FinishBlockCsr3(BlockCsr3* part);
/// y = P x (add = false) or y += P x (add = true) over the rows of P.
/// wide: the 4-wide path (only where WideKernelAvailable(), block_csr.hpp).
void BlockCsr3Apply(const BlockCsr3& part, const double* x, double* y, bool add, bool wide);

}  // namespace vibrotherm::wave
