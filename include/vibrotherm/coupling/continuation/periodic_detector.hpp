// Whether the coupled wave–contact system has reached a periodic state (issue 24).
// Sampled at source-period boundaries within a steady stretch of the source; the
// run repeats with a period of m source periods (m = 1..-periodic_max_multiple,
// the shortest that passes) when each of these is below -periodic_tol:
//   state    the energy of the change of u and of v since m periods back, relative
//            to their own (squared lumped-mass norms: ‖u_k − u_{k−m}‖²_M/‖u_k‖²_M);
//   memory   the change of the contact cells' tractions T and slip offsets b0 since m
//            periods back, squared and summed over the crack (length-weighted),
//            relative to those of T and of b (the memory diagrams' signature);
//   cells    Σ_c w_c |ΔW_c over the last window − over the window before| / Σ_c w_c ΔW_c,
//            windows of -periodic_window × m periods;
//   energies the source's work, the radiated, dissipated and damped energy over the
//            last window against the window before, each relative to itself, and
//            the window's balance: the source's work less the losses, relative to
//            the work (a transient still changes the stored energy);
// Energies and friction by windows: a contact sheds broadband noise, and single
// periods' friction energies differ cell by cell by ~0.5 % in the paper scene
// while the crack's total repeats to 1e-5; a window of 4 periods averages it.
// The largest of these (memory and cells scaled by -periodic_tol / -periodic_tol_cells:
// the contact's cell-by-cell quantities have a noise floor of ~0.5 %) is
// the change of multiple m; summary.json and
// periodic.csv report it (a scene that never becomes periodic says how close it came).
// -periodic_mode mean (a statistically steady state, e.g. a chaotically clapping crack: its
// friction per period scatters by 10-40 %): m = 1, and only what heats, the friction and the
// damping per period over the last two windows, judged as samples of a stationary process:
// the last window's mean known to -periodic_tol (its standard error over the mean), and no
// trend (the two windows' means within 3 standard errors of their difference). The source's
// work per period swings with the stored energy and is not judged (a continuation books it
// as the losses). periodic.csv's `energies` column then holds this change. Its window widens
// for an intermittently clapping crack (periodic_mean.hpp).
#pragma once

#include <petscvec.h>

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/coupling/continuation/periodic_mean.hpp"
#include "vibrotherm/coupling/continuation/periodic_options.hpp"
#include "vibrotherm/coupling/continuation/continued_parts.hpp"
#include "vibrotherm/store/atomic_file.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/io/energy_log.hpp"

namespace vibrotherm::coupling {

class PeriodicDetector {
 public:
  PeriodicDetector() = default;
  PeriodicDetector(const PeriodicDetector&) = delete;
  PeriodicDetector& operator=(const PeriodicDetector&) = delete;
  ~PeriodicDetector();

  /// Writes each sample's changes to `csv` (rank 0; the path's file is kept only by a complete run).
  PetscErrorCode Open(MPI_Comm comm, const PeriodicOptions& options, const std::string& csv);
  /// A sample at a period boundary: *multiple = the shortest m that repeats within
  /// the tolerance, 0 if none (yet). Collective.
  PetscErrorCode Sample(ContinuedWaves& waves, const io::EnergyRow& row, PetscInt* multiple);
  /// Forgets the samples (the source changed, or the waves jumped ahead).
  void Reset();
  /// The drift of the crack's friction: a least-squares line through the dissipated energy of
  /// each stretch of m source periods between the samples; *slope is its rise per source period
  /// relative to the mean, *error the slope's standard error (both 0 with fewer than 4 stretches).
  void FrictionDrift(PetscInt m, double* slope, double* error) const;
  /// Periods compared as one window, recorded and replayed as one: -periodic_window, or in mean mode
  /// that widened (WidenMeanWindow).
  PetscInt window() const { return options_.mean ? mean_window_.window() : options_.window; }
  /// The smallest change of any multiple at the last sample (inf before 2 samples).
  double last_change() const { return last_change_; }
  /// Publishes periodic.csv (a complete run).
  PetscErrorCode Finish();
  /// Rows written so far (checkpoints) and leaving the file for a restart.
  long long bytes() const { return file_ ? file_->bytes() : 0; }
  void Keep() { if (file_) file_->keep(); }
  PetscErrorCode Resume(MPI_Comm comm, const PeriodicOptions& options, const std::string& csv, long long bytes);
  /// The wave solver's lumped mass (the state's norm); before Sample and Restore.
  void Attach(Vec mass) { mass_ = mass; }
  /// Checkpoints (periodic_state.cpp): the samples, u and v keyed by wave dof (`dofs`), the cell
  /// values by contact cell (`cells`); and back.
  PetscErrorCode Save(store::Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& dofs,
                      const std::vector<long long>& cells) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& dofs,
                         const std::vector<long long>& cells);

 private:
  struct Snapshot {
    double t = 0.0;
    Vec u = nullptr, v = nullptr;
    std::vector<double> W, T, b0, b;  ///< per owned contact cell
    io::EnergyRow energy;
  };
  PetscErrorCode Take(ContinuedWaves& waves, const io::EnergyRow& row, Snapshot* s) const;
  /// The change between the last sample and the one m back (state, memory, cells, energies).
  PetscErrorCode Change(std::size_t m, const std::vector<double>& weights, double parts[4]) const;
  /// -periodic_mode mean: the heat's accounts (friction, damping) per period over the last two
  /// windows: the larger of the last window's standard error over its mean and the windows'
  /// difference in units of 3 standard errors (scaled by -periodic_tol); inf before two windows.
  double MeanChange() const;
  /// Mean mode, after each sample: the window widened when the samples keep failing (periodic_mean.hpp).
  PetscErrorCode WidenMeanWindow(bool passed);
  void Free(Snapshot& s) const;

  MPI_Comm comm_ = MPI_COMM_NULL;
  PeriodicOptions options_;
  std::deque<Snapshot> samples_;  ///< newest last; at most 2·max_multiple + 1
  Vec mass_ = nullptr;            ///< the wave solver's lumped mass (not owned)
  double last_change_ = INFINITY;
  MeanWindow mean_window_;  ///< mean mode's window (window())
  std::unique_ptr<store::AtomicFile> file_;  ///< periodic.csv (rank 0)
};

}  // namespace vibrotherm::coupling
