// The arithmetic of the 2×2-block kernel (block_kernel.hpp): y = P x over the
// block rows of one part P in 2×2-block CSR form, no PETSc.
//
// x is first spread to (x0, x0, x1, x1) per node, so a block (a00, a10, a01,
// a11: PETSc's column-major block order) is one 4-wide multiply by its spread
// x and one 4-wide add, into one of four independent accumulators (their sums
// then do not wait on each other). Two code paths, one result: 2-wide
// (SSE2 on any x86-64, scalars elsewhere) and, on x86-64 with AVX2 found at
// run time, 4-wide. Both do the same additions lane by lane in the same order
// (no fused multiply-add), so they agree bit for bit.
#pragma once

#include <cstdint>
#include <climits>
#include <vector>

namespace vibrotherm::wave {

/// Four doubles, 32-byte aligned: one 2×2 block, or one spread x pair.
struct alignas(32) Quad {
  double v[4];
};

/// Block columns whose byte offsets fit in 32 bits.
constexpr std::int32_t kMaxBlockColumns = INT32_MAX / static_cast<std::int32_t>(sizeof(Quad));

/// 2×2-block CSR arrays of one part.
struct BlockCsr {
  std::vector<std::int32_t> row_start;  ///< per block row, its first block; size rows + 1
  std::vector<std::int32_t> rows;       ///< the block row of each row entry (compressed part); empty: row r is r
  std::vector<std::int32_t> x_offset;   ///< per block: byte offset of its column's spread x (32 × column)
  std::vector<Quad> value;              ///< per block
};

/// Appends block row `row` (its columns and values, 4 per block, PETSc's order)
/// to part; columns below kMaxBlockColumns.
void AppendBlockRow(std::int32_t row, const std::int32_t* columns, const double* values, std::int32_t blocks,
                    bool compressed, BlockCsr* part);
/// The spread form of x: per block column (x0, x0, x1, x1).
void SpreadPairs(const double* x, std::int32_t pairs, Quad* spread);
/// The spread form of x at the listed block columns only.
void SpreadPairsAt(const double* x, const std::vector<std::int32_t>& columns, Quad* spread);
/// y = P x (add = false) or y += P x (add = true) over the rows of P; x spread.
/// wide: the 4-wide path (only where WideKernelAvailable()).
void BlockCsrApply(const BlockCsr& part, const Quad* x, double* y, bool add, bool wide);
/// Whether this machine runs the 4-wide path (x86-64 with AVX2).
bool WideKernelAvailable();

}  // namespace vibrotherm::wave
