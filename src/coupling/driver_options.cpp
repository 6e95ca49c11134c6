#include "vibrotherm/coupling/driver_options.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace vibrotherm::coupling {

PetscErrorCode ReadDriverOptions(MPI_Comm comm, DriverOptions* o) {
  PetscFunctionBeginUser;
  PetscReal points[256], fractions[64], times[64];
  PetscInt npoints = 256, nfractions = 64, ntimes = 64;
  PetscBool has_points = PETSC_FALSE, has_fractions = PETSC_FALSE, has_times = PETSC_FALSE;
  char physics[32] = "all", heat[32] = "auto";
  PetscOptionsBegin(comm, nullptr, "Run control and recording", nullptr);
  PetscCall(PetscOptionsString("-physics", "Physics to run: all (waves, contact, heat as the scene needs), wave, heat",
                               nullptr, physics, physics, sizeof(physics), nullptr));
  PetscCall(PetscOptionsString("-heat", "Heat solver: auto (when friction can dissipate), on, off", nullptr, heat, heat,
                               sizeof(heat), nullptr));
  PetscCall(PetscOptionsReal("-heat_crack_power", "-physics heat: power per unit crack area on every crack [W/m^2]",
                             nullptr, o->heat_crack_power, &o->heat_crack_power, nullptr));
  PetscCall(PetscOptionsReal("-final_time", "Simulated time [s] (default: the source duration)", nullptr,
                             o->final_time, &o->final_time, nullptr));
  PetscCall(PetscOptionsReal("-couple_dt", "Heat coupling interval [s] (default: 1/8 of the source period)", nullptr,
                             o->couple_dt, &o->couple_dt, nullptr));
  PetscCall(PetscOptionsReal("-wave_quiet_fraction",
                             "Waves stop after the source once, for a whole period, the mechanical energy left "
                             "(a bound on the heat still to come) is below this fraction of the energy dissipated "
                             "(of its peak when nothing dissipates); 0: never",
                             nullptr, o->quiet_fraction, &o->quiet_fraction, nullptr));
  PetscCall(PetscOptionsRealArray("-output_times", "Times of the fields in fields.h5 [s]", nullptr, times, &ntimes,
                                  &has_times));
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
  const std::map<std::string, PhysicsChoice> physics_choices = {
      {"all", PhysicsChoice::All}, {"wave", PhysicsChoice::Wave}, {"heat", PhysicsChoice::Heat}};
  const std::map<std::string, HeatChoice> heat_choices = {
      {"auto", HeatChoice::Auto}, {"on", HeatChoice::On}, {"off", HeatChoice::Off}};
  PetscCheck(physics_choices.count(physics), comm, PETSC_ERR_USER_INPUT,
             "-physics: unknown value '%s' (all, wave, heat)", physics);
  PetscCheck(heat_choices.count(heat), comm, PETSC_ERR_USER_INPUT, "-heat: unknown value '%s' (auto, on, off)", heat);
  o->physics = physics_choices.at(physics);
  o->heat = heat_choices.at(heat);
  o->crack_probes.assign(fractions, fractions + (has_fractions ? nfractions : 0));
  for (double s : o->crack_probes)
    PetscCheck(s >= 0.0 && s <= 1.0, comm, PETSC_ERR_USER_INPUT, "-crack_probe: fractions must be in [0, 1], got %g", s);
  o->output_times.assign(times, times + (has_times ? ntimes : 0));
  std::sort(o->output_times.begin(), o->output_times.end());
  for (double t : o->output_times)
    PetscCheck(t >= 0.0, comm, PETSC_ERR_USER_INPUT, "-output_times: times must be >= 0, got %g", t);
  PetscCheck(o->crack_state_every >= 0, comm, PETSC_ERR_USER_INPUT, "-crack_state_every must be >= 0");
  PetscCheck(o->energy_every >= 1, comm, PETSC_ERR_USER_INPUT, "-energy_every must be >= 1");
  PetscCheck(o->probe_every >= 1, comm, PETSC_ERR_USER_INPUT, "-probe_every must be >= 1");
  PetscCheck(o->quiet_fraction >= 0.0 && o->quiet_fraction < 1.0, comm, PETSC_ERR_USER_INPUT,
             "-wave_quiet_fraction must be in [0, 1), got %g", o->quiet_fraction);
  PetscCheck(o->heat_crack_power >= 0.0, comm, PETSC_ERR_USER_INPUT, "-heat_crack_power must be >= 0, got %g",
             o->heat_crack_power);
  o->probe_points.assign(points, points + (has_points ? npoints : 0));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
