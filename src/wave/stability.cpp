#include "vibrotherm/wave/stability.hpp"

#include "vibrotherm/wave/verlet_ts.hpp"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace vibrotherm::wave {

PetscErrorCode LargestAngularFrequency(Mat K, Vec M, double* omega_max) {
  PetscFunctionBeginUser;
  Mat A;
  Vec d;
  PetscCall(MatDuplicate(K, MAT_COPY_VALUES, &A));
  PetscCall(VecDuplicate(M, &d));
  PetscCall(VecCopy(M, d));
  PetscCall(VecSqrtAbs(d));
  PetscCall(VecReciprocal(d));
  PetscCall(MatDiagonalScale(A, d, d));
  EPS eps;
  PetscCall(EPSCreate(PetscObjectComm((PetscObject)K), &eps));
  PetscCall(EPSSetOperators(eps, A, nullptr));
  PetscCall(EPSSetProblemType(eps, EPS_HEP));
  PetscCall(EPSSetWhichEigenpairs(eps, EPS_LARGEST_REAL));
  PetscCall(EPSSetDimensions(eps, 1, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(EPSSetTolerances(eps, 1e-8, 2000));
  PetscCall(EPSSetOptionsPrefix(eps, "wave_stability_"));
  PetscCall(EPSSetFromOptions(eps));
  PetscCall(EPSSolve(eps));
  PetscInt converged;
  PetscCall(EPSGetConverged(eps, &converged));
  PetscCheck(converged >= 1, PetscObjectComm((PetscObject)K), PETSC_ERR_NOT_CONVERGED,
             "SLEPc did not find the largest eigenvalue of M^-1 K (stable time step)");
  PetscScalar lambda;
  PetscCall(EPSGetEigenvalue(eps, 0, &lambda, nullptr));
  *omega_max = std::sqrt(PetscRealPart(lambda));
  PetscCall(EPSDestroy(&eps));
  PetscCall(VecDestroy(&d));
  PetscCall(MatDestroy(&A));
  PetscFunctionReturn(0);
}

namespace {

PetscErrorCode OscillatorRHS(TS, PetscReal, Vec X, Vec F, void*) {
  PetscFunctionBeginUser;
  const PetscScalar* x;
  PetscScalar* f;
  PetscCall(VecGetArrayRead(X, &x));
  PetscCall(VecGetArray(F, &f));
  f[0] = x[1];
  f[1] = -x[0];
  PetscCall(VecRestoreArrayRead(X, &x));
  PetscCall(VecRestoreArray(F, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode PositionRHS(TS, PetscReal, Vec v, Vec f, void*) { return VecCopy(v, f); }
PetscErrorCode MomentumRHS(TS, PetscReal, Vec u, Vec f, void*) {
  PetscFunctionBeginUser;
  PetscCall(VecCopy(u, f));
  PetscCall(VecScale(f, -1.0));
  PetscFunctionReturn(0);
}

/// Largest |x| early (steps < 100) and late (steps >= 300) in a run.
struct GrowthMonitor {
  double early = 0.0, late = 0.0;
};

PetscErrorCode TrackGrowth(TS, PetscInt step, PetscReal, Vec X, void* ctx) {
  PetscFunctionBeginUser;
  auto* g = static_cast<GrowthMonitor*>(ctx);
  PetscReal norm;
  PetscCall(VecNorm(X, NORM_2, &norm));
  if (!std::isfinite(norm)) norm = INFINITY;
  if (step < 100) g->early = std::max(g->early, norm);
  if (step >= 300) g->late = std::max(g->late, norm);
  PetscFunctionReturn(0);
}

/// Whether 400 steps of size h on u'' = -u stay bounded: a bounded oscillation
/// (even one of large amplitude near the limit) has the same maximum late as
/// early; an unstable mode grows exponentially.
PetscErrorCode Stable(const char* prefix, double h, bool* stable, bool* implicit) {
  PetscFunctionBeginUser;
  TS ts;
  Vec X;
  IS is_u, is_v;
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2, &X));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, 1, 0, 1, &is_u));
  PetscCall(ISCreateStride(PETSC_COMM_SELF, 1, 1, 1, &is_v));
  PetscCall(TSCreate(PETSC_COMM_SELF, &ts));
  PetscCall(TSSetOptionsPrefix(ts, prefix));
  PetscCall(TSSetProblemType(ts, TS_LINEAR));
  PetscCall(RegisterVelocityVerletTS());
  PetscCall(TSSetType(ts, kVelocityVerletTS));  // the wave TS's default
  PetscCall(TSSetRHSFunction(ts, nullptr, OscillatorRHS, nullptr));
  PetscCall(TSRHSSplitSetIS(ts, "position", is_u));
  PetscCall(TSRHSSplitSetIS(ts, "momentum", is_v));
  PetscCall(TSRHSSplitSetRHSFunction(ts, "position", nullptr, PositionRHS, nullptr));
  PetscCall(TSRHSSplitSetRHSFunction(ts, "momentum", nullptr, MomentumRHS, nullptr));
  PetscCall(TSSetFromOptions(ts));
  TSType type;
  PetscCall(TSGetType(ts, &type));
  const std::string t(type);
  *implicit = t == TSALPHA2 || t == TSALPHA || t == TSBEULER || t == TSTHETA || t == TSCN || t == TSBDF ||
              t == TSARKIMEX || t == TSROSW || t == TSGLLE || t == TSIRK;
  if (*implicit) {
    *stable = true;
  } else {
    PetscCall(TSSetTimeStep(ts, h));
    PetscCall(TSSetMaxSteps(ts, 400));
    PetscCall(TSSetMaxTime(ts, 1e30));
    PetscCall(TSSetExactFinalTime(ts, TS_EXACTFINALTIME_STEPOVER));
    TSAdapt adapt;
    PetscCall(TSGetAdapt(ts, &adapt));
    PetscCall(TSAdaptSetType(adapt, TSADAPTNONE));
    PetscCall(VecSetValue(X, 0, 1.0, INSERT_VALUES));
    PetscCall(VecSetValue(X, 1, 0.0, INSERT_VALUES));
    GrowthMonitor growth;
    PetscCall(TSMonitorSet(ts, TrackGrowth, &growth, nullptr));
    PetscCall(TSSolve(ts, X));
    *stable = std::isfinite(growth.late) && growth.late <= 1.05 * growth.early;
  }
  PetscCall(TSDestroy(&ts));
  PetscCall(ISDestroy(&is_u));
  PetscCall(ISDestroy(&is_v));
  PetscCall(VecDestroy(&X));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode OscillatorStabilityLimit(const char* prefix, double* omega_dt_max, bool* implicit) {
  PetscFunctionBeginUser;
  bool stable;
  PetscCall(Stable(prefix, 1e-3, &stable, implicit));
  *omega_dt_max = 0.0;
  if (*implicit || !stable) PetscFunctionReturn(0);
  double lo = 1e-3, hi = 8.0;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    PetscCall(Stable(prefix, mid, &stable, implicit));
    (stable ? lo : hi) = mid;
  }
  *omega_dt_max = lo;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
