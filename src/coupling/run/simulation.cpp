#include "vibrotherm/coupling/run/simulation.hpp"

#include <algorithm>
#include <cmath>

#include "vibrotherm/coupling/run/run_observers.hpp"
#include "vibrotherm/coupling/observe/heat_camera.hpp"
#include "vibrotherm/coupling/continuation/periodic_continuation.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/stop_signals.hpp"

namespace vibrotherm::coupling {

Simulation::Simulation() = default;
Simulation::~Simulation() = default;

PetscErrorCode Simulation::Setup(const mesh::Specimen& specimen, const Scene& scene, io::RunSummary* summary,
                                 bool restarting) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  scene_ = &scene;
  specimen_ = &specimen;
  const DriverOptions& run = scene.run;
  PetscCheck(run.crack_probes.empty() || !specimen.cracks.empty(), comm, PETSC_ERR_USER_INPUT,
             "-crack_probe needs a crack (-crack_center or crack curves in -mesh_file)");
  PetscCheck(run.crack_probes.empty() ||
                 (run.crack_probe_crack >= 1 && run.crack_probe_crack <= static_cast<PetscInt>(specimen.cracks.size())),
             comm, PETSC_ERR_USER_INPUT, "-crack_probe_crack %" PetscInt_FMT ": the specimen has %zu crack(s)",
             run.crack_probe_crack, specimen.cracks.size());
  PetscCall(PetscLogStageRegister("Wave steps", &wave_stage_));
  PetscCall(PetscLogStageRegister("Heat steps", &heat_stage_));
  if (run.physics != PhysicsChoice::Heat) {
    waves_ = std::make_unique<WaveComponent>();
    PetscCall(waves_->Setup(specimen, scene, summary, restarting));
    strain_ = std::make_unique<ResponseStrain>(scene.material.cs());
  }
  const bool can_heat = waves_ && ((waves_->crack() && waves_->crack()->dissipative()) ||
                                   run.thermoelastic != ThermoelasticChoice::Off || scene.material.damping_heat);
  const bool heat_needed = run.physics == PhysicsChoice::Heat ||
                           (run.physics == PhysicsChoice::All &&
                            (run.heat == HeatChoice::On || (run.heat == HeatChoice::Auto && can_heat)));
  if (heat_needed) {
    heat_ = std::make_unique<HeatComponent>();
    PetscCall(heat_->Setup(specimen, scene, waves_.get(), summary));
    PetscCall(SetupCamera(scene));
    bool every;
    PetscCall(OptionGiven(nullptr, "-energy_every", &every));
    if (every && waves_)
      PetscCall(PetscPrintf(comm, "vibrotherm: warning: -energy_every is not used while heat runs: energy.csv gets a "
                                  "row per coupling interval (-couple_dt), where every column is known\n"));
  } else if (scene.camera.on) {
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: -camera: no heat runs in this scene, nothing to film: no "
                                "camera.h5\n"));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::SetupCamera(const Scene& scene) {
  PetscFunctionBeginUser;
  if (!scene.camera.on) PetscFunctionReturn(0);
  camera_ = std::make_unique<HeatCamera>();
  camera_->SetDefectShare(heat_->defect_share());
  PetscInt frames;
  PetscCall(camera_->Setup(heat_->solver(), scene.camera, scene.final_time, &frames));
  if (frames == 0) camera_.reset();
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Run(const std::string& dir, io::RunSummary* summary, const RunControl& control) {
  PetscFunctionBeginUser;
  dir_ = dir;
  control_ = control;
  summary_ = summary;
  const fe::LagrangeSpace& probe_space = waves_ ? waves_->solver().space() : heat_->solver().space();
  PetscCall(schedule_.Start(PetscObjectComm((PetscObject)probe_space.dm()), scene_->run.checkpoint_every_s));
  PetscCall(CanCheckpoint(&checkpoints_));
  Recorder recorder;
  PetscCall(recorder.Open(scene_->run, dir, probe_space, waves_ ? waves_->crack() : nullptr,
                          heat_ ? heat_->crack_probe_xy() : std::vector<double>{}, summary, control.restart));
  if (heat_) PetscCall(recorder.OpenHeatViews(heat_->solver(), camera_.get(), dir, control.restart != nullptr));
  if (waves_) PetscCall(recorder.MeterSource(scene_->excitation.signal, scene_->periodic.window, control.restart));
  RunObservers observers(recorder, waves_.get(), heat_.get(), scene_->run.probe_every);
  observers.OnBetweenSteps([this, &recorder](bool* stop) {
    PetscFunctionBeginUser;
    PetscCall(CheckpointIfDue(recorder, false));
    *stop = interrupted_by_ != 0;
    PetscFunctionReturn(0);
  });
  if (!control.restart) {  // t = 0
    io::EnergyRow row;
    if (waves_) PetscCall(waves_->Energy(&row));
    PetscCall(observers.Start(waves_ ? &row : nullptr));
  }
  if (waves_) {
    periodic_ = std::make_unique<PeriodicContinuation>();
    PetscCall(periodic_->Setup(scene_->continuation(), *specimen_, waves_.get(), heat_.get(), &observers, dir,
                               summary, control.restart));
  }
  if (control.restart) PetscCall(Resume(*control.restart, observers));
  PetscCall(RunPhases(observers, summary));
  if (interrupted_by_) {  // the files stay as the checkpoint describes them
    recorder.Keep();
    if (periodic_) periodic_->Keep();
    PetscFunctionReturn(0);
  }
  if (periodic_) PetscCall(periodic_->Finish(summary));
  if (heat_) {
    PetscCall(heat_->StopSources(dir));
    PetscCall(heat_->Summarise(summary));
  }
  PetscCall(recorder.Finish(summary));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::RunPhases(RunObservers& observers, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  RunPhase phase = RunPhase::kHeatAlone;
  if (waves_) {
    PetscCall(StartWaves(observers));
    continuation_restarted_ = periodic_->ready();  // restarted inside a continuation: its rest first
    phase = continuation_restarted_ ? RunPhase::kContinued : RunPhase::kCoupled;
  }
  while (phase != RunPhase::kDone && !interrupted_by_) {
    switch (phase) {
      case RunPhase::kCoupled:
        PetscCall(CoupledInterval(observers, &phase));
        break;
      case RunPhase::kContinued:
        PetscCall(Continued(observers, &phase));
        break;
      case RunPhase::kStopWaves:
        PetscCall(EndWaves(observers, summary, &phase));
        break;
      case RunPhase::kHeatAlone:
        if (heat_ && heat_->solver().time() < scene_->final_time * (1 - 1e-12)) PetscCall(RunHeatAlone(observers, summary));
        phase = RunPhase::kDone;
        break;
      case RunPhase::kDone:
        break;
    }
  }
  if (waves_ && waves_->running() && interrupted_by_) PetscCall(PetscLogStagePop());  // the waves' stage, left early
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::StartWaves(RunObservers& observers) {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = waves_->solver();
  MPI_Comm comm = PetscObjectComm((PetscObject)solver.space().dm());
  const double final_time = scene_->final_time;
  // A whole number of wave steps per heat step: every heat step has the same
  // length, so the heat matrix is factored once.
  const PetscInt per_interval = heat_ ? scene_->run.heat_substeps : 1;
  heat_dt_ = scene_->couple_dt / per_interval;
  const PetscInt per_heat_step = WaveStepsPerHeatStep(heat_dt_);
  const double expected_end = scene_->waves_expected_end();
  PetscCall(PetscPrintf(comm,
                        "Waves: %" PetscInt_FMT " dofs (degree %" PetscInt_FMT "), dt = %.4g s (limit %.4g s, "
                        "omega_max %.4g rad/s), about %.0f steps at this step to t = %.4g s%s\n",
                        solver.op().dofs(), scene_->wave.degree, solver.step().dt(), solver.step().stable_dt(), solver.omega_max(),
                        std::ceil(expected_end / solver.step().dt()), expected_end,
                        expected_end < final_time ? ", where they should be quiet (they stop once they are)" : ""));
  if (heat_)
    PetscCall(PetscPrintf(comm, "Heat: %" PetscInt_FMT " dofs, one step every %" PetscInt_FMT " wave steps (%.4g s)\n",
                          heat_->solver().dofs(), per_heat_step, per_heat_step * solver.step().dt()));
  solver.on_step = [&observers](const wave::WaveSolver& w) { return observers.WaveStep(w); };
  observers.progress().Start(comm, "wave", 0.0, expected_end, solver.step().dt(), false);
  waves_began_ = MPI_Wtime();
  PetscCall(PetscLogStagePush(wave_stage_));
  PetscCall(waves_->Energy(&row_));
  quiet_ = waves_quiet_at_restart_;  // restarted where the waves stopped: they stop at once
  if (quiet_) heat_alone_from_ = solver.time();
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::CoupledInterval(RunObservers& observers, RunPhase* next) {
  PetscFunctionBeginUser;
  if (quiet_ || waves_->solver().time() >= scene_->final_time * (1 - 1e-12)) {
    *next = RunPhase::kStopWaves;
    PetscFunctionReturn(0);
  }
  PetscCall(Interval(observers, heat_dt_, &row_));
  bool ready;
  PetscCall(periodic_->AfterInterval(row_, &ready));
  if (ready) {  // continued next; the quiet test and the checkpoint of this interval after it
    *next = RunPhase::kContinued;
    PetscFunctionReturn(0);
  }
  PetscCall(AfterCoupledInterval(observers, next));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::AfterCoupledInterval(RunObservers& observers, RunPhase* next) {
  PetscFunctionBeginUser;
  PetscCall(WavesQuiet(row_, &quiet_));
  PetscCall(CheckpointIfDue(observers.recorder(), quiet_));
  *next = RunPhase::kCoupled;
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::Continued(RunObservers& observers, RunPhase* next) {
  PetscFunctionBeginUser;
  const bool restarted = continuation_restarted_;  // restarted inside its ladder: no interval ended it
  continuation_restarted_ = false;
  bool resumed;
  PetscCall(periodic_->Continue(&resumed));
  *next = RunPhase::kCoupled;
  if (restarted) {
    PetscCall(waves_->Energy(&row_));
    PetscFunctionReturn(0);
  }
  if (resumed) {  // the waves jumped ahead: their energies now, the progress line on from here
    wave::WaveSolver& solver = waves_->solver();
    PetscCall(waves_->Energy(&row_));
    observers.progress().Start(PetscObjectComm((PetscObject)solver.space().dm()), "wave", solver.time(),
                                scene_->waves_expected_end(), solver.step().dt(), false);
  }
  PetscCall(AfterCoupledInterval(observers, next));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::EndWaves(RunObservers& observers, io::RunSummary* summary, RunPhase* next) {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = waves_->solver();
  PetscCall(PetscLogStagePop());
  summary->stages["wave_steps"] = MPI_Wtime() - waves_began_ - (heat_ ? heat_->seconds() : 0.0);
  PetscCall(observers.progress().Done(solver.time(), solver.steps()));
  PetscCall(StopWaves(observers, row_, summary));
  *next = RunPhase::kHeatAlone;
  PetscFunctionReturn(0);
}

PetscInt Simulation::WaveStepsPerHeatStep(double heat_dt) const {
  return std::max<PetscInt>(1, std::lround(heat_dt / waves_->solver().step().dt()));
}

PetscErrorCode Simulation::Interval(RunObservers& observers, double heat_dt, io::EnergyRow* row) {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = waves_->solver();
  const PetscInt heat_steps = heat_ ? scene_->run.heat_substeps : 1;
  for (PetscInt k = 0; k < heat_steps && solver.time() < scene_->final_time * (1 - 1e-12); ++k) {
    // Counted again each time: the contact may have shrunk the wave step. Quantized steps (a periodic
    // source) land on the heat step's end, where a periodic state is compared and recorded.
    if (scene_->wave.step_quantum > 0.0)
      PetscCall(waves_->AdvanceTo(std::min(scene_->final_time, (std::round(solver.time() / heat_dt) + 1.0) * heat_dt)));
    else
      PetscCall(waves_->Advance(WaveStepsPerHeatStep(heat_dt), scene_->final_time));
    if (!heat_) continue;
    PetscCall(PetscLogStagePush(heat_stage_));
    PetscCall(heat_->StepTo(solver.time()));
    PetscCall(observers.HeatStepCoupled(heat_->solver()));
    PetscCall(PetscLogStagePop());
  }
  PetscCall(waves_->Energy(row));  // once per interval: energy rows and the quiet test
  PetscCall(strain_->Check(solver, summary_));
  PetscCall(observers.IntervalCoupled(*row));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::WavesQuiet(const io::EnergyRow& e, bool* quiet) {
  PetscFunctionBeginUser;
  *quiet = false;
  if (scene_->run.quiet_fraction <= 0.0) PetscFunctionReturn(0);
  // The mechanical energy left bounds the heat still to come: once it is a small
  // fraction of what has been dissipated, stopping the waves loses at most that fraction.
  // Of it, the heating losses take at most their share of the losses over the last period
  // (friction; material damping only with -material_damping_heat; radiation heats nothing).
  const double t = e.t;
  const bool damping_heats = scene_->material.damping_heat;
  double left = e.kinetic + e.strain + e.interface_stored;
  if (heat_ && !recent_.empty()) {  // the waves stop for the heat's sake
    const Sample& first = recent_.front();
    const double friction = e.dissipated - first.dissipated, damped = e.damped - first.damped;
    const double heating = friction + (damping_heats ? damped : 0.0);
    const double losses = friction + damped + (e.radiated - first.radiated);
    if (losses > 0.0) left *= std::max(0.0, heating) / losses;
  }
  recent_.push_back({t, left, e.dissipated, e.damped, e.radiated});
  peak_mechanical_ = std::max(peak_mechanical_, left);
  // Over a whole source period: kinetic and strain energy trade places within a cycle.
  const double period = 1.0 / scene_->excitation.signal.frequency;
  while (recent_.size() > 2 && recent_.front().t < t - period) recent_.erase(recent_.begin());
  if (t < scene_->excitation.signal.duration + period) PetscFunctionReturn(0);
  double most = 0.0;
  for (const Sample& s : recent_) most = std::max(most, s.energy);
  const double heated = e.dissipated + (damping_heats ? e.damped : 0.0);
  const double reference = heat_ && heated > 0.0 ? heated : peak_mechanical_;
  *quiet = most <= scene_->run.quiet_fraction * reference;
  mechanical_left_ = most;
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::StopWaves(RunObservers& observers, const io::EnergyRow& last, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  wave::WaveSolver& solver = waves_->solver();
  MPI_Comm comm = PetscObjectComm((PetscObject)solver.space().dm());
  PetscCall(observers.WavesStopped(last));
  summary->wave_energy_left = mechanical_left_;
  summary->derived["response_strain"] = strain_->peak();
  summary->derived_rules["response_strain"] =
      "max |v| / c_s over the specimen and the coupling intervals: the strain the waves reached (a plane wave's; "
      "warned about above 1e-3 and 1e-2)";
  summary->work_thermal = last.work_thermal;
  if (solver.time() < scene_->final_time * (1 - 1e-12))
    PetscCall(PetscPrintf(comm, "Waves quiet at t = %.6g s: wave solver stopped%s\n", solver.time(),
                          heat_ ? ", heat continues alone" : ""));
  // The waves are over: the heat sources write their records, the wave solver
  // and the interface are freed (the heat TS carries on alone).
  if (heat_) PetscCall(heat_->StopSources(dir_));
  PetscCall(waves_->Stop(summary));
  PetscFunctionReturn(0);
}

PetscErrorCode Simulation::RunHeatAlone(RunObservers& observers, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  heat::HeatSolver& heat = heat_->solver();
  MPI_Comm comm = PetscObjectComm((PetscObject)heat.space().dm());
  const double final_time = scene_->final_time;
  PetscCall(heat.UseFreeIntegrator());
  const double t_begin = heat.time();
  const PetscInt steps_before = heat.steps();
  PetscCall(PetscPrintf(comm, "Heat alone from t = %.6g s to %g s: %s\n", t_begin, final_time,
                        heat_alone_from_ >= 0.0 ? "a stop from here resumes (-restart) where the waves stopped, repeating "
                                                  "this phase"
                                                : "not resumable (no checkpoint of this scene): a stop loses the run"));
  observers.progress().Start(comm, "heat", t_begin, final_time, 0.0, true);
  const double t0 = MPI_Wtime();
  PetscCall(PetscLogStagePush(heat_stage_));
  PetscCall(observers.HeatAloneStart(t_begin));
  heat.on_step = [this, &observers, &heat](const heat::HeatSolver&) {
    PetscFunctionBeginUser;
    bool due;  // no checkpoints here: a signal stops the run, a restart repeats this phase
    PetscCall(schedule_.Poll(&due, &interrupted_by_));
    if (interrupted_by_) heat.RequestStop();
    PetscCall(observers.HeatStepAlone(heat));
    PetscFunctionReturn(0);
  };
  // One TSSolve per output segment (or camera window boundary): each lands on the output time
  // it is due at; the step ladder's rung carries over.
  while (heat.time() < final_time * (1 - 1e-12) && !interrupted_by_)
    PetscCall(heat.AdvanceTo(observers.NextHeatStop(heat.time(), final_time)));
  heat.on_step = nullptr;
  if (interrupted_by_ && heat_alone_from_ >= 0.0)
    PetscCall(PetscPrintf(comm, "vibrotherm: %s at t = %.6g s while the heat runs alone: stopping; -restart %s resumes "
                                "from its checkpoint at t = %.6g s, where the waves stopped, and repeats this phase\n",
                          stop_signals::Name(interrupted_by_), heat.time(), dir_.c_str(), heat_alone_from_));
  else if (interrupted_by_)
    PetscCall(PetscPrintf(comm, "vibrotherm: %s at t = %.6g s while the heat runs alone: stopping, without a checkpoint "
                                "(this scene has none): the run is lost\n", stop_signals::Name(interrupted_by_), heat.time()));
  if (interrupted_by_) stop_signals::Stopping();
  summary->stages["heat_free"] = MPI_Wtime() - t0;
  summary->steps_heat_free = heat.steps() - steps_before;
  PetscCall(PetscLogStagePop());
  heat_->add_seconds(MPI_Wtime() - t0);
  PetscCall(observers.progress().Done(heat.time(), heat.steps()));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
