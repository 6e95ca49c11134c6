#include "vibrotherm/wave/block_csr3.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define VIBROTHERM_WIDE_KERNEL 1
#include <immintrin.h>
#endif

namespace vibrotherm::wave {
namespace {

/// The portable path: two blocks at a time in two sets of sums (independent chains).
template <bool kAdd>
void ApplyScalar(const BlockCsr3& part, const double* __restrict x, double* __restrict y) {
  const auto rows = static_cast<std::int32_t>(part.row_start.size()) - 1;
  const std::int32_t* __restrict start = part.row_start.data();
  const std::int32_t* __restrict index = part.x_index.data();
  const double* __restrict value = part.value.data();
  for (std::int32_t r = 0; r < rows; ++r) {
    double s[2][3] = {};
    for (std::int32_t k = start[r]; k < start[r + 1]; ++k) {
      const double* a = value + 9 * static_cast<std::ptrdiff_t>(k);
      const double* xc = x + index[k];
      double* t = s[k & 1];
      for (int i = 0; i < 3; ++i) t[i] += a[i] * xc[0] + a[3 + i] * xc[1] + a[6 + i] * xc[2];
    }
    double* yr = y + 3 * static_cast<std::ptrdiff_t>(part.rows.empty() ? r : part.rows[r]);
    for (int i = 0; i < 3; ++i) yr[i] = (kAdd ? yr[i] : 0.0) + (s[0][i] + s[1][i]);
  }
}

#ifdef VIBROTHERM_WIDE_KERNEL
/// The 4-wide path: lanes 0–2 hold a column of a block, lane 3 the next value (dropped).
template <bool kAdd>
__attribute__((target("avx2"))) void ApplyWide(const BlockCsr3& part, const double* __restrict x,
                                               double* __restrict y) {
  const auto rows = static_cast<std::int32_t>(part.row_start.size()) - 1;
  const std::int32_t* __restrict start = part.row_start.data();
  const std::int32_t* __restrict index = part.x_index.data();
  const double* __restrict value = part.value.data();
  for (std::int32_t r = 0; r < rows; ++r) {
    __m256d s0 = _mm256_setzero_pd(), s1 = _mm256_setzero_pd();
    std::int32_t k = start[r];
    const std::int32_t end = start[r + 1];
    for (; k + 1 < end; k += 2) {  // two blocks, two chains
      const double *a = value + 9 * static_cast<std::ptrdiff_t>(k), *b = a + 9;
      const double *xa = x + index[k], *xb = x + index[k + 1];
      s0 = _mm256_add_pd(s0, _mm256_mul_pd(_mm256_loadu_pd(a), _mm256_broadcast_sd(xa)));
      s1 = _mm256_add_pd(s1, _mm256_mul_pd(_mm256_loadu_pd(b), _mm256_broadcast_sd(xb)));
      s0 = _mm256_add_pd(s0, _mm256_mul_pd(_mm256_loadu_pd(a + 3), _mm256_broadcast_sd(xa + 1)));
      s1 = _mm256_add_pd(s1, _mm256_mul_pd(_mm256_loadu_pd(b + 3), _mm256_broadcast_sd(xb + 1)));
      s0 = _mm256_add_pd(s0, _mm256_mul_pd(_mm256_loadu_pd(a + 6), _mm256_broadcast_sd(xa + 2)));
      s1 = _mm256_add_pd(s1, _mm256_mul_pd(_mm256_loadu_pd(b + 6), _mm256_broadcast_sd(xb + 2)));
    }
    if (k < end) {
      const double* a = value + 9 * static_cast<std::ptrdiff_t>(k);
      const double* xa = x + index[k];
      for (int c = 0; c < 3; ++c) s0 = _mm256_add_pd(s0, _mm256_mul_pd(_mm256_loadu_pd(a + 3 * c), _mm256_broadcast_sd(xa + c)));
    }
    alignas(32) double sum[4];
    _mm256_store_pd(sum, _mm256_add_pd(s0, s1));
    double* yr = y + 3 * static_cast<std::ptrdiff_t>(part.rows.empty() ? r : part.rows[r]);
    for (int i = 0; i < 3; ++i) yr[i] = (kAdd ? yr[i] : 0.0) + sum[i];
  }
}
#endif

}  // namespace

void AppendBlockRow3(std::int32_t row, const std::int32_t* columns, const double* values, std::int32_t blocks,
                     bool compressed, BlockCsr3* part) {
  if (part->row_start.empty()) part->row_start.push_back(0);
  if (compressed) part->rows.push_back(row);
  for (std::int32_t b = 0; b < blocks; ++b) part->x_index.push_back(3 * columns[b]);
  part->value.insert(part->value.end(), values, values + 9 * static_cast<std::ptrdiff_t>(blocks));
  part->row_start.push_back(static_cast<std::int32_t>(part->x_index.size()));
}

void FinishBlockCsr3(BlockCsr3* part) {
  if (part->row_start.empty()) part->row_start.push_back(0);
  part->value.push_back(0.0);
}

void BlockCsr3Apply(const BlockCsr3& part, const double* x, double* y, bool add, bool wide) {
#ifdef VIBROTHERM_WIDE_KERNEL
  if (wide) return add ? ApplyWide<true>(part, x, y) : ApplyWide<false>(part, x, y);
#endif
  (void)wide;
  add ? ApplyScalar<true>(part, x, y) : ApplyScalar<false>(part, x, y);
}

}  // namespace vibrotherm::wave
