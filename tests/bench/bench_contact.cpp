// MMD cell updates per second under a realistic history: shear-dominated
// sinusoid with clapping (contact lost for part of each cycle), 100 steps per
// cycle, 1000 cells with staggered phases as along a crack.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <vector>

#include "vibrotherm/contact/crack_law.hpp"

namespace {

using namespace vibrotherm::contact;

struct History {
  std::vector<double> a;      // [step][cell] flattened
  std::vector<Tangential> b;  // one component (2D)
  std::size_t cells, steps;
};

History make_history(std::size_t cells, std::size_t steps, const ContactParameters& p) {
  History h{{}, {}, cells, steps};
  h.a.resize(cells * steps);
  h.b.resize(cells * steps);
  const double s = 1e-8, tm = p.theta() * p.mu;
  for (std::size_t k = 0; k < steps; ++k) {
    const double phase = 2.0 * M_PI * k / 100.0;  // 100 steps per cycle
    for (std::size_t c = 0; c < cells; ++c) {
      const double shift = 0.01 * c;
      h.a[k * cells + c] = s * (0.3 + 0.5 * std::sin(phase + shift + 0.4));       // clapping: a < 0 for part of the cycle
      h.b[k * cells + c] = Tangential(tm * s * (1.2 * std::sin(phase + shift)));  // shear-dominated, reaches sliding
    }
  }
  return h;
}

/// One crack's worth of MMD cells in their virgin state, and the history to drive them.
struct CrackCells {
  static constexpr std::size_t cells = 1000, steps = 1000;
  History history;
  std::unique_ptr<CrackLaw> law;
  std::size_t step = 0;
  explicit CrackCells(const ContactParameters& p) : history(make_history(cells, steps, p)), law(create_crack_law(p)) {
    law->initialize(cells, history.a.data(), history.b.data());
  }
  /// Advances to the next step (cycling) and returns the offset of its rows.
  std::size_t next() {
    step = step + 1 < steps ? step + 1 : 1;
    return step * cells;
  }
};

/// Commits per second; arg 0: Biwa m = 1/2 (paper default, p = 2), arg 1: power
/// law with a general exponent p = 1.7 (pow() in every law evaluation).
void BM_MmdCommit(benchmark::State& state) {
  ContactParameters p;  // Biwa law (paper default), mu = 1
  if (state.range(0) == 1) {
    p.normal_law = "power";
    p.power_p = 1.7;
    p.power_C = 1e6 / std::pow(1e-8, 1.7);
  }
  state.SetLabel(state.range(0) == 1 ? "power p=1.7" : "biwa m=0.5");
  CrackCells crack(p);
  double W = 0.0;
  for (auto _ : state) {
    const std::size_t row = crack.next();
    for (std::size_t c = 0; c < crack.cells; ++c)
      W += crack.law->commit(c, crack.history.a[row + c], crack.history.b[row + c]).dW;
  }
  benchmark::DoNotOptimize(W);
  state.counters["updates_per_s"] = benchmark::Counter(static_cast<double>(state.iterations() * crack.cells),
                                                       benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MmdCommit)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// What the wave solver does per step with velocity Verlet: one trial (RHS) and one commit.
void BM_MmdTrialAndCommit(benchmark::State& state) {
  CrackCells crack{ContactParameters{}};
  double sum = 0.0;
  for (auto _ : state) {
    const std::size_t row = crack.next();
    for (std::size_t c = 0; c < crack.cells; ++c) {
      const double a = crack.history.a[row + c];
      const Tangential& b = crack.history.b[row + c];
      sum += crack.law->trial(c, a, b).T[0] + crack.law->commit(c, a, b).dW;
    }
  }
  benchmark::DoNotOptimize(sum);
  state.counters["steps_per_s"] = benchmark::Counter(static_cast<double>(state.iterations() * crack.cells),
                                                     benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MmdTrialAndCommit)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
