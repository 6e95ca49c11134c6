#include "recorder.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {

PetscErrorCode Recorder::Open(const DriverOptions& options, const std::string& dir,
                              const fe::LagrangeSpace& probe_space, interface::CrackInterface* crack,
                              const std::vector<double>& crack_probe_xy, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  options_ = &options;
  summary_ = summary;
  dir_ = dir;
  crack_ = crack;
  crack_probe_xy_ = crack_probe_xy;
  MPI_Comm comm = PetscObjectComm((PetscObject)probe_space.dm());
  PetscCall(probes_.Setup(probe_space, options.probe_points, dir + "/probes.csv"));
  PetscCall(energy_.Open(comm, dir + "/energy.csv"));
  for (std::size_t p = 0; p < probes_.count(); ++p)
    summary->probe_labels[static_cast<int>(p)] =
        "point (" + std::to_string(probes_.points()[p][0]) + ", " + std::to_string(probes_.points()[p][1]) + ")";
  for (std::size_t p = 0; p < options.crack_probes.size(); ++p)
    summary->probe_labels[static_cast<int>(probes_.count() + p)] =
        "crack " + std::to_string(options.crack_probe_crack) + " at xi = " + std::to_string(options.crack_probes[p]);
  if (crack_) {
    for (double s : options.crack_probes) {
      PetscInt cell;
      PetscCall(crack_->NearestCell(options.crack_probe_crack - 1, s, &cell));
      crack_probe_cells_.push_back(cell);
    }
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    if (rank == 0 && options.crack_state_every > 0) {
      VibrothermCallCpp(PETSC_COMM_SELF, crack_state_ = std::make_unique<io::AtomicFile>(dir + "/crack_state.csv"));
      crack_state_->stream() << "t,crack,xi,x,y,a,b,N,T,state,power,W\n";
    }
  }
  if (!options.output_times.empty()) PetscCall(fields_.Open(comm, dir + "/fields.h5"));
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::RecordCrack(const wave::WaveSolver& w) {
  PetscFunctionBeginUser;
  if (!crack_) PetscFunctionReturn(0);
  if (!crack_probe_cells_.empty() && w.steps() % options_->probe_every == 0) {
    Vec u, v;
    std::vector<double> rows;
    PetscCall(w.GetFields(&u, &v));
    PetscCall(crack_->Rows(crack_probe_cells_, u, &rows));
    PetscCall(w.RestoreFields(&u, &v));
    const int K = interface::CrackInterface::kRowValues;
    for (std::size_t p = 0; p < crack_probe_cells_.size() && !rows.empty(); ++p) {
      const double* r = &rows[K * p];
      probes_.RecordCrack(w.time(), probes_.count() + p, r[0], r[1], r[10], r[11], r + 2);
    }
  }
  if (options_->crack_state_every > 0 && w.steps() % options_->crack_state_every == 0) {
    std::vector<double> table;
    PetscCall(crack_->GatherState(&table));
    static const char* states[] = {"loss", "slide", "partial", "stick"};
    if (crack_state_)
      for (std::size_t k = 0; k + 11 <= table.size(); k += 11) {
        std::ostream& out = crack_state_->stream();
        out << w.time();
        for (int j = 0; j < 8; ++j) out << ',' << table[k + j];
        out << ',' << states[static_cast<int>(table[k + 8])] << ',' << table[k + 9] << ',' << table[k + 10] << '\n';
      }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::WaveEnergy(const wave::WaveSolver& w, io::EnergyRow* row) const {
  PetscFunctionBeginUser;
  wave::WaveEnergy e;
  PetscCall(w.Energy(&e));
  row->t = w.time();
  row->work_source = e.work_source;
  row->kinetic = e.kinetic;
  row->strain = e.strain;
  row->radiated = e.radiated;
  row->integrator_correction = e.integrator;
  row->interface_stored = e.interface_stored;
  row->dissipated = e.dissipated;
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::RecordEnergy(io::EnergyRow row, const heat::HeatSolver* heat) {
  PetscFunctionBeginUser;
  if (heat) {
    row.t = heat->time();
    row.heat_deposited = heat->deposited();
    row.heat_boundary_loss = heat->boundary_loss();
    PetscCall(heat->HeatContent(&row.heat_content));
  }
  PetscCall(energy_.Record(row, nullptr));
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
    PetscCall(WaveEnergy(w, &row));
    PetscCall(RecordEnergy(row, nullptr));
  }
  PetscCall(RecordCrack(w));
  progress_.Update(w.time(), w.steps());
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::RecordTemperature(const heat::HeatSolver& heat, bool waves_running) {
  PetscFunctionBeginUser;
  bracket_.t0 = bracket_.t1;
  bracket_.T0 = bracket_.T1;
  bracket_.t1 = heat.time();
  PetscCall(heat.ProbeTemperatures(&bracket_.T1));
  if (bracket_.T0.empty()) bracket_.T0 = bracket_.T1;
  const double T0 = heat.material().T0;
  for (std::size_t p = 0; p < bracket_.T1.size(); ++p) {
    double& peak = summary_->probe_max_temperature_rise[static_cast<int>(p)];
    peak = std::max(peak, bracket_.T1[p] - T0);
  }
  if (waves_running) {
    probes_.Flush(&bracket_);
  } else {
    const std::size_t n = probes_.count();
    for (std::size_t p = 0; p < bracket_.T1.size(); ++p) {
      const double x = p < n ? probes_.points()[p][0] : crack_probe_xy_[2 * (p - n)];
      const double y = p < n ? probes_.points()[p][1] : crack_probe_xy_[2 * (p - n) + 1];
      probes_.WriteTemperature(heat.time(), p, x, y, bracket_.T1[p]);
    }
  }
  PetscFunctionReturn(0);
}

bool Recorder::OutputDue(double t) const {
  return next_output_ < options_->output_times.size() && t >= options_->output_times[next_output_] * (1 - 1e-12);
}

PetscErrorCode Recorder::WriteFields(double t, const wave::WaveSolver* w, const heat::HeatSolver* heat) {
  PetscFunctionBeginUser;
  const int k = outputs_written_;
  if (heat) {
    if (!heat_meshes_added_) PetscCall(fields_.AddMesh("heat", heat->space()));
    heat_meshes_added_ = true;
    Vec T;
    PetscCall(heat->Temperature(&T));
    PetscCall(fields_.WriteField("heat", "temperature", T, k, t));
    PetscCall(VecDestroy(&T));
    std::map<int, double> rises;
    for (std::size_t p = 0; p < bracket_.T1.size(); ++p)
      rises[static_cast<int>(p)] = bracket_.T1[p] - heat->material().T0;
    summary_->output_temperature_rise.push_back({t, rises});
  }
  if (w) {
    if (!wave_mesh_added_) PetscCall(fields_.AddMesh("wave", w->space()));
    wave_mesh_added_ = true;
    Vec u, v;
    PetscCall(w->GetFields(&u, &v));
    PetscCall(fields_.WriteField("wave", "displacement", u, k, t));
    PetscCall(fields_.WriteField("wave", "velocity", v, k, t));
    PetscCall(w->RestoreFields(&u, &v));
    if (crack_) {
      std::vector<std::pair<PetscInt, double>> states;
      for (std::size_t i = 0; i < crack_->cells().size(); ++i) {
        states.push_back({crack_->cells()[i].plus, crack_->state_code(i)});
        states.push_back({crack_->cells()[i].minus, crack_->state_code(i)});
      }
      PetscCall(fields_.WriteVertexValues("wave", "contact_state", states, -1.0, k, t));
    }
  }
  ++outputs_written_;
  while (OutputDue(t)) ++next_output_;
  PetscFunctionReturn(0);
}

PetscErrorCode Recorder::Finish(io::RunSummary* summary) {
  PetscFunctionBeginUser;
  PetscCall(probes_.Finish());
  PetscCall(energy_.Finish());
  if (crack_state_) VibrothermCallCpp(PETSC_COMM_SELF, crack_state_->commit());
  PetscCall(fields_.Finish());
  summary->max_budget_error = energy_.max_budget_error();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
