// The wave solver with clustered local time stepping (lts_stepper.hpp): when
// it applies, and the macro step the velocity Verlet TS calls.
#include <string>

#include "vibrotherm/wave/verlet_ts.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::wave {

PetscErrorCode WaveSolver::SetupLts() {
  PetscFunctionBeginUser;
  if (!options_.lts.on) PetscFunctionReturn(0);
  TSType type;
  PetscCall(TSGetType(ts_, &type));
  // Where the global step stays, and why (summary.json says it).
  if (std::string(type) != kVelocityVerletTS) {
    lts_note_ = "off: -wave_ts_type is not velocityverlet";
  } else if (options_.dt > 0.0) {
    lts_note_ = "off: -wave_dt sets one global step";
  } else if (options_.kernel != StiffnessKernel::kBlocked) {
    lts_note_ = "off: needs -wave_kernel blocked";
  }
  if (!lts_note_.empty()) PetscFunctionReturn(0);
  LtsLevels levels;
  PetscCall(AssignCellLevels(op_.space(), material_, options_.lts, &levels));
  if (levels.levels < 2) {
    lts_note_ = "off: every cell has the same level";
    PetscFunctionReturn(0);
  }
  PetscCall(lts_.Setup(op_.space(), material_, op_.mass(), levels, boundary_, excitation_, step_.omega_dt_max(), options_.lts));
  if (lts_.macro_step() <= step_.dt()) {
    lts_note_ = "off: the levels' macro step is not longer than the global step";
    PetscFunctionReturn(0);
  }
  step_.UseMacroStep(lts_.macro_step());
  PetscCall(VelocityVerletSetMacroStep(ts_, MacroStep, this));
  lts_active_ = true;
  PetscFunctionReturn(0);
}

PetscErrorCode WaveSolver::MacroStep(void* ctx, PetscReal t, PetscReal h, Vec u, Vec v) {
  PetscFunctionBeginUser;
  auto* self = static_cast<WaveSolver*>(ctx);
  if (!self->lts_started_) PetscCall(self->lts_.Start(u));  // the level forces of the state (first step, restart)
  self->lts_started_ = true;
  PetscCall(self->lts_.Step(t, h, u, v));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
