// The harmonic start's problem (-wave_start harmonic): the steady response of the
// linearized waves to the source at its frequency, solved once before the first step
// (harmonic_start.cpp has the method). It reads the wave operator's pieces and fills
// u(0), v(0); the wave solver then books the state's energy as the source's work.
#pragma once

#include <petscdm.h>
#include <petscmat.h>

#include <functional>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/material.hpp"
#include "vibrotherm/wave/wave_boundary.hpp"

namespace vibrotherm::wave {

class WaveInterface;
struct WaveOptions;

/// What the harmonic problem is made of (the wave solver's, not owned).
struct HarmonicOperator {
  DM dm = nullptr;
  const fe::LagrangeSpace* space = nullptr;
  Mat A = nullptr;  ///< −M⁻¹K
  Vec M = nullptr;  ///< the lumped mass
  const WaveBoundary* boundary = nullptr;
  const Excitation* excitation = nullptr;
  const ElasticMaterial* material = nullptr;
  const WaveOptions* options = nullptr;
  const WaveInterface* interface = nullptr;  ///< null: no crack contact (its tangent stiffness otherwise)
};

class HarmonicStart {
 public:
  explicit HarmonicStart(const HarmonicOperator& op) : op_(op) {}
  /// u = Im U, v = ω Re U (global vectors of the DM) for the steady phasor U. Collective.
  PetscErrorCode Solve(Vec u, Vec v) const;

 private:
  /// add(row, col, value) for every entry of K + K_c + mass_coefficient · M (owned rows; K_c this rank's cells').
  using EntryAdder = std::function<PetscErrorCode(PetscInt, PetscInt, double)>;
  PetscErrorCode AddLinearizedStiffness(double mass_coefficient, const EntryAdder& add) const;
  /// The constrained dofs (global) and their prescribed amplitudes.
  PetscErrorCode Constraints(std::vector<PetscInt>* dofs, std::vector<double>* values) const;
  PetscErrorCode Assemble(double omega, Mat* Z, Vec* rhs) const;
  /// K + K_c + ω² M, constrained rows and columns identity: the Krylov solve's preconditioner.
  PetscErrorCode AssemblePreconditioner(double omega, Mat* P) const;
  /// The wave nodes' positions as a global vector (block size = dimension).
  PetscErrorCode NodePositionVector(Vec* coordinates) const;
  /// Z U = rhs by -wave_harmonic_solver.
  PetscErrorCode SolveSystem(double omega, Mat Z, Vec rhs, Vec U) const;

  HarmonicOperator op_;
};

}  // namespace vibrotherm::wave
