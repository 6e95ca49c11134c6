// What a run writes while it steps: probes.csv, energy.csv, crack_state.csv,
// fields.h5/.xmf, the progress line and the temperature extremes for the
// summary. Owned by the driver; knows the solvers only through their getters.
#pragma once

#include <memory>
#include <vector>

#include "vibrotherm/coupling/driver_options.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/io/field_output.hpp"
#include "vibrotherm/io/point_probes.hpp"
#include "vibrotherm/io/progress.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

class Recorder {
 public:
  /// Opens the outputs in dir. `probe_space`: the space probes are located in
  /// (the wave space, or the heat space when no wave runs). crack_probe_xy: the
  /// crack probes' points (temperature is evaluated there).
  PetscErrorCode Open(const DriverOptions& options, const std::string& dir, const fe::LagrangeSpace& probe_space,
                      interface::CrackInterface* crack, const std::vector<double>& crack_probe_xy,
                      io::RunSummary* summary);
  /// After every accepted wave step: probe rows (held), energy rows (without heat), crack state.
  PetscErrorCode OnWaveStep(const wave::WaveSolver& w, bool energy_rows);
  /// Energy columns of the wave solver now (collective).
  PetscErrorCode WaveEnergy(const wave::WaveSolver& w, io::EnergyRow* row) const;
  /// Appends an energy row: the wave columns of `wave_row`, the heat columns of heat (if any).
  PetscErrorCode RecordEnergy(io::EnergyRow row, const heat::HeatSolver* heat);
  /// Temperatures at every probe at the heat solver's time (collective); writes
  /// the held wave rows with temperatures interpolated from the last call.
  PetscErrorCode RecordTemperature(const heat::HeatSolver& heat, bool waves_running);
  /// Writes the held probe rows without temperature.
  void FlushProbes() { probes_.Flush(nullptr); }
  /// Fields at output times: whether output k is due at time t.
  bool OutputDue(double t) const;
  PetscErrorCode WriteFields(double t, const wave::WaveSolver* w, const heat::HeatSolver* heat);
  /// The waves (and the crack interface) are gone: no more wave or crack rows.
  void DetachWaves() { crack_ = nullptr; }
  PetscErrorCode Finish(io::RunSummary* summary);
  io::Progress& progress() { return progress_; }
  double max_budget_error() const { return energy_.max_budget_error(); }

 private:
  PetscErrorCode RecordCrack(const wave::WaveSolver& w);

  const DriverOptions* options_ = nullptr;
  io::RunSummary* summary_ = nullptr;
  io::PointProbes probes_;
  io::EnergyLog energy_;
  io::Progress progress_;
  io::FieldFile fields_;
  std::string dir_;
  interface::CrackInterface* crack_ = nullptr;
  std::vector<PetscInt> crack_probe_cells_;      ///< owned cell per crack probe (-1 elsewhere)
  std::vector<double> crack_probe_xy_;
  std::unique_ptr<io::AtomicFile> crack_state_;  ///< rank 0
  io::TemperatureBracket bracket_;               ///< probe temperatures at the last two heat times
  std::size_t next_output_ = 0;
  int outputs_written_ = 0;
  bool heat_meshes_added_ = false, wave_mesh_added_ = false;
};

}  // namespace vibrotherm::coupling
