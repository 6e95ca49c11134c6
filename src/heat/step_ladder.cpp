#include "vibrotherm/heat/step_ladder.hpp"

#include <petsc/private/tsimpl.h>

namespace vibrotherm::heat {
namespace {

struct Ladder {              // plain data: PetscNew'ed (Create sets the defaults)
  PetscInt steps_per_rung;  ///< -ts_adapt_ladder_steps (16)
  PetscReal ratio;          ///< -ts_adapt_ladder_ratio (2)
  PetscReal rung;           ///< the current rung; 0 until StepLadderStart or the first step sets it
  PetscInt taken;           ///< steps taken on it
};

PetscErrorCode Choose(TSAdapt adapt, TS, PetscReal h, PetscInt* next_sc, PetscReal* next_h, PetscBool* accept,
                      PetscReal* wlte, PetscReal* wltea, PetscReal* wlter) {
  PetscFunctionBeginUser;
  auto* ladder = static_cast<Ladder*>(adapt->data);
  if (ladder->rung <= 0.0) ladder->rung = h;  // the step the TS was started with
  if (++ladder->taken >= ladder->steps_per_rung) {
    ladder->rung = PetscMin(ladder->rung * ladder->ratio, adapt->dt_max);
    ladder->taken = 0;
  }
  *next_h = PetscClipInterval(ladder->rung, adapt->dt_min, adapt->dt_max);
  *next_sc = 0;
  *accept = PETSC_TRUE;
  *wlte = *wltea = *wlter = -1;  // no error estimate: nothing to report
  PetscFunctionReturn(0);
}

PetscErrorCode Reset(TSAdapt adapt) {
  PetscFunctionBeginUser;
  auto* ladder = static_cast<Ladder*>(adapt->data);
  ladder->rung = 0.0;
  ladder->taken = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode Destroy(TSAdapt adapt) {
  PetscFunctionBeginUser;
  PetscCall(PetscFree(adapt->data));
  PetscFunctionReturn(0);
}

PetscErrorCode SetFromOptions(TSAdapt adapt, PetscOptionItems* PetscOptionsObject) {
  PetscFunctionBeginUser;
  auto* ladder = static_cast<Ladder*>(adapt->data);
  PetscOptionsHeadBegin(PetscOptionsObject, "Step ladder (free diffusion)");
  PetscCall(PetscOptionsInt("-ts_adapt_ladder_steps", "Steps on each rung before the step grows", nullptr,
                            ladder->steps_per_rung, &ladder->steps_per_rung, nullptr));
  PetscCall(PetscOptionsReal("-ts_adapt_ladder_ratio", "Growth of the step from one rung to the next", nullptr,
                             ladder->ratio, &ladder->ratio, nullptr));
  PetscOptionsHeadEnd();
  const char* prefix = PetscOptionsObject->prefix;  // the TS's: the adaptor has none of its own
  PetscCheck(ladder->steps_per_rung >= 1, PetscObjectComm((PetscObject)adapt), PETSC_ERR_USER_INPUT,
             "-%sts_adapt_ladder_steps must be >= 1, got %" PetscInt_FMT, prefix ? prefix : "",
             ladder->steps_per_rung);
  PetscCheck(ladder->ratio >= 1.0, PetscObjectComm((PetscObject)adapt), PETSC_ERR_USER_INPUT,
             "-%sts_adapt_ladder_ratio must be >= 1, got %g", prefix ? prefix : "", (double)ladder->ratio);
  PetscFunctionReturn(0);
}

PetscErrorCode View(TSAdapt adapt, PetscViewer viewer) {
  PetscFunctionBeginUser;
  auto* ladder = static_cast<Ladder*>(adapt->data);
  PetscBool ascii;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii)
    PetscCall(PetscViewerASCIIPrintf(viewer, "  step x %g every %" PetscInt_FMT " steps, current rung %g\n",
                                     (double)ladder->ratio, ladder->steps_per_rung, (double)ladder->rung));
  PetscFunctionReturn(0);
}

PetscErrorCode Create(TSAdapt adapt) {
  PetscFunctionBeginUser;
  Ladder* ladder;
  PetscCall(PetscNew(&ladder));  // zeroed: rung 0 (set by the first step), taken 0
  ladder->steps_per_rung = 16;
  ladder->ratio = 2.0;
  adapt->data = ladder;
  adapt->ops->choose = Choose;
  adapt->ops->reset = Reset;
  adapt->ops->destroy = Destroy;
  adapt->ops->setfromoptions = SetFromOptions;
  adapt->ops->view = View;
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode RegisterStepLadder() {
  PetscFunctionBeginUser;
  PetscCall(TSAdaptRegister(kStepLadderAdapt, Create));
  PetscFunctionReturn(0);
}

PetscErrorCode StepLadderStart(TSAdapt adapt, PetscReal rung) {
  PetscFunctionBeginUser;
  PetscBool ladder;
  PetscCall(PetscObjectTypeCompare((PetscObject)adapt, kStepLadderAdapt, &ladder));
  if (!ladder) PetscFunctionReturn(0);
  auto* data = static_cast<Ladder*>(adapt->data);
  data->rung = rung;
  data->taken = 0;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
