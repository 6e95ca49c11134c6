#include "vibrotherm/coupling/driver.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "recorder.hpp"
#include "vibrotherm/interface/contact_options.hpp"
#include "vibrotherm/mesh/crack_line.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {

Simulation::Simulation() = default;
Simulation::~Simulation() = default;

PetscErrorCode Simulation::Setup(const mesh::Specimen& specimen, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  PetscCall(wave::ReadElasticMaterial(comm, &material_));
  PetscCall(wave::ReadExcitation(comm, &excitation_));
  PetscCall(wave::ReadWaveOptions(comm, &wave_options_));
  PetscCall(ReadDriverOptions(comm, &options_));
  final_time_ = options_.final_time > 0.0 ? options_.final_time : excitation_.signal.duration;
  if (options_.couple_dt <= 0.0) options_.couple_dt = 1.0 / (8.0 * excitation_.signal.frequency);
  PetscCheck(options_.crack_probes.empty() || !specimen.cracks.empty(), comm, PETSC_ERR_USER_INPUT,
             "-crack_probe needs a crack (-crack_center or crack curves in -mesh_file)");
  PetscCheck(options_.crack_probes.empty() ||
                 (options_.crack_probe_crack >= 1 &&
                  options_.crack_probe_crack <= static_cast<PetscInt>(specimen.cracks.size())),
             comm, PETSC_ERR_USER_INPUT, "-crack_probe_crack %" PetscInt_FMT ": the specimen has %zu crack(s)",
             options_.crack_probe_crack, specimen.cracks.size());
  if (options_.physics != PhysicsChoice::Heat) PetscCall(SetupWaves(specimen, summary));
  const bool heat_needed =
      options_.physics == PhysicsChoice::Heat ||
      (options_.physics == PhysicsChoice::All &&
       (options_.heat == HeatChoice::On || (options_.heat == HeatChoice::Auto && crack_ && crack_->dissipative())));
  if (heat_needed) PetscCall(SetupHeat(specimen, summary));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::SetupWaves(const mesh::Specimen& specimen, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  PetscLogStage setup_stage;
  PetscCall(PetscLogStageRegister("Wave setup", &setup_stage));
  PetscCall(PetscLogStageRegister("Wave steps", &wave_stage_));
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(setup_stage));
  wave_ = std::make_unique<wave::WaveSolver>();
  PetscCall(wave_->Setup(specimen.wave, material_, excitation_, wave_options_));
  // The crack interface exists only when there is a crack whose law transmits tractions.
  contact::ContactParameters contact_params;
  PetscCall(ReadContactOptions(comm, contact_params));
  interface::ApproachProfile a0;
  PetscCall(interface::ReadApproachProfile(comm, &a0));
  if (!specimen.cracks.empty() && contact_params.crack_law != "open") {
    crack_ = std::make_unique<interface::CrackInterface>();
    PetscCall(crack_->Setup(wave_->space(), wave_->mass(), contact_params, a0));
    // Expected largest approach: twice the displacement amplitude the source imposes
    // (for a traction source, the displacement of a plane S wave, A / (ρ c_s ω)).
    const double omega = 2.0 * M_PI * excitation_.signal.frequency;
    const double amplitude = excitation_.type == wave::SourceType::Displacement
                                 ? excitation_.signal.amplitude
                                 : excitation_.signal.amplitude / (material_.density * material_.cs() * omega);
    PetscCall(wave_->SetInterface(crack_.get(), 2.0 * std::abs(amplitude)));
    summary->contact_cells = crack_->global_cells();
  }
  PetscCall(PetscLogStagePop());
  summary->stages["wave_setup"] = MPI_Wtime() - t0;
  // Probe points are input too: check them before anything is written.
  for (std::size_t i = 0; i + 1 < options_.probe_points.size(); i += 2) {
    PetscInt cell;
    std::array<double, 2> ref;
    PetscCall(wave_->space().Locate(options_.probe_points[i], options_.probe_points[i + 1], &cell, &ref));
    PetscInt found = cell >= 0, anywhere;
    PetscCallMPI(MPI_Allreduce(&found, &anywhere, 1, MPIU_INT, MPI_MAX, comm));
    PetscCheck(anywhere, comm, PETSC_ERR_USER_INPUT, "-probe_points: point %zu (%g, %g) lies outside the specimen",
               i / 2 + 1, options_.probe_points[i], options_.probe_points[i + 1]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::SetupHeat(const mesh::Specimen& specimen, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.heat);
  PetscLogStage setup_stage;
  PetscCall(PetscLogStageRegister("Heat setup", &setup_stage));
  PetscCall(PetscLogStageRegister("Heat steps", &heat_stage_));
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(setup_stage));
  heat::HeatMaterial material;
  PetscCall(heat::ReadHeatMaterial(comm, material_.density, &material));
  heat_ = std::make_unique<heat::HeatSolver>();
  PetscCall(heat_->Setup(specimen.heat, material));
  summary->dofs_heat = heat_->dofs();
  if (options_.physics == PhysicsChoice::Heat) {
    PetscCheck(!specimen.cracks.empty() || options_.heat_crack_power == 0.0, comm, PETSC_ERR_USER_INPUT,
               "-heat_crack_power needs a crack (-crack_center or crack curves in -mesh_file)");
    PetscInt facets = 0;
    for (const mesh::CrackSummary& c : summary->mesh.cracks) facets += c.facets;
    PetscCall(heat_->SetCrackPower(std::vector<double>(facets, options_.heat_crack_power)));
  } else if (crack_) {
    // Point sources at every contact cell, in the order of an Allgatherv over ranks.
    const auto& cells = crack_->cells();
    PetscMPIInt size, n = static_cast<PetscMPIInt>(cells.size());
    PetscCallMPI(MPI_Comm_size(comm, &size));
    cell_counts_.assign(size, 0);
    cell_displs_.assign(size, 0);
    PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, cell_counts_.data(), 1, MPI_INT, comm));
    for (int r = 1; r < size; ++r) cell_displs_[r] = cell_displs_[r - 1] + cell_counts_[r - 1];
    const int total = cell_displs_[size - 1] + cell_counts_[size - 1];
    std::vector<double> mine, xy(2 * total), w;
    for (const auto& c : cells) {
      mine.insert(mine.end(), {c.x, c.y});
      w.push_back(c.weight);
    }
    std::vector<int> counts2(size), displs2(size);
    for (int r = 0; r < size; ++r) counts2[r] = 2 * cell_counts_[r], displs2[r] = 2 * cell_displs_[r];
    PetscCallMPI(MPI_Allgatherv(mine.data(), 2 * n, MPI_DOUBLE, xy.data(), counts2.data(), displs2.data(), MPI_DOUBLE,
                                comm));
    cell_weights_.resize(total);
    PetscCallMPI(MPI_Allgatherv(w.data(), n, MPI_DOUBLE, cell_weights_.data(), cell_counts_.data(),
                                cell_displs_.data(), MPI_DOUBLE, comm));
    cell_energy_.assign(total, 0.0);
    PetscCall(heat_->SetSourcePoints(xy));
  }
  // Temperature probes: the point probes, then the crack probes (on the crack line).
  if (!options_.crack_probes.empty()) {
    mesh::CrackLine line;
    PetscCall(line.Setup(specimen.heat, options_.crack_probe_crack - 1));
    for (double s : options_.crack_probes) {
      const auto p = line.At(s);
      crack_probe_xy_.insert(crack_probe_xy_.end(), {p[0], p[1]});
    }
  }
  std::vector<double> probes = options_.probe_points;
  probes.insert(probes.end(), crack_probe_xy_.begin(), crack_probe_xy_.end());
  PetscCall(heat_->SetProbePoints(probes));
  PetscCall(PetscLogStagePop());
  summary->stages["heat_setup"] = MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Run(const std::string& dir, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  Recorder recorder;
  const fe::LagrangeSpace& probe_space = wave_ ? wave_->space() : heat_->space();
  PetscCall(recorder.Open(options_, dir, probe_space, crack_.get(), crack_probe_xy_, summary));
  if (heat_) PetscCall(recorder.RecordTemperature(*heat_, wave_ != nullptr));  // t = 0
  if (wave_) PetscCall(RunWaves(recorder, summary));
  if (heat_ && heat_->time() < final_time_ * (1 - 1e-12)) PetscCall(RunHeatAlone(recorder, summary));
  if (heat_) {
    summary->physics_ran.push_back("heat");
    summary->physics_time["heat"] = {0.0, heat_->time()};
    summary->steps_heat = heat_->steps();
    summary->heat_deposited = heat_->deposited();
    summary->heat_boundary_loss = heat_->boundary_loss();
    PetscCall(heat_->HeatContent(&summary->heat_content));
    summary->stages["heat_steps"] = heat_seconds_;
  }
  PetscCall(recorder.Finish(summary));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::RunWaves(Recorder& recorder, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = *wave_;
  MPI_Comm comm = PetscObjectComm((PetscObject)solver.space().dm());
  const PetscInt couple_steps = std::max<PetscInt>(1, std::lround(options_.couple_dt / solver.dt()));
  PetscCall(PetscPrintf(comm,
                        "Waves: %" PetscInt_FMT " dofs (degree %" PetscInt_FMT "), dt = %.4g s (limit %.4g s, "
                        "omega_max %.4g rad/s), up to %.0f steps to t = %g s\n",
                        solver.dofs(), wave_options_.degree, solver.dt(), solver.stable_dt(), solver.omega_max(),
                        std::ceil(final_time_ / solver.dt()), final_time_));
  if (heat_)
    PetscCall(PetscPrintf(comm, "Heat: %" PetscInt_FMT " dofs, coupled every %" PetscInt_FMT " wave steps (%.4g s)\n",
                          heat_->dofs(), couple_steps, couple_steps * solver.dt()));
  const bool heat_rows = heat_ != nullptr;  // with heat, energy rows at exchanges (all columns at one time)
  solver.on_step = [&recorder, heat_rows](const wave::WaveSolver& w) { return recorder.OnWaveStep(w, !heat_rows); };
  recorder.progress().Start(comm, "wave", 0.0, final_time_);
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(wave_stage_));
  io::EnergyRow row;
  PetscCall(recorder.WaveEnergy(solver, &row));
  PetscCall(recorder.RecordEnergy(row, heat_.get()));  // t = 0
  if (recorder.OutputDue(0.0)) PetscCall(recorder.WriteFields(0.0, wave_.get(), heat_.get()));
  bool quiet = false;
  while (solver.time() < final_time_ * (1 - 1e-12) && !quiet) {
    const double t_start = solver.time();
    if (solver.StepsUntil(final_time_) <= couple_steps) PetscCall(solver.AdvanceTo(final_time_));
    else PetscCall(solver.AdvanceSteps(couple_steps));
    const double interval = solver.time() - t_start;
    PetscCall(recorder.WaveEnergy(solver, &row));  // once per interval: energy rows and the quiet test
    if (heat_) {
      PetscCall(Exchange(interval));
      PetscCall(recorder.RecordTemperature(*heat_, true));
      PetscCall(recorder.RecordEnergy(row, heat_.get()));
    } else {
      recorder.FlushProbes();
    }
    if (recorder.OutputDue(solver.time())) PetscCall(recorder.WriteFields(solver.time(), wave_.get(), heat_.get()));
    PetscCall(WavesQuiet(row, &quiet));
  }
  PetscCall(PetscLogStagePop());
  summary->stages["wave_steps"] = MPI_Wtime() - t0 - heat_seconds_;
  recorder.progress().Done(solver.time(), solver.steps());
  PetscCall(StopWaves(recorder, summary));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Exchange(double interval) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(heat_stage_));
  std::vector<double> power(cell_energy_.size(), 0.0);
  if (crack_) {
    const auto& cells = crack_->cells();
    const auto& W = crack_->dissipated_per_area();
    std::vector<double> mine(cells.size()), energy(cell_energy_.size());
    for (std::size_t i = 0; i < cells.size(); ++i) mine[i] = cells[i].weight * W[i];
    PetscCallMPI(MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, energy.data(),
                                cell_counts_.data(), cell_displs_.data(), MPI_DOUBLE,
                                PetscObjectComm((PetscObject)wave_->space().dm())));
    for (std::size_t i = 0; i < energy.size(); ++i) {
      power[i] = (energy[i] - cell_energy_[i]) / interval;
      cell_energy_[i] = energy[i];
    }
    PetscCall(heat_->SetSourcePowers(power));
  }
  PetscCall(heat_->AdvanceInOneStep(wave_->time()));
  PetscCall(PetscLogStagePop());
  heat_seconds_ += MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::WavesQuiet(const io::EnergyRow& e, bool* quiet) {
  PetscFunctionBeginUser;
  *quiet = false;
  if (options_.quiet_fraction <= 0.0) PetscFunctionReturn(0);
  // The mechanical energy left bounds the heat still to come: once it is a small
  // fraction of what has been dissipated, stopping the waves loses at most that fraction.
  const double left = e.kinetic + e.strain + e.interface_stored;
  const double t = wave_->time();
  recent_.push_back({t, left});
  peak_mechanical_ = std::max(peak_mechanical_, left);
  // Over a whole source period: kinetic and strain energy trade places within a cycle.
  const double period = 1.0 / excitation_.signal.frequency;
  while (recent_.size() > 2 && recent_.front().t < t - period) recent_.erase(recent_.begin());
  if (t < excitation_.signal.duration + period) PetscFunctionReturn(0);
  double most = 0.0;
  for (const Sample& s : recent_) most = std::max(most, s.energy);
  const double reference = heat_ && e.dissipated > 0.0 ? e.dissipated : peak_mechanical_;
  *quiet = most <= options_.quiet_fraction * reference;
  mechanical_left_ = most;
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::StopWaves(Recorder& recorder, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = *wave_;
  MPI_Comm comm = PetscObjectComm((PetscObject)solver.space().dm());
  PetscCall(recorder.WaveEnergy(solver, &final_wave_energy_));
  if (!heat_) PetscCall(recorder.RecordEnergy(final_wave_energy_, nullptr));
  recorder.FlushProbes();
  solver.on_step = nullptr;
  summary->physics_ran.push_back("wave");
  summary->physics_time["wave"] = {0.0, solver.time()};
  if (crack_) {
    summary->physics_ran.push_back("contact");
    summary->physics_time["contact"] = {0.0, solver.time()};
    double stored, seconds = crack_->seconds();
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &seconds, 1, MPI_DOUBLE, MPI_MAX, comm));
    summary->stages["contact"] = seconds;  // part of wave_steps
    PetscCall(crack_->Energies(&stored, &summary->dissipated_energy));
    PetscCall(crack_->MaxFrictionExcess(&summary->max_friction_excess));
  }
  summary->wave_dt_reductions = solver.dt_reductions();
  summary->wave_energy_left = mechanical_left_;
  summary->dofs_wave = solver.dofs();
  summary->steps_wave = solver.steps();
  if (solver.time() < final_time_ * (1 - 1e-12))
    PetscCall(PetscPrintf(comm, "Waves quiet at t = %.6g s: wave solver stopped%s\n", solver.time(),
                          heat_ ? ", heat continues alone" : ""));
  // The waves are over: free their solver and the interface (the heat TS carries on alone).
  recorder.DetachWaves();
  crack_.reset();
  wave_.reset();
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::RunHeatAlone(Recorder& recorder, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)heat_->space().dm());
  if (!cell_energy_.empty()) PetscCall(heat_->SetSourcePowers(std::vector<double>(cell_energy_.size(), 0.0)));
  PetscCall(heat_->UseFreeIntegrator());
  const double t_begin = heat_->time();
  const PetscInt steps_before = heat_->steps();
  recorder.progress().Start(comm, "heat", t_begin, final_time_);
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(heat_stage_));
  if (recorder.OutputDue(t_begin)) PetscCall(recorder.WriteFields(t_begin, nullptr, heat_.get()));
  heat_->on_step = [this, &recorder](const heat::HeatSolver& heat) {
    PetscFunctionBeginUser;
    PetscCall(recorder.RecordTemperature(heat, false));
    PetscCall(recorder.RecordEnergy(final_wave_energy_, &heat));
    recorder.progress().Update(heat.time(), heat.steps());
    PetscFunctionReturn(0);
  };
  // One TSSolve per output segment: the adaptor needs the step history a new solve discards.
  while (heat_->time() < final_time_ * (1 - 1e-12)) {
    double stop = final_time_;
    for (double t : options_.output_times)
      if (t > heat_->time() * (1 + 1e-12)) {
        stop = std::min(stop, t);
        break;
      }
    PetscCall(heat_->AdvanceTo(stop));
    if (recorder.OutputDue(heat_->time())) PetscCall(recorder.WriteFields(heat_->time(), nullptr, heat_.get()));
  }
  heat_->on_step = nullptr;
  summary->stages["heat_free"] = MPI_Wtime() - t0;
  summary->steps_heat_free = heat_->steps() - steps_before;
  PetscCall(PetscLogStagePop());
  heat_seconds_ += MPI_Wtime() - t0;
  recorder.progress().Done(heat_->time(), heat_->steps());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
