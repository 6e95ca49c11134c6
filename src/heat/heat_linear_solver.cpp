// The heat's linear solvers: which KSP and PC a Jacobian K + shift·M gets, and the
// defaults vibrotherm puts in the options database for them (the user's options win).
#include <petscdmplex.h>

#include <string>

#include "vibrotherm/heat/heat_solver.hpp"

#include "vibrotherm/options/query/option_query.hpp"

namespace vibrotherm::heat {

namespace {

/// Puts -<prefix>name value in the options database unless the user gave it.
PetscErrorCode DefaultOption(const char* prefix, const char* name, const char* value) {
  PetscFunctionBeginUser;
  bool given;
  PetscCall(OptionGiven(prefix, name, &given));
  const std::string full = "-" + std::string(prefix ? prefix : "") + (name + 1);  // name without its '-'
  if (!given) PetscCall(PetscOptionsSetValue(nullptr, full.c_str(), value));
  PetscFunctionReturn(0);
}

/// The -<prefix>pc_type the user gave ("" when none).
PetscErrorCode UserPcType(const char* prefix, std::string* type) {
  PetscFunctionBeginUser;
  type->clear();
  PetscCall(OptionText(prefix, "-pc_type", type));
  PetscFunctionReturn(0);
}

/// BoomerAMG for a 3D heat mesh: HMIS coarsening, ext+i interpolation, one level of
/// aggressive coarsening (hypre's advice for 3D problems), and a strong threshold of 0.8,
/// not hypre's 3D advice of 0.5: the heat grids' layers across a crack plane span the whole
/// box, cells 3 µm by 2.5 mm, and only a high threshold coarsens along them alone. On
/// block3d's 110055 heat dofs the cooling rungs took 10-15 V-cycles a step to 1e-8 against
/// 18-45 with 0.5 to 1e-12 (docs/MEASUREMENTS.md "The cooling phase in 3D").
/// The user's -<prefix>pc_hypre_boomeramg_* win.
PetscErrorCode DefaultBoomerAmg3D(const char* prefix) {
  PetscFunctionBeginUser;
  PetscCall(DefaultOption(prefix, "-pc_hypre_boomeramg_strong_threshold", "0.8"));
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

PetscErrorCode HeatSolver::Iterative(const char* prefix, bool* iterative) const {
  PetscFunctionBeginUser;
  std::string user_pc;
  PetscCall(UserPcType(prefix, &user_pc));
  // A preconditioner the user names is iterated to the tolerance, never applied once.
  const bool factor = user_pc.empty() || user_pc == PCREDUNDANT || user_pc == PCCHOLESKY || user_pc == PCLU;
  *iterative = !(direct_solve() && factor);
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::ConfigureKsp(KSP ksp) const {
  PetscFunctionBeginUser;
  const char* prefix;
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  bool iterative;
  PetscCall(Iterative(prefix, &iterative));
  if (!iterative) {
    PetscCall(KSPSetType(ksp, KSPPREONLY));
    PetscFunctionReturn(0);
  }
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, kRelativeTolerance, 1e-50, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::ConfigurePc(KSP ksp, const char* prefix, double shift) const {
  PetscFunctionBeginUser;
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  // The Jacobian (K + shift M, sink rows and columns replaced by the identity)
  // is SPD. Below kDirectSolveDofs: Cholesky (nested dissection, on every rank),
  // 0.7 ms a solve at 6e3 dofs against 2 ms for CG + BoomerAMG or MUMPS on 2 ranks
  // (measured), set up once per rung (rung_solvers.hpp). Larger: CG + hypre BoomerAMG
  // (CG + GAMG diverged once the step grew, PETSC-NOTES.md). 3D factors fill far more:
  // Cholesky took 8.8 s against CG + BoomerAMG's 1.9 s for 91 steps at 2.2e4 dofs (a 3D
  // heat box), hence a lower threshold there; MUMPS's Cholesky of block3d's 110055 heat
  // dofs took 50-70 s a rung (docs/MEASUREMENTS.md).
  PetscCall(PCSetOptionsPrefix(pc, prefix));
  bool iterative;
  PetscCall(Iterative(prefix, &iterative));
  if (!iterative) {
    PetscCall(PCSetType(pc, PCREDUNDANT));
    KSP inner;
    PC factor;
    PetscCall(PCRedundantGetKSP(pc, &inner));
    PetscCall(KSPGetPC(inner, &factor));
    PetscCall(PCSetType(factor, PCCHOLESKY));
    PetscCall(PCFactorSetMatOrderingType(factor, MATORDERINGND));
    PetscCall(PCSetFromOptions(pc));
    PetscFunctionReturn(0);
  }
  // A step so short that the mass dominates every row (the coupled steps: fractions of a
  // source period; the free phase's first rungs) needs no multigrid: Jacobi's CG converges
  // in a few dozen products, each ~7x cheaper than a V-cycle (block3d).
  double ratio = -1.0;
  if (shift > 0.0) PetscCall(StiffnessToMassRatio(shift, &ratio));
  const bool jacobi = ratio >= 0.0 && ratio <= kJacobiStiffnessRatio;
  PetscCall(PCSetType(pc, jacobi ? PCJACOBI : PCHYPRE));
  PetscCall(PetscInfo(ksp, "%s: stiffness-to-mass ratio %g: %s\n", prefix ? prefix : "", ratio,
                      jacobi ? "Jacobi" : "BoomerAMG"));
  PetscCall(PCSetFromOptions(pc));  // the user's -<prefix>pc_type wins
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::ReadSolverOptions(const char* prefix) const {
  PetscFunctionBeginUser;
  // The rungs' solvers are made by the steps; their options are read now (a bad value is
  // refused before any step, none is reported unused): a stand-in of the type that reads most.
  std::string user_pc;
  PetscCall(UserPcType(prefix, &user_pc));
  bool iterative;
  PetscCall(Iterative(prefix, &iterative));
  if (iterative && space_.dim() == 3 && (user_pc.empty() || user_pc == PCHYPRE)) PetscCall(DefaultBoomerAmg3D(prefix));
  PC pc;
  PetscCall(PCCreate(PetscObjectComm((PetscObject)dm_), &pc));
  PetscCall(PCSetOptionsPrefix(pc, prefix));
  PetscCall(PCSetType(pc, iterative ? PCHYPRE : PCREDUNDANT));
  PetscCall(PCSetFromOptions(pc));
  PetscCall(PCDestroy(&pc));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatSolver::ConfigureStepSolver(TS ts, KSP ksp) {
  PetscFunctionBeginUser;
  const char* prefix;
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  PetscCall(ConfigureKsp(ksp));
  PetscCall(ReadSolverOptions(prefix));
  auto rungs = std::make_unique<RungSolvers>();
  const std::string own(prefix ? prefix : "");
  PetscCall(rungs->Setup(
      K_, [this](double shift, Mat J) { return FillJacobian(shift, J); },
      [this, own](double shift, KSP rung) {
        PetscFunctionBeginUser;
        PetscCall(KSPSetType(rung, KSPPREONLY));  // the step's KSP iterates; a rung applies its PC once
        PetscCall(ConfigurePc(rung, own.c_str(), shift));
        PetscFunctionReturn(0);
      }));
  PetscCall(rungs->AttachAsPreconditioner(ksp));
  rungs_[ts] = std::move(rungs);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
