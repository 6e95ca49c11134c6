#include "vibrotherm/heat/rung_solvers.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace vibrotherm::heat {

RungSolvers::~RungSolvers() {
  for (Rung& r : rungs_) {
    (void)KSPDestroy(&r.ksp);
    (void)MatDestroy(&r.J);
  }
}

PetscErrorCode RungSolvers::Setup(Mat pattern, Assemble assemble, Configure configure) {
  PetscFunctionBeginUser;
  pattern_ = pattern;
  assemble_ = std::move(assemble);
  configure_ = std::move(configure);
  PetscCall(PetscLogEventRegister("HeatRungSetup", KSP_CLASSID, &setup_event_));  // the same event for every instance
  PetscFunctionReturn(0);
}

PetscErrorCode RungSolvers::Get(double shift, KSP* ksp) {
  PetscFunctionBeginUser;
  ++calls_;
  for (Rung& r : rungs_)
    if (std::abs(shift - r.shift) <= 1e-10 * std::abs(shift)) {
      if (!r.ksp) PetscCall(SetUpRung(&r));
      r.used = calls_;
      *ksp = r.ksp;
      PetscFunctionReturn(0);
    }
  if (rungs_.size() == kCapacity) {  // a new step length: the least recently used goes
    auto oldest = std::min_element(rungs_.begin(), rungs_.end(), [](const Rung& a, const Rung& b) { return a.used < b.used; });
    PetscCall(KSPDestroy(&oldest->ksp));
    PetscCall(MatDestroy(&oldest->J));
    rungs_.erase(oldest);
  }
  rungs_.push_back(Rung{shift, nullptr, nullptr, calls_});
  PetscCall(SetUpRung(&rungs_.back()));
  *ksp = rungs_.back().ksp;
  PetscFunctionReturn(0);
}

PetscErrorCode RungSolvers::SetUpRung(Rung* r) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(setup_event_, 0, 0, 0, 0));
  PetscCall(MatDuplicate(pattern_, MAT_DO_NOT_COPY_VALUES, &r->J));
  PetscCall(MatSetOption(r->J, MAT_KEEP_NONZERO_PATTERN, PETSC_TRUE));
  PetscCall(assemble_(r->shift, r->J));
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)pattern_), &r->ksp));
  PetscCall(KSPSetOperators(r->ksp, r->J, r->J));
  PetscCall(configure_(r->shift, r->ksp));
  PetscCall(KSPSetUp(r->ksp));
  PetscCall(PetscLogEventEnd(setup_event_, 0, 0, 0, 0));
  ++setups_;
  PetscFunctionReturn(0);
}

std::vector<double> RungSolvers::KeptShifts() const {
  std::vector<const Rung*> order;
  for (const Rung& r : rungs_) order.push_back(&r);
  std::sort(order.begin(), order.end(), [](const Rung* a, const Rung* b) { return a->used < b->used; });
  std::vector<double> shifts;
  for (const Rung* r : order) shifts.push_back(r->shift);
  return shifts;
}

PetscErrorCode RungSolvers::Remember(const std::vector<double>& shifts) {
  PetscFunctionBeginUser;
  for (Rung& r : rungs_) {
    PetscCall(KSPDestroy(&r.ksp));
    PetscCall(MatDestroy(&r.J));
  }
  rungs_.clear();
  selected_ = nullptr;
  for (double shift : shifts) rungs_.push_back(Rung{shift, nullptr, nullptr, ++calls_});
  PetscFunctionReturn(0);
}

PetscErrorCode RungSolvers::Select(double shift) {
  PetscFunctionBeginUser;
  PetscCall(Get(shift, &selected_));
  PetscFunctionReturn(0);
}

PetscErrorCode RungSolvers::Apply(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  RungSolvers* self;
  PetscCall(PCShellGetContext(pc, &self));
  PetscCheck(self->selected_, PetscObjectComm((PetscObject)pc), PETSC_ERR_ORDER,
             "heat: a solve before the step's Jacobian chose its rung");
  PetscCall(KSPSolve(self->selected_, x, y));
  PetscFunctionReturn(0);
}

PetscErrorCode RungSolvers::AttachAsPreconditioner(KSP outer) {
  PetscFunctionBeginUser;
  PC pc;
  PetscCall(KSPGetPC(outer, &pc));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, this));
  PetscCall(PCShellSetApply(pc, Apply));
  PetscCall(PCShellSetName(pc, "the solver of the step's rung (heat/rung_solvers)"));
  PetscCall(PCAppendOptionsPrefix(pc, "rung_"));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
