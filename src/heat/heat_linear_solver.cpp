// The heat's linear solvers: which KSP and PC a Jacobian K + shift·M gets, and the
// defaults vibrotherm puts in the options database for them (the user's options win).
#include <petscdmplex.h>

#include <string>

#include "vibrotherm/heat/heat_solver.hpp"

namespace vibrotherm::heat {

namespace {

/// Puts -<prefix>name value in the options database unless the user gave it.
PetscErrorCode DefaultOption(const char* prefix, const char* name, const char* value) {
  PetscFunctionBeginUser;
  PetscBool given;
  PetscCall(PetscOptionsHasName(nullptr, prefix, name, &given));
  const std::string full = "-" + std::string(prefix ? prefix : "") + (name + 1);  // name without its '-'
  if (!given) PetscCall(PetscOptionsSetValue(nullptr, full.c_str(), value));
  PetscFunctionReturn(0);
}

/// The -<prefix>pc_type the user gave ("" when none).
PetscErrorCode UserPcType(const char* prefix, std::string* type) {
  PetscFunctionBeginUser;
  char value[64] = "";
  PetscBool given;
  PetscCall(PetscOptionsGetString(nullptr, prefix, "-pc_type", value, sizeof value, &given));
  *type = given ? value : "";
  PetscFunctionReturn(0);
}

/// BoomerAMG for a 3D heat mesh (hypre's advice for 3D problems): strong threshold
/// 0.5, HMIS coarsening, ext+i interpolation, one level of aggressive coarsening.
/// On block3d_small's free phase (21735 dofs, 486 steps): 9.8 s against 59 s with
/// hypre's defaults, 14 CG iterations a solve instead of 20, the same temperatures
/// (heat content to 1e-13). The user's -<prefix>pc_hypre_boomeramg_* win.
PetscErrorCode DefaultBoomerAmg3D(const char* prefix) {
  PetscFunctionBeginUser;
  PetscCall(DefaultOption(prefix, "-pc_hypre_boomeramg_strong_threshold", "0.5"));
  PetscCall(DefaultOption(prefix, "-pc_hypre_boomeramg_coarsen_type", "HMIS"));
  PetscCall(DefaultOption(prefix, "-pc_hypre_boomeramg_interp_type", "ext+i"));
  PetscCall(DefaultOption(prefix, "-pc_hypre_boomeramg_agg_nl", "1"));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode HeatSolver::StiffnessToMassRatio(double shift, double* ratio) const {
  PetscFunctionBeginUser;
  Vec k, m;
  PetscCall(VecDuplicate(theta_, &k));
  PetscCall(VecDuplicate(theta_, &m));
  PetscCall(MatGetDiagonal(K_, k));
  PetscCall(MatGetDiagonal(M_, m));
  PetscCall(VecPointwiseDivide(k, k, m));
  PetscReal largest;
  PetscCall(VecMax(k, nullptr, &largest));
  PetscCall(VecDestroy(&k));
  PetscCall(VecDestroy(&m));
  *ratio = largest / shift;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::ConfigureLinearSolver(KSP ksp, bool direct, double stiffness_ratio) {
  PetscFunctionBeginUser;
  // The Jacobian (K + shift M, sink rows and columns replaced by the identity)
  // is SPD. Below kDirectSolveDofs: Cholesky (nested dissection, on every rank),
  // factored once for a fixed step (0.7 ms a solve at 6e3 dofs against 2 ms for
  // CG + BoomerAMG or MUMPS on 2 ranks, measured) and numerically refactored when
  // a new step changes the shift (the free phase's step ladder: once per rung;
  // with error-controlled steps once per step, still 1.5 s against 4.0 s with CG +
  // BoomerAMG at rtol 1e-12, same temperatures). Larger:
  // CG + hypre BoomerAMG (CG + GAMG diverged once the step grew, PETSC-NOTES.md).
  // 3D factors fill far more: Cholesky took 8.8 s against CG + BoomerAMG's 1.9 s
  // for 91 steps at 2.2e4 dofs (a 3D heat box), hence a lower threshold there.
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  const char* prefix;
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  std::string user_pc;
  PetscCall(UserPcType(prefix, &user_pc));
  // A preconditioner the user names is iterated to the tolerance, never applied once.
  const bool factor = user_pc.empty() || user_pc == PCREDUNDANT || user_pc == PCCHOLESKY || user_pc == PCLU;
  if (direct && factor) {
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscCall(PCSetType(pc, PCREDUNDANT));
    KSP inner;
    PC factor;
    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCall(KSPGetPC(inner, &factor));
    PetscCall(PCSetType(factor, PCCHOLESKY));
    PetscCall(PCFactorSetMatOrderingType(factor, MATORDERINGND));
    PetscFunctionReturn(0);
  }
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, 1e-12, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  // A fixed step so short that the mass dominates every row (the coupled steps:
  // fractions of a source period) needs no multigrid: Jacobi's CG converges in a few
  // dozen products, each ~7× cheaper than a V-cycle (block3d, ratio below).
  const bool jacobi = stiffness_ratio >= 0.0 && stiffness_ratio <= kJacobiStiffnessRatio;
  PetscCall(PCSetType(pc, jacobi ? PCJACOBI : PCHYPRE));
  PetscCall(PetscInfo(ksp, "%s: stiffness-to-mass ratio %g: %s\n", prefix ? prefix : "", stiffness_ratio,
                      jacobi ? "Jacobi" : "BoomerAMG"));
  const bool hypre = user_pc.empty() ? !jacobi : user_pc == PCHYPRE;
  if (hypre && space_.dim() == 3) PetscCall(DefaultBoomerAmg3D(prefix));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
