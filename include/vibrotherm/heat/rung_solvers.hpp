// Linear solvers of the heat's Jacobians J = K + shift·M, one per step length ("rung").
//
// Why: the step ladder changes its step only at rungs, a periodic continuation's ladder
// too, and a step clipped to an output time or a camera window comes back at every window
// (1 ms and 9 ms steps in turn at 100 fps): a handful of step lengths recur. Each gets its
// own copy of J and a solver set up once for it (a Cholesky factorisation, a BoomerAMG
// hierarchy, Jacobi), and every step of that length reuses it; the least recently used of
// the last kCapacity goes. Before, one Jacobian per TS was refactored (or its AMG set up
// again) at every change of the step, i.e. every step while the camera's windows alternate.
//
// A TS uses them through AttachAsPreconditioner: its KSP (CG, or PREONLY for a factor)
// keeps the TS's own Jacobian as its operator and gets a shell PC that applies the solver
// of the shift Select chose last (the TS's IJacobian selects it).
#pragma once

#include <petscksp.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace vibrotherm::heat {

class RungSolvers {
 public:
  /// Fills J (K's pattern) with K + shift·M (sink rows as the TS's). Collective.
  using Assemble = std::function<PetscErrorCode(double shift, Mat J)>;
  /// Sets up ksp (operators set) as the solver for this shift. Collective.
  using Configure = std::function<PetscErrorCode(double shift, KSP ksp)>;
  static constexpr std::size_t kCapacity = 4;

  RungSolvers() = default;
  RungSolvers(const RungSolvers&) = delete;
  RungSolvers& operator=(const RungSolvers&) = delete;
  ~RungSolvers();

  /// pattern: a matrix of J's pattern (duplicated per rung, values not copied). Each rung's
  /// assembly and setup is logged as the event HeatRungSetup (-log_view: count and time).
  PetscErrorCode Setup(Mat pattern, Assemble assemble, Configure configure);
  /// The solver of this shift: a kept one whose shift is within a relative 1e-10 (as the
  /// TS keeps its Jacobian: equal steps differ in their last bits), else a new one. Collective.
  PetscErrorCode Get(double shift, KSP* ksp);
  /// Get(shift), and makes it the one AttachAsPreconditioner's PC applies. Collective.
  PetscErrorCode Select(double shift);
  /// outer's PC becomes a shell applying the selected solver (prefix <outer's>rung_, so that
  /// the user's -<prefix>pc_type reaches the rungs' solvers, not the shell).
  PetscErrorCode AttachAsPreconditioner(KSP outer);
  /// Solvers set up so far (factorisations or preconditioner setups).
  PetscInt setups() const { return setups_; }
  /// The kept rungs' shifts, least recently used first (a checkpoint) ...
  std::vector<double> KeptShifts() const;
  /// ... and back, in place of any kept now: each is set up again at that very shift when a step
  /// asks for it. Why: a step whose shift differs in its last bits reuses a kept rung, so the run
  /// never stopped solved with the matrix of the rung's first shift; a restart must too, or it
  /// differs from it by rounding.
  PetscErrorCode Remember(const std::vector<double>& shifts);

 private:
  struct Rung {
    double shift;
    Mat J;    ///< null for a remembered rung not set up yet
    KSP ksp;
    long long used;  ///< the Get call that last returned it
  };
  static PetscErrorCode Apply(PC pc, Vec x, Vec y);
  /// Assembles r.J at r.shift and sets up r.ksp. Collective.
  PetscErrorCode SetUpRung(Rung* r);
  Mat pattern_ = nullptr;
  Assemble assemble_;
  Configure configure_;
  std::vector<Rung> rungs_;
  KSP selected_ = nullptr;
  long long calls_ = 0;
  PetscInt setups_ = 0;
  PetscLogEvent setup_event_ = 0;
};

}  // namespace vibrotherm::heat
