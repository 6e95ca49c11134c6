// The harmonic start's GMRES with a multigrid on each part (harmonic_krylov.hpp).
#include "vibrotherm/wave/harmonic_krylov.hpp"

namespace vibrotherm::wave {
namespace {

/// The shell preconditioner's state: one multigrid solve of P, applied to the real and the
/// imaginary part (the even and odd entries of the doubled vectors) in turn.
struct PartsPreconditioner {
  KSP multigrid = nullptr;
  IS parts[2] = {nullptr, nullptr};
};

PetscErrorCode ApplyParts(PC pc, Vec x, Vec y) {
  PetscFunctionBeginUser;
  PartsPreconditioner* context;
  PetscCall(PCShellGetContext(pc, &context));
  for (IS part : context->parts) {
    Vec xp, yp;
    PetscCall(VecGetSubVector(x, part, &xp));
    PetscCall(VecGetSubVector(y, part, &yp));
    PetscCall(KSPSolve(context->multigrid, xp, yp));
    PetscCall(VecRestoreSubVector(y, part, &yp));
    PetscCall(VecRestoreSubVector(x, part, &xp));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode DestroyParts(PC pc) {
  PetscFunctionBeginUser;
  PartsPreconditioner* context;
  PetscCall(PCShellGetContext(pc, &context));
  PetscCall(KSPDestroy(&context->multigrid));
  for (IS& part : context->parts) PetscCall(ISDestroy(&part));
  delete context;
  PetscFunctionReturn(0);
}

/// One V-cycle of smoothed-aggregation multigrid on P, with the rigid-body modes when the nodes'
/// positions are known (elasticity's near-nullspace: without it aggregation sees only translations).
PetscErrorCode CreateMultigrid(Mat P, Vec coordinates, KSP* multigrid) {
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(PetscObjectComm((PetscObject)P), multigrid));
  PetscCall(KSPSetOptionsPrefix(*multigrid, "wave_harmonic_mg_"));
  PetscCall(KSPSetOperators(*multigrid, P, P));
  PetscCall(KSPSetType(*multigrid, KSPPREONLY));
  PC pc;
  PetscCall(KSPGetPC(*multigrid, &pc));
  PetscCall(PCSetType(pc, PCGAMG));
  if (coordinates) {
    MatNullSpace rigid;
    PetscCall(MatNullSpaceCreateRigidBody(coordinates, &rigid));
    PetscCall(MatSetNearNullSpace(P, rigid));
    PetscCall(MatNullSpaceDestroy(&rigid));
  }
  PetscCall(KSPSetFromOptions(*multigrid));
  PetscCall(KSPSetUp(*multigrid));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ConfigureHarmonicKrylov(KSP ksp, Mat P, Vec coordinates) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)ksp);
  auto* context = new PartsPreconditioner;
  PetscCall(CreateMultigrid(P, coordinates, &context->multigrid));
  PetscInt start, end;
  PetscCall(MatGetOwnershipRange(P, &start, &end));
  for (PetscInt part = 0; part < 2; ++part)
    PetscCall(ISCreateStride(comm, end - start, 2 * start + part, 2, &context->parts[part]));
  PC pc;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, context));
  PetscCall(PCShellSetApply(pc, ApplyParts));
  PetscCall(PCShellSetDestroy(pc, DestroyParts));
  PetscCall(PCShellSetName(pc, "multigrid on K + K_c + w^2 M, each part"));
  PetscCall(KSPSetType(ksp, KSPGMRES));
  PetscCall(KSPGMRESSetRestart(ksp, 100));  // the outliers near ω need a basis that holds them
  PetscCall(KSPSetTolerances(ksp, 1e-8, PETSC_DEFAULT, PETSC_DEFAULT, 2000));
  PetscCall(KSPSetPCSide(ksp, PC_RIGHT));  // the residual GMRES minimises is the true one
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
