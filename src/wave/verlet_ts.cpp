#include "vibrotherm/wave/verlet_ts.hpp"

#include <petsc/private/tsimpl.h>

namespace vibrotherm::wave {
namespace {

struct VerletData {
  IS is_q = nullptr, is_p = nullptr;      ///< not owned (the splits')
  TS sub_q = nullptr, sub_p = nullptr;    ///< not owned
  PetscInt offset_q = 0, offset_p = 0;    ///< local offsets of the splits in the state
  const PetscScalar* base = nullptr;      ///< the state array the views were made on
  Vec q = nullptr, p = nullptr;           ///< views of the state
  Vec q_update = nullptr, p_update = nullptr;
  PetscBool position_rate_is_momentum = PETSC_FALSE;  ///< q̇ = p: drifts skip the RHS call
  VelocityVerletMacroStep macro = nullptr;             ///< the caller's multi-rate step, if any
  void* macro_ctx = nullptr;
};

/// Local offset and size of a contiguous split inside the state vector.
PetscErrorCode SplitOffset(TS ts, IS is, PetscInt* offset, PetscInt* n) {
  PetscFunctionBeginUser;
  PetscInt rstart, rend;
  PetscBool contiguous;
  PetscCall(VecGetOwnershipRange(ts->vec_sol, &rstart, &rend));
  PetscCall(ISGetLocalSize(is, n));
  *offset = 0;
  if (*n == 0) PetscFunctionReturn(0);
  PetscCall(ISContiguousLocal(is, rstart, rend, offset, &contiguous));
  PetscCheck(contiguous, PetscObjectComm((PetscObject)ts), PETSC_ERR_SUP,
             "-ts_type velocityverlet needs contiguous position and momentum splits on every rank");
  PetscFunctionReturn(0);
}

/// Views of u and v on the state's memory, remade only if the state vector's array moved.
PetscErrorCode UpdateViews(TS ts, VerletData* d) {
  PetscFunctionBeginUser;
  PetscScalar* x;
  PetscCall(VecGetArray(ts->vec_sol, &x));  // also marks the state changed: this step writes it
  if (x != d->base) {
    MPI_Comm comm = PetscObjectComm((PetscObject)ts);
    PetscInt nq, np;
    PetscCall(VecDestroy(&d->q));
    PetscCall(VecDestroy(&d->p));
    PetscCall(SplitOffset(ts, d->is_q, &d->offset_q, &nq));
    PetscCall(SplitOffset(ts, d->is_p, &d->offset_p, &np));
    PetscCall(VecCreateMPIWithArray(comm, 1, nq, PETSC_DECIDE, x + d->offset_q, &d->q));
    PetscCall(VecCreateMPIWithArray(comm, 1, np, PETSC_DECIDE, x + d->offset_p, &d->p));
    if (!d->q_update) {
      PetscCall(VecDuplicate(d->q, &d->q_update));
      PetscCall(VecDuplicate(d->p, &d->p_update));
    }
    d->base = x;
  }
  PetscCall(VecRestoreArray(ts->vec_sol, &x));
  PetscFunctionReturn(0);
}

/// Half a step of position: q += h/2 q̇(p, t).
PetscErrorCode Drift(TS ts, VerletData* d, PetscReal h) {
  PetscFunctionBeginUser;
  if (d->position_rate_is_momentum) {
    PetscCall(VecAXPY(d->q, 0.5 * h, d->p));
  } else {
    PetscCall(TSComputeRHSFunction(d->sub_q, ts->ptime, d->p, d->q_update));
    PetscCall(VecAXPY(d->q, 0.5 * h, d->q_update));
  }
  PetscFunctionReturn(0);
}

/// Drift–kick–drift: u += h/2 v; v += h a(u, t + h/2); u += h/2 v.
PetscErrorCode Step(TS ts) {
  PetscFunctionBeginUser;
  auto* d = static_cast<VerletData*>(ts->data);
  PetscCall(UpdateViews(ts, d));
  const PetscReal h = ts->time_step;
  if (d->macro) {
    PetscCall(d->macro(d->macro_ctx, ts->ptime, h, d->q, d->p));
    ts->ptime = ts->ptime + h;
  } else {
    PetscCall(Drift(ts, d, h));
    ts->ptime = ts->ptime + 0.5 * h;
    PetscCall(TSComputeRHSFunction(d->sub_p, ts->ptime, d->q, d->p_update));
    PetscCall(VecAXPY(d->p, h, d->p_update));
    PetscCall(Drift(ts, d, h));
    ts->ptime = ts->ptime + 0.5 * h;
  }
  PetscScalar* x;  // the state changed through the views
  PetscCall(VecGetArray(ts->vec_sol, &x));
  PetscCall(VecRestoreArray(ts->vec_sol, &x));
  PetscFunctionReturn(0);
}

PetscErrorCode SetUp(TS ts) {
  PetscFunctionBeginUser;
  auto* d = static_cast<VerletData*>(ts->data);
  PetscCall(TSRHSSplitGetIS(ts, "position", &d->is_q));
  PetscCall(TSRHSSplitGetIS(ts, "momentum", &d->is_p));
  PetscCall(TSRHSSplitGetSubTS(ts, "position", &d->sub_q));
  PetscCall(TSRHSSplitGetSubTS(ts, "momentum", &d->sub_p));
  PetscCheck(d->is_q && d->is_p && d->sub_q && d->sub_p, PetscObjectComm((PetscObject)ts), PETSC_ERR_USER,
             "-ts_type velocityverlet needs the RHS splits \"position\" and \"momentum\" with their functions");
  TSAdapt adapt;
  PetscCall(TSGetAdapt(ts, &adapt));
  PetscCall(TSAdaptCandidatesClear(adapt));  // fixed steps
  PetscFunctionReturn(0);
}

PetscErrorCode Reset(TS ts) {
  PetscFunctionBeginUser;
  auto* d = static_cast<VerletData*>(ts->data);
  for (Vec* v : {&d->q, &d->p, &d->q_update, &d->p_update}) PetscCall(VecDestroy(v));
  d->base = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode Destroy(TS ts) {
  PetscFunctionBeginUser;
  PetscCall(Reset(ts));
  delete static_cast<VerletData*>(ts->data);
  ts->data = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode Create(TS ts) {
  PetscFunctionBeginUser;
  ts->data = new VerletData;
  ts->ops->setup = SetUp;
  ts->ops->step = Step;
  ts->ops->reset = Reset;
  ts->ops->destroy = Destroy;
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode VelocityVerletSetPositionRateIsMomentum(TS ts, PetscBool identity) {
  PetscFunctionBeginUser;
  PetscBool ours;
  PetscCall(PetscObjectTypeCompare((PetscObject)ts, kVelocityVerletTS, &ours));
  if (ours) static_cast<VerletData*>(ts->data)->position_rate_is_momentum = identity;
  PetscFunctionReturn(0);
}

PetscErrorCode VelocityVerletSetMacroStep(TS ts, VelocityVerletMacroStep macro, void* ctx) {
  PetscFunctionBeginUser;
  PetscBool ours;
  PetscCall(PetscObjectTypeCompare((PetscObject)ts, kVelocityVerletTS, &ours));
  PetscCheck(ours, PetscObjectComm((PetscObject)ts), PETSC_ERR_ARG_WRONG,
             "local time stepping needs -wave_ts_type velocityverlet");
  auto* d = static_cast<VerletData*>(ts->data);
  d->macro = macro;
  d->macro_ctx = ctx;
  PetscFunctionReturn(0);
}

PetscErrorCode RegisterVelocityVerletTS() {
  PetscFunctionBeginUser;
  PetscCall(TSRegister(kVelocityVerletTS, Create));  // a second registration replaces the first
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
