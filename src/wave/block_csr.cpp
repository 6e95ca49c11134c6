#include "vibrotherm/wave/block_csr.hpp"

#include <cstring>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define VIBROTHERM_WIDE_KERNEL 1
#include <immintrin.h>
#endif

namespace vibrotherm::wave {
namespace {

// Two doubles as one value (GCC/Clang vector extension): an SSE2 register on
// x86-64, two scalars where the target has no vectors.
typedef double Pair __attribute__((vector_size(16)));

/// The spread x of a block: x_offset is in bytes, so no multiply per block.
inline const double* At(const Quad* x, std::int32_t offset) {
  return reinterpret_cast<const Quad*>(reinterpret_cast<const char*>(x) + offset)->v;
}

inline Pair Half(const double* p) {
  return *static_cast<const Pair*>(__builtin_assume_aligned(p, 16));  // vector types alias their elements
}

/// y_r = sum, or y_r += sum (kAdd): sum = the row's (Σ a00 x0 + Σ a01 x1, Σ a10 x0 + Σ a11 x1).
template <bool kAdd>
inline void Store(double* yr, Pair sum) {
  if (kAdd) {
    Pair y;
    std::memcpy(&y, yr, sizeof y);
    sum = y + sum;
  }
  std::memcpy(yr, &sum, sizeof sum);
}

/// The 2-wide path: each 4-wide chain as a lo and a hi pair.
template <bool kAdd>
void ApplyPairs(const BlockCsr& part, const Quad* __restrict x, double* __restrict y) {
  const auto rows = static_cast<std::int32_t>(part.row_start.size()) - 1;
  const std::int32_t* __restrict start = part.row_start.data();
  const std::int32_t* __restrict offset = part.x_offset.data();
  const Quad* __restrict value = part.value.data();
  for (std::int32_t r = 0; r < rows; ++r) {
    Pair lo[4] = {}, hi[4] = {};
    std::int32_t k = start[r];
    const std::int32_t end = start[r + 1];
    for (; k + 3 < end; k += 4)
      for (int c = 0; c < 4; ++c) {
        const double* xc = At(x, offset[k + c]);
        lo[c] += Half(value[k + c].v) * Half(xc);
        hi[c] += Half(value[k + c].v + 2) * Half(xc + 2);
      }
    for (; k < end; ++k) {
      lo[0] += Half(value[k].v) * Half(At(x, offset[k]));
      hi[0] += Half(value[k].v + 2) * Half(At(x, offset[k]) + 2);
    }
    const Pair sum = ((lo[0] + lo[1]) + (lo[2] + lo[3])) + ((hi[0] + hi[1]) + (hi[2] + hi[3]));
    Store<kAdd>(y + 2 * (part.rows.empty() ? r : part.rows[r]), sum);
  }
}

#ifdef VIBROTHERM_WIDE_KERNEL
/// The 4-wide path: the same additions as ApplyPairs, lo and hi in one register.
template <bool kAdd>
__attribute__((target("avx2"))) void ApplyWide(const BlockCsr& part, const Quad* __restrict x, double* __restrict y) {
  typedef double Wide __attribute__((vector_size(32)));
  const auto rows = static_cast<std::int32_t>(part.row_start.size()) - 1;
  const std::int32_t* __restrict start = part.row_start.data();
  const std::int32_t* __restrict offset = part.x_offset.data();
  const Quad* __restrict value = part.value.data();
  // (No helper function: a lambda would not inherit the AVX2 target.)
  for (std::int32_t r = 0; r < rows; ++r) {
    Wide s[4] = {};
    std::int32_t k = start[r];
    const std::int32_t end = start[r + 1];
    for (; k + 3 < end; k += 4)
      for (int c = 0; c < 4; ++c)
        s[c] += *reinterpret_cast<const Wide*>(value[k + c].v) * *reinterpret_cast<const Wide*>(At(x, offset[k + c]));
    for (; k < end; ++k)
      s[0] += *reinterpret_cast<const Wide*>(value[k].v) * *reinterpret_cast<const Wide*>(At(x, offset[k]));
    const __m256d t = (s[0] + s[1]) + (s[2] + s[3]);
    __m128d sum = _mm_add_pd(_mm256_castpd256_pd128(t), _mm256_extractf128_pd(t, 1));  // lo + hi
    double* yr = y + 2 * (part.rows.empty() ? r : part.rows[r]);
    if (kAdd) sum = _mm_add_pd(_mm_loadu_pd(yr), sum);
    _mm_storeu_pd(yr, sum);
  }
}
#endif

}  // namespace

void AppendBlockRow(std::int32_t row, const std::int32_t* columns, const double* values, std::int32_t blocks,
                    bool compressed, BlockCsr* part) {
  if (part->row_start.empty()) part->row_start.push_back(0);
  if (compressed) part->rows.push_back(row);
  for (std::int32_t b = 0; b < blocks; ++b) {
    part->x_offset.push_back(columns[b] * static_cast<std::int32_t>(sizeof(Quad)));
    part->value.push_back(Quad{{values[4 * b], values[4 * b + 1], values[4 * b + 2], values[4 * b + 3]}});
  }
  part->row_start.push_back(static_cast<std::int32_t>(part->value.size()));
}

void SpreadPairs(const double* x, std::int32_t pairs, Quad* spread) {
  for (std::int32_t c = 0; c < pairs; ++c) spread[c] = Quad{{x[2 * c], x[2 * c], x[2 * c + 1], x[2 * c + 1]}};
}

void SpreadPairsAt(const double* x, const std::vector<std::int32_t>& columns, Quad* spread) {
  for (std::int32_t c : columns) spread[c] = Quad{{x[2 * c], x[2 * c], x[2 * c + 1], x[2 * c + 1]}};
}

void BlockCsrApply(const BlockCsr& part, const Quad* x, double* y, bool add, bool wide) {
#ifdef VIBROTHERM_WIDE_KERNEL
  if (wide) return add ? ApplyWide<true>(part, x, y) : ApplyWide<false>(part, x, y);
#endif
  (void)wide;
  add ? ApplyPairs<true>(part, x, y) : ApplyPairs<false>(part, x, y);
}

bool WideKernelAvailable() {
#ifdef VIBROTHERM_WIDE_KERNEL
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

}  // namespace vibrotherm::wave
