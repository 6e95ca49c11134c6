#include "vibrotherm/coupling/observe/recorder.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/heat/heat_probes.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {

PetscErrorCode Recorder::Open(const RecordingOptions& options, const std::string& dir,
                              const fe::LagrangeSpace& probe_space, interface::CrackInterface* crack,
                              const std::vector<double>& crack_probe_xy, io::RunSummary* summary,
                              const store::Checkpoint* resume) {
  PetscFunctionBeginUser;
  options_ = &options;
  summary_ = summary;
  dir_ = dir;
  crack_ = crack;
  crack_probe_xy_ = crack_probe_xy;
  MPI_Comm comm = PetscObjectComm((PetscObject)probe_space.dm());
  comm_ = comm;
  std::vector<double> bytes = {-1, -1, -1, 0};  // probes, energy, crack state; fields written before
  if (resume) PetscCall(resume->GetShared("recorder/bytes", &bytes, 4));
  PetscCall(probes_.Setup(probe_space, options.probe_points, dir + "/probes.csv", static_cast<long long>(bytes[0])));
  PetscCall(energy_.Open(comm, dir + "/energy.csv", static_cast<long long>(bytes[1])));
  for (std::size_t p = 0; p < probes_.count(); ++p)
    summary->probe_labels[static_cast<int>(p)] =
        "point (" + std::to_string(probes_.points()[p][0]) + ", " + std::to_string(probes_.points()[p][1]) +
        (probe_space.dim() == 3 ? ", " + std::to_string(probes_.points()[p][2]) : std::string()) + ")";
  for (std::size_t p = 0; p < options.crack_probes.size(); ++p)
    summary->probe_labels[static_cast<int>(probes_.count() + p)] =
        "crack " + std::to_string(options.crack_probe_crack) + " at xi = " + std::to_string(options.crack_probes[p]);
  if (crack_) {
    for (double s : options.crack_probes) {
      PetscInt cell;
      PetscCall(crack_->NearestCell(options.crack_probe_crack - 1, s, &cell));
      crack_probe_cells_.push_back(cell);
    }
    if (options.crack_state_every > 0)
      PetscCall(crack_state_.Open(comm, dir + "/crack_state.csv", static_cast<long long>(bytes[2])));
  }
  if (!options.output_times.empty()) {
    // Outputs before the checkpoint are kept on the same partition (the grids' vertex numbering is the partition's).
    const bool append = resume && bytes[3] > 0 && resume->same_ranks();
    if (resume && bytes[3] > 0 && !append)
      PetscCall(PetscPrintf(comm, "vibrotherm: warning: -restart on %d ranks instead of %d: the %d field outputs before the "
                                  "checkpoint are not carried over into fields.h5\n",
                            static_cast<int>(summary->mesh.ranks), resume->writer_ranks(), static_cast<int>(bytes[3])));
    PetscCall(fields_.Open(comm, dir + "/fields.h5", io::XdmfLayout::kSeriesPerGrid, "time", append));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::MeterSource(const wave::SourceTimeFunction& signal, PetscInt window,
                                     const store::Checkpoint* resume) {
  PetscFunctionBeginUser;
  PetscCall(source_power_.Open(comm_, signal, window, dir_ + "/source_power.csv", resume));
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::RecordCrack(const wave::WaveSolver& w) {
  PetscFunctionBeginUser;
  if (!crack_) PetscFunctionReturn(0);
  MPI_Comm comm = PetscObjectComm((PetscObject)w.space().dm());
  if (!crack_probe_cells_.empty() && w.steps() % options_->probe_every == 0) {
    std::vector<PetscInt> mine;
    std::vector<long> slots;
    for (std::size_t p = 0; p < crack_probe_cells_.size(); ++p)
      if (crack_probe_cells_[p] >= 0) mine.push_back(crack_probe_cells_[p]), slots.push_back(static_cast<long>(p));
    Vec u, v;
    std::vector<interface::CrackCellRecord> records, all;
    PetscCall(w.GetFields(&u, &v));
    PetscCall(crack_->Records(mine, u, &records));
    PetscCall(w.RestoreFields(&u, &v));
    for (std::size_t k = 0; k < records.size(); ++k) records[k].slot = slots[k];
    PetscCall(interface::GatherCrackRecords(comm, records, &all));
    for (const interface::CrackCellRecord& r : all)
      probes_.RecordCrack(w.time(), probes_.count() + static_cast<std::size_t>(r.slot), r);
  }
  if (options_->crack_state_every > 0 && w.steps() % options_->crack_state_every == 0) {
    std::vector<PetscInt> every(crack_->cells().size());
    for (std::size_t i = 0; i < every.size(); ++i) every[i] = static_cast<PetscInt>(i);
    std::vector<interface::CrackCellRecord> records, all;
    PetscCall(crack_->Records(every, nullptr, &records));
    PetscCall(interface::GatherCrackRecords(comm, records, &all));
    crack_state_.Record(w.time(), all);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::RecordEnergy(const io::EnergyRow& row) {
  PetscFunctionBeginUser;
  double error;
  PetscCall(energy_.Record(row, &error));
  // A budget off by half the source's work is no rounding: the step is unstable
  // (a local-time-stepping resonance grows slowly, never to inf: stop it here).
  PetscCheck(std::abs(error) < 0.5, comm_, PETSC_ERR_NOT_CONVERGED,
             "the wave energy budget is off by %.3g of the source's work at t = %g s: the wave step is unstable (with "
             "-wave_lts on: lower -wave_lts_cfl; else lower -wave_cfl)",
             error, row.t);
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::OnWaveStep(const wave::WaveSolver& w, bool energy_rows) {
  PetscFunctionBeginUser;
  if (w.steps() % options_->probe_every == 0) {
    Vec u, v;
    PetscCall(w.GetFields(&u, &v));
    PetscCall(probes_.Record(w.time(), u, v));
    PetscCall(w.RestoreFields(&u, &v));
  }
  if (energy_rows && w.steps() % options_->energy_every == 0) {
    io::EnergyRow row;
    PetscCall(WaveEnergyRow(w, &row));
    PetscCall(RecordEnergy(row));
  }
  PetscCall(RecordCrack(w));
  PetscCall(progress_.Update(w.time(), w.steps()));
  PetscFunctionReturn(0);
}


PetscErrorCode Recorder::RecordTemperature(const io::TemperatureSeries& series, double T0, bool waves_running) {
  PetscFunctionBeginUser;
  if (series.t.empty()) PetscFunctionReturn(0);
  last_T_ = series.T.back();
  for (const std::vector<double>& T : series.T)
    for (std::size_t p = 0; p < T.size(); ++p) {
      double& peak = summary_->probe_max_temperature_rise[static_cast<int>(p)];
      peak = std::max(peak, T[p] - T0);
    }
  if (waves_running) {
    probes_.Flush(&series);
  } else {
    const std::size_t n = probes_.count();
    for (std::size_t p = 0; p < last_T_.size(); ++p) {
      const std::array<double, 3> x =
          p < n ? probes_.points()[p]
                : std::array<double, 3>{crack_probe_xy_[2 * (p - n)], crack_probe_xy_[2 * (p - n) + 1], 0.0};
      probes_.WriteTemperature(series.t.back(), p, x, last_T_[p]);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::OpenHeatViews(const heat::HeatSolver& heat, HeatCamera* camera, const std::string& dir,
                                       bool resume) {
  PetscFunctionBeginUser;
  PetscCall(field_peak_.Setup(heat.space()));
  heat_views_ = true;
  camera_ = camera;
  if (camera_ && !resume) PetscCall(camera_->Open(dir));
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::OnHeatStep(const heat::HeatSolver& heat) {
  PetscFunctionBeginUser;
  PetscCall(field_peak_.Update(heat));
  if (camera_) PetscCall(camera_->Sample(heat));
  PetscFunctionReturn(0);
}

double Recorder::NextHeatStop(double t, double final_time) const {
  double stop = final_time;
  for (double output : options_->output_times)
    if (output > t * (1 + 1e-12)) {
      stop = std::min(stop, output);
      break;
    }
  if (camera_) stop = std::min(stop, camera_->NextBoundary(t));
  return stop;
}

bool Recorder::OutputDue(double t) const {
  return next_output_ < options_->output_times.size() && t >= options_->output_times[next_output_] * (1 - 1e-12);
}

PetscErrorCode Recorder::WriteFields(double t, const wave::WaveSolver* w, const heat::HeatSolver* heat) {
  PetscFunctionBeginUser;
  const int k = outputs_written_;
  if (heat) {
    if (!fields_.has_grid("heat")) PetscCall(fields_.AddMesh("heat", heat->space()));
    Vec T;
    PetscCall(heat::TemperatureField(*heat, &T));
    PetscCall(fields_.WriteField("heat", "temperature", "K", T, k, t));
    // The rise is what changes (µK on T0 ≈ 293 K): a colour bar of T reads T0 at every tick.
    PetscCall(VecShift(T, -heat->material().T0));
    PetscCall(fields_.WriteField("heat", "temperature_rise", "K", T, k, t));
    PetscCall(VecDestroy(&T));
    std::map<int, double> rises;
    for (std::size_t p = 0; p < last_T_.size(); ++p) rises[static_cast<int>(p)] = last_T_[p] - heat->material().T0;
    if (!replaying_) summary_->output_temperature_rise.push_back({t, rises});
  }
  if (w) {
    if (!fields_.has_grid("wave")) PetscCall(fields_.AddMesh("wave", w->space()));
    Vec u, v;
    PetscCall(w->GetFields(&u, &v));
    PetscCall(fields_.WriteField("wave", "displacement", "m", u, k, t));
    PetscCall(fields_.WriteField("wave", "velocity", "m/s", v, k, t));
    PetscCall(w->RestoreFields(&u, &v));
    if (crack_) PetscCall(WriteCrackFields(k, t));
  }
  ++outputs_written_;
  if (!replaying_) written_times_.push_back(t);
  if (!replaying_) PetscCall(fields_.Flush());
  while (OutputDue(t)) ++next_output_;
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::AddCrackCells() {
  PetscFunctionBeginUser;
  // Each contact cell (a ± node pair) drawn as its tributary part of the crack: in 2D a
  // segment of its length along the crack, in 3D a square of its area in the crack plane
  // (a map of the crack surface; the squares of cells at the front overlap or leave gaps).
  std::vector<double> points;
  const bool planar = crack_->dim() == 2;
  for (const interface::ContactCell& c : crack_->cells()) {
    if (planar) {
      const double h = c.weight / 2;
      points.insert(points.end(), {c.x - h * c.s[0], c.y - h * c.s[1], c.x + h * c.s[0], c.y + h * c.s[1]});
      continue;
    }
    const double h = std::sqrt(c.weight) / 2, x[3] = {c.x, c.y, c.z};
    for (const auto& [a, b] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
      for (int d = 0; d < 3; ++d) points.push_back(x[d] + h * (a * c.s[d] + b * c.s2[d]));
  }
  PetscCall(fields_.AddFreeCells("cracks", planar ? 2 : 4, planar ? 2 : 3, points));
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::WriteCrackFields(int k, double t) {
  PetscFunctionBeginUser;
  const std::vector<interface::ContactCell>& cells = crack_->cells();
  if (!fields_.has_grid("cracks")) PetscCall(AddCrackCells());
  std::vector<PetscInt> owned(cells.size());
  for (std::size_t i = 0; i < owned.size(); ++i) owned[i] = static_cast<PetscInt>(i);
  std::vector<interface::CrackCellRecord> records;
  PetscCall(crack_->Records(owned, nullptr, &records));
  std::vector<double> state, power, dissipated;
  std::vector<std::pair<PetscInt, double>> nodal;
  for (std::size_t i = 0; i < records.size(); ++i) {
    state.push_back(static_cast<double>(static_cast<int>(records[i].state)));
    power.push_back(records[i].power);
    dissipated.push_back(records[i].W);
    nodal.push_back({cells[i].plus, state.back()});
    nodal.push_back({cells[i].minus, state.back()});
  }
  // contact_state: 0 loss, 1 slide, 2 partial, 3 stick (contact::ContactState). The
  // wave-grid copy is a nodal code (−1 off the crack) ParaView interpolates between
  // nodes into states that never were; the cell field on "cracks" is the one to read.
  PetscCall(fields_.WriteCellValues("cracks", "contact_state", "1", state, k, t));
  PetscCall(fields_.WriteCellValues("cracks", "friction_power", "W/m^2", power, k, t));
  PetscCall(fields_.WriteCellValues("cracks", "dissipated_energy", "J/m^2", dissipated, k, t));
  PetscCall(fields_.WriteVertexValues("wave", "contact_state", "1", nodal, -1.0, k, t));
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::Finish(io::RunSummary* summary) {
  PetscFunctionBeginUser;
  PetscCall(probes_.Finish());
  PetscCall(energy_.Finish());
  PetscCall(crack_state_.Finish());
  PetscCall(source_power_.Finish(summary));
  PetscCall(fields_.Finish());
  summary->max_budget_error = energy_.max_budget_error();
  if (heat_views_) field_peak_.Summarise(summary);
  if (camera_) PetscCall(camera_->Finish(summary));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
