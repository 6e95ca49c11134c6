// The memory a MUMPS factorisation will take, from MUMPS's own analysis, checked
// before any numerical work (-modes' shift-invert, -wave_start harmonic's complex
// system): a 3D stiffness fills far more than its matrix (nested dissection: O(n^{4/3})
// entries), and running out mid-factorisation on a shared node is the worst way to
// learn it.
#pragma once

#include <petscmat.h>

namespace vibrotherm::wave {

/// Who asks and how much it may take.
struct FactorMemoryLimit {
  const char* who;           ///< the run's name for it in messages ("Modes", "Harmonic start")
  const char* option;        ///< the option that sets the limit, named in the refusal
  double limit_gb = 0.0;     ///< [GB] (0: 0.9 x the memory available on rank 0's node)
  bool force = false;        ///< -force: factor even above that
  bool fallback = false;     ///< above the limit: say so and report *fits = false instead of refusing
};

/// MUMPS's estimate of its LU factorisation of A [bytes] (INFOG(17), in-core, summed
/// over ranks), from its analysis phase with the options under `prefix`. Collective.
PetscErrorCode MumpsFactorMemory(Mat A, const char* prefix, double* bytes);

/// Prints that estimate and refuses, naming limit.option, when it exceeds the limit,
/// unless limit.force (or limit.fallback: then *fits = false); nothing when
/// -<prefix>pc_factor_mat_solver_type is not MUMPS. Collective.
PetscErrorCode CheckFactorMemory(Mat A, const char* prefix, const FactorMemoryLimit& limit, bool* fits = nullptr);

}  // namespace vibrotherm::wave
