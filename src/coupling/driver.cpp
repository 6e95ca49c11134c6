#include "vibrotherm/coupling/driver.hpp"

#include "vibrotherm/io/energy_log.hpp"
#include "vibrotherm/io/point_probes.hpp"
#include "vibrotherm/io/progress.hpp"
#include <array>
#include <cmath>

#include "vibrotherm/interface/contact_options.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {

PetscErrorCode ReadDriverOptions(MPI_Comm comm, DriverOptions* o) {
  PetscFunctionBeginUser;
  PetscReal points[256], fractions[64];
  PetscInt npoints = 256, nfractions = 64;
  PetscBool has_points = PETSC_FALSE, has_fractions = PETSC_FALSE;
  PetscOptionsBegin(comm, nullptr, "Run control and recording", nullptr);
  PetscCall(PetscOptionsReal("-final_time", "Simulated time [s] (default: the source duration)", nullptr,
                             o->final_time, &o->final_time, nullptr));
  PetscCall(PetscOptionsInt("-energy_every", "Steps between rows of energy.csv", nullptr, o->energy_every,
                            &o->energy_every, nullptr));
  PetscCall(PetscOptionsInt("-probe_every", "Steps between rows of probes.csv", nullptr, o->probe_every,
                            &o->probe_every, nullptr));
  PetscCall(PetscOptionsRealArray("-probe_points", "Probe points x1,y1,x2,y2,... [m]", nullptr, points, &npoints,
                                  &has_points));
  PetscCall(PetscOptionsRealArray("-crack_probe", "Crack probes: fractions of the crack length (0.5: centre)", nullptr,
                                  fractions, &nfractions, &has_fractions));
  PetscCall(PetscOptionsInt("-crack_probe_crack", "Crack of the crack probes (1-based)", nullptr, o->crack_probe_crack,
                            &o->crack_probe_crack, nullptr));
  PetscCall(PetscOptionsInt("-crack_state_every", "Steps between crack_state.csv records (0: none)", nullptr,
                            o->crack_state_every, &o->crack_state_every, nullptr));
  PetscOptionsEnd();
  o->crack_probes.assign(fractions, fractions + (has_fractions ? nfractions : 0));
  for (double s : o->crack_probes)
    PetscCheck(s >= 0.0 && s <= 1.0, comm, PETSC_ERR_USER_INPUT, "-crack_probe: fractions must be in [0, 1], got %g", s);
  PetscCheck(o->crack_state_every >= 0, comm, PETSC_ERR_USER_INPUT, "-crack_state_every must be >= 0");
  PetscCheck(o->energy_every >= 1, comm, PETSC_ERR_USER_INPUT, "-energy_every must be >= 1");
  PetscCheck(o->probe_every >= 1, comm, PETSC_ERR_USER_INPUT, "-probe_every must be >= 1");
  o->probe_points.assign(points, points + (has_points ? npoints : 0));
  PetscFunctionReturn(0);
}

namespace {

struct WaveRecorder {
  const DriverOptions* options;
  io::PointProbes probes;
  io::EnergyLog energy;
  io::Progress progress;
  interface::CrackInterface* crack = nullptr;
  std::vector<PetscInt> crack_probe_cells;     ///< owned cell per crack probe (-1 elsewhere)
  std::unique_ptr<io::AtomicFile> crack_state;  ///< rank 0

  PetscErrorCode RecordCrack(const wave::WaveSolver& w) {
    PetscFunctionBeginUser;
    if (!crack) PetscFunctionReturn(0);
    if (!crack_probe_cells.empty() && w.steps() % options->probe_every == 0) {
      Vec u, v;
      std::vector<double> rows;
      PetscCall(w.GetFields(&u, &v));
      PetscCall(crack->Rows(crack_probe_cells, u, &rows));
      PetscCall(w.RestoreFields(&u, &v));
      const int K = interface::CrackInterface::kRowValues;
      for (std::size_t p = 0; p < crack_probe_cells.size() && !rows.empty(); ++p) {
        const double* r = &rows[K * p];
        probes.WriteCrackRow(w.time(), probes.count() + p, r[0], r[1], r[10], r[11], r + 2);
      }
    }
    if (options->crack_state_every > 0 && w.steps() % options->crack_state_every == 0) {
      std::vector<double> table;
      PetscCall(crack->GatherState(&table));
      static const char* states[] = {"loss", "slide", "partial", "stick"};
      if (crack_state)
        for (std::size_t k = 0; k + 11 <= table.size(); k += 11) {
          std::ostream& out = crack_state->stream();
          out << w.time();
          for (int j = 0; j < 8; ++j) out << ',' << table[k + j];
          out << ',' << states[static_cast<int>(table[k + 8])] << ',' << table[k + 9] << ',' << table[k + 10] << '\n';
        }
    }
    PetscFunctionReturn(0);
  }

  PetscErrorCode RecordEnergy(const wave::WaveSolver& w) {
    PetscFunctionBeginUser;
    wave::WaveEnergy e;
    PetscCall(w.Energy(&e));
    io::EnergyRow row;
    row.t = w.time();
    row.work_source = e.work_source;
    row.kinetic = e.kinetic;
    row.strain = e.strain;
    row.radiated = e.radiated;
    row.integrator_correction = e.integrator;
    row.interface_stored = e.interface_stored;
    row.dissipated = e.dissipated;
    PetscCall(energy.Record(row, nullptr));
    PetscFunctionReturn(0);
  }

  PetscErrorCode OnStep(const wave::WaveSolver& w) {
    PetscFunctionBeginUser;
    if (w.steps() % options->probe_every == 0) {
      Vec u, v;
      PetscCall(w.GetFields(&u, &v));
      PetscCall(probes.Record(w.time(), u, v));
      PetscCall(w.RestoreFields(&u, &v));
    }
    if (w.steps() % options->energy_every == 0) PetscCall(RecordEnergy(w));
    PetscCall(RecordCrack(w));
    progress.Update(w.time(), w.steps());
    PetscFunctionReturn(0);
  }
};

}  // namespace

PetscErrorCode Simulation::Setup(const mesh::Specimen& specimen, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  PetscLogStage setup_stage;
  PetscCall(PetscLogStageRegister("Wave setup", &setup_stage));
  PetscCall(PetscLogStageRegister("Wave steps", &steps_stage_));
  PetscCall(wave::ReadElasticMaterial(comm, &material_));
  PetscCall(wave::ReadExcitation(comm, &excitation_));
  PetscCall(wave::ReadWaveOptions(comm, &wave_options_));
  PetscCall(ReadDriverOptions(comm, &options_));
  final_time_ = options_.final_time > 0.0 ? options_.final_time : excitation_.signal.duration;
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

PetscErrorCode Simulation::Run(const std::string& dir, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = *wave_;
  MPI_Comm comm = PetscObjectComm((PetscObject)solver.space().dm());
  WaveRecorder recorder{&options_, {}, {}, {}, nullptr, {}, nullptr};
  PetscCall(recorder.probes.Setup(solver.space(), options_.probe_points, dir + "/probes.csv"));
  PetscCall(recorder.energy.Open(comm, dir + "/energy.csv"));
  if (crack_) {
    recorder.crack = crack_.get();
    for (double s : options_.crack_probes) {
      PetscInt cell;
      PetscCall(crack_->NearestCell(options_.crack_probe_crack - 1, s, &cell));
      recorder.crack_probe_cells.push_back(cell);
    }
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    if (rank == 0 && options_.crack_state_every > 0) {
      VibrothermCallCpp(PETSC_COMM_SELF, recorder.crack_state = std::make_unique<io::AtomicFile>(dir + "/crack_state.csv"));
      recorder.crack_state->stream() << "t,crack,xi,x,y,a,b,N,T,state,power,W\n";
    }
  }
  PetscCall(PetscPrintf(comm,
                        "Waves: %" PetscInt_FMT " dofs (degree %" PetscInt_FMT "), dt = %.4g s (limit %.4g s, "
                        "omega_max %.4g rad/s), %.0f steps to t = %g s\n",
                        solver.dofs(), wave_options_.degree, solver.dt(), solver.stable_dt(), solver.omega_max(),
                        std::ceil(final_time_ / solver.dt()), final_time_));
  solver.on_step = [&recorder](const wave::WaveSolver& w) { return recorder.OnStep(w); };
  recorder.progress.Start(comm, "wave", 0.0, final_time_);
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(steps_stage_));
  PetscCall(recorder.RecordEnergy(solver));  // t = 0
  PetscCall(solver.AdvanceTo(final_time_));
  PetscCall(PetscLogStagePop());
  summary->stages["wave_steps"] = MPI_Wtime() - t0;
  recorder.progress.Done(solver.time(), solver.steps());
  if (solver.steps() % options_.energy_every != 0) PetscCall(recorder.RecordEnergy(solver));
  PetscCall(recorder.probes.Finish());
  PetscCall(recorder.energy.Finish());
  if (recorder.crack_state) VibrothermCallCpp(PETSC_COMM_SELF, recorder.crack_state->commit());
  solver.on_step = nullptr;

  summary->physics_ran.push_back("wave");
  if (crack_) summary->physics_ran.push_back("contact");
  summary->wave_dt_reductions = solver.dt_reductions();
  if (crack_) {
    double stored, seconds = crack_->seconds();
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &seconds, 1, MPI_DOUBLE, MPI_MAX, comm));
    summary->stages["contact"] = seconds;  // part of wave_steps
    PetscCall(crack_->Energies(&stored, &summary->dissipated_energy));
    PetscCall(crack_->MaxFrictionExcess(&summary->max_friction_excess));
  }
  summary->dofs_wave = solver.dofs();
  summary->steps_wave = solver.steps();
  summary->max_budget_error = recorder.energy.max_budget_error();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
