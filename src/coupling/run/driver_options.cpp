#include "vibrotherm/coupling/run/driver_options.hpp"

#include "vibrotherm/options/petsc/option_choice.hpp"
#include "vibrotherm/options/petsc/option_list.hpp"

#include <algorithm>
#include <cmath>
#include <string>


namespace vibrotherm::coupling {

namespace {

/// Every value given must be usable: refused naming the option, never silently replaced by the default.
PetscErrorCode CheckDriverOptions(MPI_Comm comm, PetscBool final_set, PetscBool couple_set, DriverOptions* o) {
  PetscFunctionBeginUser;
  // Checked here, not only when the recorder opens probes.csv (the output directory exists by then).
  PetscCheck(o->probe_points.size() % o->dimension == 0, comm, PETSC_ERR_USER_INPUT,
             "-probe_points needs %s, got %zu numbers", o->dimension == 2 ? "x,y pairs" : "x,y,z triples in 3D",
             o->probe_points.size());
  for (double s : o->crack_probes)
    PetscCheck(s >= 0.0 && s <= 1.0, comm, PETSC_ERR_USER_INPUT, "-crack_probe: fractions must be in [0, 1], got %g", s);
  std::sort(o->output_times.begin(), o->output_times.end());
  for (double t : o->output_times)
    PetscCheck(t >= 0.0, comm, PETSC_ERR_USER_INPUT, "-output_times: times must be >= 0, got %g", t);
  PetscCheck(o->crack_state_every >= 0, comm, PETSC_ERR_USER_INPUT, "-crack_state_every must be >= 0");
  PetscCheck(o->crack_probe_crack >= 1, comm, PETSC_ERR_USER_INPUT,
             "-crack_probe_crack must be >= 1 (cracks are numbered from 1), got %" PetscInt_FMT, o->crack_probe_crack);
  // Given values must be usable: never silently replaced by the default.
  PetscCheck(!final_set || (o->final_time > 0.0 && std::isfinite(o->final_time)), comm, PETSC_ERR_USER_INPUT,
             "-final_time must be > 0 and finite, got %g", o->final_time);
  PetscCheck(!couple_set || (o->couple_dt > 0.0 && std::isfinite(o->couple_dt)), comm, PETSC_ERR_USER_INPUT,
             "-couple_dt must be > 0 and finite, got %g", o->couple_dt);
  PetscCheck(o->checkpoint_every_s >= 0.0 && std::isfinite(o->checkpoint_every_s), comm, PETSC_ERR_USER_INPUT,
             "-checkpoint_every_s must be >= 0 and finite, got %g", o->checkpoint_every_s);
  PetscCheck(o->max_steps >= 1.0 && std::isfinite(o->max_steps), comm, PETSC_ERR_USER_INPUT,
             "-max_steps must be >= 1 and finite, got %g", o->max_steps);
  // PETSc counts steps in a PetscInt: a larger count would wrap around (a run "done in 1 step").
  PetscCheck(o->max_steps <= static_cast<double>(PETSC_MAX_INT), comm, PETSC_ERR_USER_INPUT,
             "-max_steps must be <= %g (PETSc's step counter), got %g", static_cast<double>(PETSC_MAX_INT),
             o->max_steps);
  PetscCheck(o->heat_substeps >= 1, comm, PETSC_ERR_USER_INPUT, "-heat_substeps must be >= 1, got %" PetscInt_FMT,
             o->heat_substeps);
  PetscCheck(o->near_field_steps >= 1, comm, PETSC_ERR_USER_INPUT,
             "-heat_near_field_steps must be >= 1, got %" PetscInt_FMT, o->near_field_steps);
  PetscCheck(o->energy_every >= 1, comm, PETSC_ERR_USER_INPUT, "-energy_every must be >= 1");
  PetscCheck(o->probe_every >= 1, comm, PETSC_ERR_USER_INPUT, "-probe_every must be >= 1");
  PetscCheck(o->quiet_fraction >= 0.0 && o->quiet_fraction < 1.0, comm, PETSC_ERR_USER_INPUT,
             "-wave_quiet_fraction must be in [0, 1), got %g", o->quiet_fraction);
  PetscCheck(o->heat_crack_power >= 0.0, comm, PETSC_ERR_USER_INPUT, "-heat_crack_power must be >= 0, got %g",
             o->heat_crack_power);
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ReadDriverOptions(MPI_Comm comm, DriverOptions* o) {
  PetscFunctionBeginUser;
  PetscBool final_set = PETSC_FALSE, couple_set = PETSC_FALSE;
  PetscInt physics = static_cast<PetscInt>(o->physics), heat = static_cast<PetscInt>(o->heat);
  PetscInt thermoelastic = static_cast<PetscInt>(o->thermoelastic);
  PetscOptionsBegin(comm, nullptr, "Run control and recording", nullptr);
  PetscCall(OptionsChoice(PetscOptionsObject, "-physics",
                          "Physics to run: all (waves, contact, heat as the scene needs), wave, heat",
                          {"all", "wave", "heat"}, &physics, nullptr));
  PetscCall(OptionsChoice(PetscOptionsObject, "-heat", "Heat solver: auto (when friction can dissipate), on, off",
                          {"auto", "on", "off"}, &heat, nullptr));
  PetscCall(OptionsChoice(PetscOptionsObject, "-thermoelastic",
                          "Thermoelastic coupling: heating of the waves -T0 beta tr(eps_dot) (one_way: waves -> heat); "
                          "two_way: also the thermal stress -beta theta I on the waves (thermoelastic damping)",
                          {"off", "one_way", "two_way"}, &thermoelastic, nullptr));
  PetscCall(PetscOptionsReal("-heat_crack_power", "-physics heat: power per unit crack area on every crack [W/m^2]",
                             nullptr, o->heat_crack_power, &o->heat_crack_power, nullptr));
  PetscCall(PetscOptionsReal("-final_time", "Simulated time [s] (default: the source duration)", nullptr,
                             o->final_time, &o->final_time, &final_set));
  PetscCall(PetscOptionsReal("-couple_dt", "Heat coupling interval [s] (default: 1/8 of the source period)", nullptr,
                             o->couple_dt, &o->couple_dt, &couple_set));
  PetscCall(PetscOptionsInt("-heat_substeps", "Heat steps per coupling interval, each with the friction energy dissipated within it", nullptr,
                            o->heat_substeps, &o->heat_substeps, nullptr));
  PetscBool near_field = o->near_field ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(PetscOptionsBool("-heat_near_field",
                             "Probes within reach of a crack add the friction heat of the last heat steps at wave-step "
                             "resolution, exactly (the heat mesh smooths the pulses)", nullptr, near_field, &near_field,
                             nullptr));
  o->near_field = near_field;
  PetscCall(PetscOptionsInt("-heat_near_field_steps",
                            "Heat steps whose friction heat the crack probes take exactly (-heat_near_field)", nullptr,
                            o->near_field_steps, &o->near_field_steps, nullptr));
  PetscCall(PetscOptionsReal("-max_steps",
                             "Largest number of wave steps a run may take (refused at setup with the estimate)", nullptr,
                             o->max_steps, &o->max_steps, nullptr));
  PetscCall(PetscOptionsReal("-checkpoint_every_s",
                             "Wall seconds between checkpoints (DIR/checkpoint.h5, for -restart DIR) while the waves run; "
                             "0: only when SIGTERM, SIGINT or SIGUSR1 stops the run", nullptr, o->checkpoint_every_s,
                             &o->checkpoint_every_s, nullptr));
  PetscCall(PetscOptionsReal("-wave_quiet_fraction",
                             "Waves stop after the source once, for a whole period, the mechanical energy left "
                             "(a bound on the heat still to come) is below this fraction of the energy dissipated "
                             "(of its peak when nothing dissipates); 0: never",
                             nullptr, o->quiet_fraction, &o->quiet_fraction, nullptr));
  PetscCall(OptionsRealList(PetscOptionsObject, "-output_times", "Times of the fields in fields.h5 [s]",
                            &o->output_times, nullptr));
  PetscCall(PetscOptionsInt("-energy_every", "Steps between rows of energy.csv", nullptr, o->energy_every,
                            &o->energy_every, nullptr));
  PetscCall(PetscOptionsInt("-probe_every", "Steps between rows of probes.csv", nullptr, o->probe_every,
                            &o->probe_every, nullptr));
  PetscCall(OptionsRealList(PetscOptionsObject, "-probe_points", "Probe points x1,y1,x2,y2,... [m] (3D: x1,y1,z1,...)",
                            &o->probe_points, nullptr));
  PetscCall(OptionsRealList(PetscOptionsObject, "-crack_probe", "Crack probes: fractions of the crack length (0.5: centre)",
                            &o->crack_probes, nullptr));
  PetscCall(PetscOptionsInt("-crack_probe_crack", "Crack of the crack probes (1-based)", nullptr, o->crack_probe_crack,
                            &o->crack_probe_crack, nullptr));
  PetscCall(PetscOptionsInt("-crack_state_every", "Steps between crack_state.csv records (0: none)", nullptr,
                            o->crack_state_every, &o->crack_state_every, nullptr));
  PetscOptionsEnd();
  o->physics = static_cast<PhysicsChoice>(physics);
  o->heat = static_cast<HeatChoice>(heat);
  o->thermoelastic = static_cast<ThermoelasticChoice>(thermoelastic);
  PetscCall(CheckDriverOptions(comm, final_set, couple_set, o));
  PetscFunctionReturn(0);
}

double CouplingInterval(const DriverOptions& options, double source_frequency) {
  return options.couple_dt > 0.0 ? options.couple_dt : 1.0 / (8.0 * source_frequency);
}

}  // namespace vibrotherm::coupling
