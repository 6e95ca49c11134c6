// What a run writes while it steps, and when: probes.csv, energy.csv,
// crack_state.csv, fields.h5 (+ fields_<grid>.xmf), camera.h5 (HeatCamera), the progress
// line and the temperature extremes for the summary (probes and the whole field). The recording schedule (-probe_every,
// -energy_every, -crack_state_every, -output_times) lives here; the solvers are
// read only through their getters and the crack interface's records. The recorder
// knows solvers and rows, not the run's components (run/recording.hpp fills rows
// from them): observation sits below the run.
#pragma once

#include <memory>
#include <vector>

#include "vibrotherm/coupling/observe/recording_options.hpp"
#include "vibrotherm/coupling/observe/field_peak.hpp"
#include "vibrotherm/coupling/observe/source_power.hpp"
#include "vibrotherm/coupling/observe/wave_energy_row.hpp"
#include "vibrotherm/coupling/observe/heat_camera.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/io/crack_state_log.hpp"
#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/store/checkpoint.hpp"
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
  /// resume: continue the files of the interrupted run whose checkpoint it is (restart).
  PetscErrorCode Open(const RecordingOptions& options, const std::string& dir, const fe::LagrangeSpace& probe_space,
                      interface::CrackInterface* crack, const std::vector<double>& crack_probe_xy,
                      io::RunSummary* summary, const store::Checkpoint* resume = nullptr);
  /// Checkpoints (recorder_state.cpp): file lengths, what the summary has
  /// gathered so far, the outputs written; and back, replaying the field
  /// outputs' index (restore after the components). Collective.
  PetscErrorCode Save(store::Checkpoint& checkpoint) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const wave::WaveSolver* waves, const heat::HeatSolver* heat);
  /// The run stops for a restart: the files stay as .partial, as the checkpoint describes them.
  void Keep();
  /// The source's power per period from the energy rows (source_power.csv, summary.json source_power):
  /// for a run with waves, after Open. window: the periods of a steady stretch it reports. Collective.
  PetscErrorCode MeterSource(const wave::SourceTimeFunction& signal, PetscInt window,
                             const store::Checkpoint* resume = nullptr);
  /// At t = 0 and after every coupling interval while the waves run (or are continued): the wave
  /// columns of an energy row at the interval's end (the source's power per period).
  void OnInterval(const io::EnergyRow& row) { source_power_.OnEnergyRow(row); }
  /// After every accepted wave step: probe rows (held), energy rows (without heat), crack state.
  PetscErrorCode OnWaveStep(const wave::WaveSolver& w, bool energy_rows);
  /// Appends an energy row (wave and heat columns filled by the caller); stops an unstable run.
  PetscErrorCode RecordEnergy(const io::EnergyRow& row);
  /// The probes' temperatures since the last call (HeatComponent::ProbeSeries: at every
  /// held row while the waves run, else one sample at the heat's time): writes the
  /// held wave rows with them, or temperature rows; keeps the probes' peaks.
  PetscErrorCode RecordTemperature(const io::TemperatureSeries& series, double T0, bool waves_running);
  /// The heat field's views: its peak (always) and the IR camera (null: none), which writes into dir. Collective.
  /// resume: the camera's file is reopened by Restore, not created.
  PetscErrorCode OpenHeatViews(const heat::HeatSolver& heat, HeatCamera* camera, const std::string& dir,
                               bool resume = false);
  /// After every heat step and at t = 0: the field peak and the camera's pixels. Collective.
  PetscErrorCode OnHeatStep(const heat::HeatSolver& heat);
  /// Where the heat running alone stops next after t: an output time or a camera window boundary (or final).
  double NextHeatStop(double t, double final_time) const;
  /// Writes the held probe rows without temperature.
  void FlushProbes() { probes_.Flush(nullptr); }
  /// Fields at output times: whether output k is due at time t.
  bool OutputDue(double t) const;
  PetscErrorCode WriteFields(double t, const wave::WaveSolver* waves, const heat::HeatSolver* heat);
  /// The waves (and the crack interface) are gone; `last` holds their final energy columns.
  void StopWaves(const io::EnergyRow& last) {
    crack_ = nullptr;
    waves_at_stop_ = last;
    source_power_.Stop();
  }
  const io::EnergyRow& waves_at_stop() const { return waves_at_stop_; }
  PetscErrorCode Finish(io::RunSummary* summary);
  io::Progress& progress() { return progress_; }

 private:
  PetscErrorCode RecordCrack(const wave::WaveSolver& w);
  /// The "cracks" grid of the fields: each contact cell drawn as its tributary part of the crack.
  PetscErrorCode AddCrackCells();
  /// The "cracks" grid's cell fields (contact_state, friction power, dissipated energy) at output k.
  PetscErrorCode WriteCrackFields(int k, double t);

  const RecordingOptions* options_ = nullptr;
  io::RunSummary* summary_ = nullptr;
  io::PointProbes probes_;
  io::EnergyLog energy_;
  MPI_Comm comm_ = MPI_COMM_NULL;  ///< the probes' (and waves') communicator
  io::CrackStateLog crack_state_;
  SourcePowerMeter source_power_;
  io::Progress progress_;
  io::FieldFile fields_;
  FieldPeak field_peak_;
  bool heat_views_ = false;
  HeatCamera* camera_ = nullptr;
  interface::CrackInterface* crack_ = nullptr;
  std::vector<PetscInt> crack_probe_cells_;  ///< owned cell per crack probe (-1 elsewhere)
  std::vector<double> crack_probe_xy_;
  std::vector<double> last_T_;  ///< the probes' temperatures at the last time recorded
  io::EnergyRow waves_at_stop_;
  bool replaying_ = false;
  std::string dir_;
  std::vector<double> written_times_;  ///< time of each field output written  ///< Restore is indexing the outputs written before the checkpoint
  std::size_t next_output_ = 0;
  int outputs_written_ = 0;
};

}  // namespace vibrotherm::coupling
