#include "vibrotherm/coupling/run/scene.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "vibrotherm/coupling/run/scene_dimension.hpp"
#include "vibrotherm/interface/contact_options.hpp"
#include "vibrotherm/options/query/option_query.hpp"

namespace vibrotherm::coupling {

double Scene::exchange_length() const {
  return std::sqrt(heat.material.diffusivity() * couple_dt / static_cast<double>(run.heat_substeps));
}

double Scene::waves_expected_end() const {
  return std::min(final_time, excitation.signal.duration + 8.0 / excitation.signal.frequency);
}

ContinuationScene Scene::continuation() const {
  return {periodic, &excitation.signal, final_time, couple_dt, run.heat_substeps, waves_expected_end(), &excitation};
}

namespace {

/// A start that needs a steady response (harmonic, state) has none with a sweep; a state start needs its file.
PetscErrorCode CheckWaveStart(MPI_Comm comm, const wave::WaveOptions& o, const wave::SourceTimeFunction& signal) {
  PetscFunctionBeginUser;
  const bool state = o.start == wave::WaveStart::kState;
  PetscCheck(o.start == wave::WaveStart::kRest || !signal.sweeping(), comm, PETSC_ERR_USER_INPUT,
             "-wave_start %s with -source_sweep: a sweep has no steady response to start in (use -wave_start rest)",
             state ? "state" : "harmonic");
  PetscCheck(!state || !o.start_state.empty(), comm, PETSC_ERR_USER_INPUT,
             "-wave_start state: needs -wave_start_state FILE (a state saved by -periodic_save_state)");
  PetscCheck(state || o.start_state.empty(), comm, PETSC_ERR_USER_INPUT,
             "-wave_start_state %s: only read with -wave_start state", o.start_state.c_str());
  PetscBool readable = PETSC_TRUE;
  if (state) PetscCall(PetscTestFile(o.start_state.c_str(), 'r', &readable));
  PetscCheck(readable, comm, PETSC_ERR_FILE_OPEN, "-wave_start_state %s: file not found", o.start_state.c_str());
  PetscFunctionReturn(0);
}

/// Values every reader accepted but no run can use: infinities, and wave TS types
/// that cannot run here.
PetscErrorCode CheckScene(MPI_Comm comm, const Scene& s) {
  PetscFunctionBeginUser;
  const std::pair<const char*, double> finite[] = {
      {"-material_density", s.material.density}, {"-material_E", s.material.E},
      {"-source_frequency", s.excitation.signal.frequency}, {"-source_amplitude", s.excitation.signal.amplitude},
      {"-source_duration", s.excitation.signal.duration}, {"-source_ramp_cycles", s.excitation.signal.ramp_cycles},
      {"-wave_dt", s.wave.dt}, {"-heat_conductivity", s.heat.material.conductivity},
      {"-heat_capacity", s.heat.material.capacity}, {"-heat_T0", s.heat.material.T0},
      {"-crack_a0", s.a0.uniform}, {"-crack_a0_max", s.a0.max},
      {"-heat_crack_power", s.run.heat_crack_power}};
  for (const auto& [option, value] : finite)
    PetscCheck(std::isfinite(value), comm, PETSC_ERR_USER_INPUT, "%s must be finite, got %g", option, value);
  // Implicit types other than alpha2 would build a dense Jacobian; rk types with an
  // embedded error estimate reject steps rank by rank (a deadlock on 2 ranks).
  std::string type = "velocityverlet", rk = "4";
  PetscCall(OptionText("wave_", "-ts_type", &type));
  PetscCall(OptionText("wave_", "-ts_rk_type", &rk));
  const std::vector<std::string> types = {"velocityverlet", "basicsymplectic", "rk", "ssp", "alpha2"};
  PetscCheck(std::find(types.begin(), types.end(), type) != types.end(), comm, PETSC_ERR_USER_INPUT,
             "-wave_ts_type %s is not supported for waves (velocityverlet|basicsymplectic|rk|ssp|alpha2)", type.c_str());
  const std::vector<std::string> rk_types = {"1fe", "2a", "3", "4"};
  PetscCheck(type != "rk" || std::find(rk_types.begin(), rk_types.end(), rk) != rk_types.end(),
             comm, PETSC_ERR_USER_INPUT, "-wave_ts_rk_type %s is not supported for waves (1fe|2a|3|4: fixed steps)", rk.c_str());
  // Options of the TS objects that vibrotherm sets itself: refused, not ignored.
  const std::pair<const char*, const char*> owned[] = {
      {"-wave_ts_dt", "-wave_dt or -wave_cfl"}, {"-wave_ts_max_time", "-final_time"},
      {"-wave_ts_max_steps", "-final_time (or -max_steps)"}, {"-wave_ts_exact_final_time", "-final_time"},
      {"-heat_ts_dt", "-couple_dt and -heat_substeps"}, {"-heat_ts_max_time", "-final_time"},
      {"-heat_ts_max_steps", "-final_time"}, {"-heat_free_ts_max_time", "-final_time"},
      {"-heat_free_ts_max_steps", "-final_time"}};
  for (const auto& [option, instead] : owned) {
    bool given;
    PetscCall(OptionGiven(nullptr, option, &given));
    PetscCheck(!given, comm, PETSC_ERR_USER_INPUT, "%s is set by vibrotherm itself: use %s", option, instead);
  }
  PetscFunctionReturn(0);
}

/// Values every reader accepts but that can only give a useless run (a source that
/// never drives, a switch-on longer than the excitation, a heat step longer than the
/// run, a camera without noise): refused naming the option, or said when a default is cut.
PetscErrorCode CheckUsefulValues(MPI_Comm comm, const Scene& s) {
  PetscFunctionBeginUser;
  const wave::SourceTimeFunction& g = s.excitation.signal;
  if (s.run.physics != PhysicsChoice::Heat) {
    PetscCheck(g.duration > 0.0, comm, PETSC_ERR_USER_INPUT,
               "-source_duration must be > 0 (the waves are driven only while the source runs), got %g", g.duration);
    PetscCheck(g.duration * g.frequency >= 1.0, comm, PETSC_ERR_USER_INPUT,
               "-source_frequency %g Hz: %.3g cycles in -source_duration %g s; at least one whole cycle is needed "
               "(raise -source_frequency or -source_duration)",
               g.frequency, g.duration * g.frequency, g.duration);
    PetscCheck(g.amplitude != 0.0 || !g.schedule.empty(), comm, PETSC_ERR_USER_INPUT,
               "-source_amplitude 0: nothing drives the waves (give an amplitude, or a -source_schedule)");
    // The switch-on and the switch-off each take at most half the excitation: a longer ramp is cut
    // (said), and one longer than the whole excitation is no ramp anyone meant (refused).
    const double fit = 0.5 * g.duration * g.frequency;  // cycles
    PetscCheck(g.ramp_cycles <= 2.0 * fit * (1 + 1e-12), comm, PETSC_ERR_USER_INPUT,
               "-source_ramp_cycles %g: a switch-on longer than the whole excitation (-source_duration %g s: %.4g "
               "cycles at %g Hz); the switch-on and the switch-off take at most %.4g cycles each",
               g.ramp_cycles, g.duration, 2.0 * fit, g.frequency, fit);
    if (g.ramp_cycles > fit * (1 + 1e-12))
      PetscCall(PetscPrintf(comm, "vibrotherm: warning: -source_ramp_cycles %g does not fit twice in -source_duration %g "
                                  "s (%.4g cycles): the switch-on and the switch-off take %.4g cycles each\n",
                            g.ramp_cycles, g.duration, 2.0 * fit, fit));
  }
  const double heat_dt = s.couple_dt / static_cast<double>(s.run.heat_substeps);
  const bool heat_may_run = s.run.physics == PhysicsChoice::All && s.run.heat != HeatChoice::Off;
  PetscCheck(!heat_may_run || heat_dt <= s.final_time * (1 + 1e-12), comm, PETSC_ERR_USER_INPUT,
             "a heat step of %g s (the coupling interval %g s%s, / -heat_substeps %" PetscInt_FMT ") is longer than the "
             "run (%g s, -final_time): set -couple_dt or raise -final_time",
             heat_dt, s.couple_dt, s.run.couple_dt > 0.0 ? "" : ", 1/8 of the source period", s.run.heat_substeps,
             s.final_time);
  PetscFunctionReturn(0);
}

/// A periodic continuation compares and replays whole source periods, and the source's power is
/// measured over whole periods: the wave step must divide the heat step, which must divide the
/// period. The steps are quantized so whenever the coupling allows it (the continuation is off,
/// said once, when it cannot be).
PetscErrorCode QuantizeForPeriodicity(MPI_Comm comm, Scene* s) {
  PetscFunctionBeginUser;
  const bool heat_may_run = s->run.physics == PhysicsChoice::All && s->run.heat != HeatChoice::Off;
  if (s->periodic.choice == PeriodicChoice::Auto && !heat_may_run) s->periodic.on = false;
  if (s->periodic.on && s->excitation.signal.sweeping()) {
    s->periodic.on = false;
    PetscCall(PetscPrintf(comm, "vibrotherm: note: periodic continuation off: a frequency sweep (-source_sweep) never "
                                "repeats itself; it is simulated in full\n"));
  }
  const double period = 1.0 / s->excitation.signal.frequency, heat_dt = s->couple_dt / s->run.heat_substeps;
  const double per_period = period / heat_dt;
  const bool divides = std::abs(per_period - std::round(per_period)) <= 1e-9 * per_period;
  // Only for a continuation: quantizing shrinks the step (a run without one keeps its own CFL step;
  // the source's power between rows that miss a period boundary is then interpolated).
  if (divides && s->wave.dt <= 0.0 && s->periodic.on)
    s->wave.step_quantum = s->wave.lts.step_quantum = period / std::round(per_period);
  if (s->periodic.on && s->wave.step_quantum <= 0.0) {
    s->periodic.on = false;
    PetscCall(PetscPrintf(comm, "vibrotherm: note: periodic continuation off: %s\n",
                          s->wave.dt > 0.0 ? "-wave_dt fixes the wave step (it must divide the heat step)"
                                           : "-couple_dt / -heat_substeps does not divide the source period"));
  }
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ReadScene(MPI_Comm comm, Scene* s) {
  PetscFunctionBeginUser;
  int file_dimension;
  PetscCall(ReadSceneDimension(comm, &s->run.dimension, &file_dimension));
  PetscCall(ReadDriverOptions(comm, &s->run, &s->values));
  PetscCall(wave::ReadElasticMaterial(comm, &s->material, &s->values));
  PetscCall(wave::ReadExcitation(comm, &s->excitation, &s->values));
  // A sweep's loss factor holds at its centre frequency (mass-proportional damping: η ∝ 1/f across the band).
  const wave::SourceTimeFunction& signal = s->excitation.signal;
  const double damping_frequency = signal.sweeping() ? 0.5 * (signal.sweep_from + signal.sweep_to) : signal.frequency;
  PetscCall(wave::ReadMaterialDamping(comm, damping_frequency, &s->material, &s->values));
  PetscCall(wave::ReadWaveOptions(comm, &s->wave, &s->values));
  PetscCall(CheckWaveStart(comm, s->wave, signal));
  // No switch-on: the waves start in a steady state.
  s->excitation.signal.running_at_start = s->wave.start != wave::WaveStart::kRest;
  PetscCall(ReadContactOptions(comm, s->contact, &s->values));
  PetscCall(interface::ReadApproachProfile(comm, &s->a0, &s->values));
  PetscCall(heat::ReadHeatOptions(comm, s->material.density, &s->heat, &s->values));
  PetscCall(ReadCameraOptions(comm, &s->camera, &s->values));
  PetscCall(ReadPeriodicOptions(comm, &s->periodic, &s->values));
  PetscCall(CheckScene(comm, *s));
  PetscCall(RestrictToDimension(comm, s));
  s->final_time = s->run.final_time > 0.0 ? s->run.final_time : s->excitation.signal.duration;
  s->couple_dt = CouplingInterval(s->run, s->excitation.signal.frequency);
  PetscCall(CheckUsefulValues(comm, *s));
  PetscCall(QuantizeForPeriodicity(comm, s));
  s->heat.coupled_step = s->couple_dt / static_cast<double>(s->run.heat_substeps);
  // Output times after the end would never be written: say so, and drop them.
  std::vector<double> kept;
  for (double t : s->run.output_times) {
    if (t <= s->final_time * (1 + 1e-12)) kept.push_back(t);
    else
      PetscCall(PetscPrintf(comm, "vibrotherm: warning: -output_times %g s is after the end of the run (%g s): not written\n",
                            t, s->final_time));
  }
  s->run.output_times = kept;
  PetscCall(mesh::ReadSpecimenOptions(comm, s->exchange_length(), &s->specimen, &s->values));  // its heat mesh: after the heat step
  s->specimen.source.file_dimension = file_dimension;
  s->wave.harmonic_force = s->specimen.source.force;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
