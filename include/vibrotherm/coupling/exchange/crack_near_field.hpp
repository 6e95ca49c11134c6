// The crack probes' temperature resolved at the wave steps (README "The
// temperature at the crack"): friction heats the crack in pulses of about half
// a microsecond, shorter than a heat step, in a layer a few µm thick. The heat
// mesh receives each heat step's energy as a constant rate and its backward
// Euler smooths the pulses; the saw-tooth at the crack is not in the heat field.
//
// A probe within reach of a crack therefore reads
//   T(t) = [φᵀθ − D](t) + E(t),
// the heat mesh's value without its own response D to the friction heat of a
// window of the last K heat steps (-heat_near_field_steps), plus the exact
// continuum temperature E of that window's heat at wave-step resolution (line
// source along the wave mesh's crack elements, exact in space: line_kernel.hpp).
//   D(t_n) = Σ_{k<K} g_kᵀ q̄_{n−k},  g_k = Tᵀ w_k: the discrete step responses of
//            the heat integrator (HeatSolver::StepResponses) through the friction
//            transfer T, per contact cell; q̄: each heat step's density per cell.
//            Equal steps share one table g_k; a window with unequal steps (the
//            wave step changed, the last step of a run) gets its own, exactly;
//   E(t)   = Σ_c Σ_j q_{c,j} [Φ_c(t − t_{j−1}) − Φ_c(t − t_j)] over the wave steps j
//            of the window, q_{c,j} = ΔW_c / Δt_j the friction power per area.
// Sources older than the window are where the heat mesh is accurate (they have
// spread over √(α K Δt) ≫ the first layer); [φᵀθ − D] is smooth in time and is
// interpolated between heat steps (probe_temperatures.hpp).
//
// The input is the friction energy per cell over intervals: per heat step for
// D (what the heat solver received), per wave step for E (only the window's).
// Any interval lengths work (a replayed record of per-cell energies too): E
// takes any wave steps, D any heat steps (K solves a step while they differ).
//
// MPI: each rank sums over its own contact cells; the caller adds the ranks'
// partial sums (one reduction per coupling interval).
#pragma once

#include <petscvec.h>

#include <array>
#include <deque>
#include <vector>

#include "vibrotherm/coupling/exchange/friction_heat.hpp"
#include "vibrotherm/coupling/exchange/line_kernel.hpp"
#include "vibrotherm/heat/heat_probes.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::coupling {

class CrackNearField {
 public:
  CrackNearField() = default;
  CrackNearField(const CrackNearField&) = delete;
  CrackNearField& operator=(const CrackNearField&) = delete;
  ~CrackNearField();

  /// For every probe of `heat` (probes: its points in the heat mesh): a near field when a
  /// contact cell lies within reach (and no outer edge does). `heat_step`: the
  /// expected heat step (the window's reach); `steps`: K. Collective.
  PetscErrorCode Setup(const interface::CrackInterface& crack, const FrictionHeat& friction, heat::HeatSolver* heat,
                       const heat::HeatProbes& probes, PetscInt steps, double heat_step);
  /// Whether probe p has a near field (the same on every rank).
  bool active(std::size_t probe) const { return probe < probes_.size() && probes_[probe].active; }
  bool any() const;
  /// After every wave step (ending at t): keeps the cells' cumulative friction energy.
  void AfterWaveStep(double t);
  /// The same with the cells' energies given (a periodic continuation's replay, no waves running).
  void SampleEnergies(double t, const std::vector<double>& W);
  /// After every heat step (ending at t): keeps the step's density per cell. Collective.
  PetscErrorCode AfterHeatStep(double t);
  /// A periodic continuation's heat ladder (other integrator, averaged power over whole periods,
  /// spread far beyond the crack's layers): the probes read the field alone; the window restarts
  /// empty at t when the waves come back (D and E then cover the same steps again).
  void Pause(double t);
  void Restart(double t);
  /// This rank's part of D for probe p at the ends of the last three heat steps
  /// (j = 0: t_n, 1: t_{n−1}, 2: t_{n−2}), all for the window of step n.
  std::array<double, 3> Discrete(std::size_t probe) const;
  /// This rank's part of E for probe p at times of the last heat step (t_{n−1} < t ≤ t_n).
  PetscErrorCode Exact(std::size_t probe, const std::vector<double>& times, std::vector<double>* e) const;
  /// Checkpoints (after a heat step): the energy histories of the window; and back. Collective.
  PetscErrorCode Save(store::Checkpoint& checkpoint, const std::vector<long long>& cell_keys) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const std::vector<long long>& cell_keys);

 private:
  struct Probe {
    bool active = false;
    LineKernel kernel;
    std::vector<int> cells;                ///< owned cell of each kernel cell
    Vec phi = nullptr;                     ///< the probe as a functional of θ
    std::vector<std::vector<double>> g;    ///< g[k][owned cell]: response at lag k to equal steps
    std::deque<std::vector<double>> terms; ///< last three steps: g_kᵀ q̄_{n−k} by lag k (this rank's cells)
    std::vector<double> jumps;             ///< [boundary][kernel cell]: q_{b+1} − q_b over the window
  };
  struct Sample {
    double t;
    std::vector<double> W;  ///< cumulative energy per owned cell
  };
  PetscErrorCode FindNearCells(std::size_t p, const std::array<double, 2>& x, double reach);
  PetscErrorCode ClearOfEdges(const std::array<double, 2>& x, double reach, bool* clear) const;
  /// g_k per probe for K equal steps of h.
  PetscErrorCode EqualStepResponses(double h);
  /// Each probe's terms g_kᵀ q̄_{n−k} of the step just taken (its own responses when the window's steps differ).
  PetscErrorCode Terms();
  void Prune();
  /// The window's density jumps at every wave step boundary (Exact's summation by parts).
  void Jumps();

  const interface::CrackInterface* crack_ = nullptr;
  const FrictionHeat* friction_ = nullptr;
  heat::HeatSolver* heat_ = nullptr;
  std::vector<Probe> probes_;
  PetscInt steps_ = 24;
  double alpha_ = 1.0, rho_c_ = 1.0, tau_max_ = 0.0;
  bool paused_ = false;
  double equal_step_ = 0.0;                 ///< heat step length of the probes' g (0: none yet)
  std::deque<double> ends_;                 ///< heat step ends t_{n−K} .. t_n
  std::deque<std::vector<double>> density_; ///< q̄ of steps n−K+1 .. n
  std::deque<Sample> fine_;                 ///< every wave step from t_{n−K} on
  std::size_t owned_cells_ = 0;
  PetscLogEvent setup_event_ = 0, step_event_ = 0, exact_event_ = 0, response_event_ = 0;
};

}  // namespace vibrotherm::coupling
