// The harmonic start's iterative solver (-wave_harmonic_solver krylov): GMRES on the
// doubled real form of the damped, linearized wave system
//   Z = [[K̃ − ω²M, −ωC], [ωC, K̃ − ω²M]]   (K̃ = K + K_c, parts interleaved per dof),
// preconditioned on each part by algebraic multigrid on the shifted stiffness
//   P = K̃ + ω²M   (symmetric positive definite, the constraints as identity rows).
// Why this preconditioner: P⁻¹Z maps the modes far above ω to ~1 and those below to ~−1;
// only the few modes near ω (a plate has tens below 40 kHz) are outliers, which GMRES
// removes one by one. Memory is that of Z, P and its multigrid hierarchy plus the Krylov
// basis: linear in the dofs like the explicit run, where MUMPS's 3D factor grows as
// n^{4/3} (39.9 GB for block3d's 350k dofs).
#pragma once

#include <petscksp.h>

namespace vibrotherm::wave {

/// Sets ksp (operators Z already set) to GMRES with the two-part shell preconditioner built on
/// P (global n×n, the wave dofs' layout). coordinates: the nodes' positions as a vector of P's
/// layout with block size = dimension (multigrid's rigid-body near-nullspace), or null.
/// Options: -wave_harmonic_ksp_* for the outer Krylov, -wave_harmonic_mg_* for the multigrid.
/// Keeps its own references to P. Collective.
PetscErrorCode ConfigureHarmonicKrylov(KSP ksp, Mat P, Vec coordinates);

}  // namespace vibrotherm::wave
