// The 2×2-block kernel (wave/block_csr) against this machine's limit for it: the
// same loop on block matrices from L1-sized to larger than L2, one core. Where the
// rate per block stays that of the L1-sized matrix, the kernel is bound by its
// instructions (two 32-byte loads and one 4-wide multiply-add a block), not by
// memory: a step can then only get cheaper by doing fewer blocks.
// Matrices: Q2-like rows (16 blocks, columns within ±120 block columns of the
// row, as the paper's ordered mesh), random values.
//   bench_block_csr [--benchmark_repetitions=3 ...]; counters: time_per_block, KiB (matrix + spread x)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <random>
#include <vector>

#include "vibrotherm/wave/block_csr.hpp"

namespace {

using vibrotherm::wave::AppendBlockRow;
using vibrotherm::wave::BlockCsr;
using vibrotherm::wave::Quad;

constexpr int kBlocksPerRow = 16;

BlockCsr BandedPart(int rows, std::mt19937* random) {
  BlockCsr part;
  std::uniform_int_distribution<int> offset(-120, 120);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<std::int32_t> columns(kBlocksPerRow);
  std::vector<double> values(4 * kBlocksPerRow);
  for (int r = 0; r < rows; ++r) {
    for (int& c : columns) c = std::clamp(r + offset(*random), 0, rows - 1);
    std::sort(columns.begin(), columns.end());
    for (double& v : values) v = value(*random);
    AppendBlockRow(r, columns.data(), values.data(), kBlocksPerRow, false, &part);
  }
  return part;
}

void BM_BlockCsrApply(benchmark::State& state) {
  const int rows = static_cast<int>(state.range(0));
  const bool wide = state.range(1) != 0;
  if (wide && !vibrotherm::wave::WideKernelAvailable()) {
    state.SkipWithError("no AVX2 on this machine");
    return;
  }
  std::mt19937 random(7);
  const BlockCsr part = BandedPart(rows, &random);
  std::vector<Quad> x(rows);
  for (Quad& q : x) q = Quad{{1.0, 1.0, 0.5, 0.5}};
  std::vector<double> y(2 * rows);
  for (auto _ : state) {
    vibrotherm::wave::BlockCsrApply(part, x.data(), y.data(), false, wide);
    benchmark::DoNotOptimize(y.data());
    benchmark::ClobberMemory();
  }
  const double blocks = static_cast<double>(part.value.size());
  state.counters["time_per_block"] =
      benchmark::Counter(blocks, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["KiB"] = (blocks * (sizeof(Quad) + 4) + rows * sizeof(Quad)) / 1024.0;
}

// Block rows: 100 (57 KiB: L1/L2), 400, 1600, 3730 (the paper matrix per rank on 2 ranks), 15000, 60000 (> L2).
BENCHMARK(BM_BlockCsrApply)
    ->ArgsProduct({{100, 400, 1600, 3730, 15000, 60000}, {0, 1}})
    ->ArgNames({"rows", "wide"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
