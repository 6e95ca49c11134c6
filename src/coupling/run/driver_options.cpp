#include "vibrotherm/coupling/run/driver_options.hpp"

#include <algorithm>


namespace vibrotherm::coupling {

const std::vector<OptionSpec<DriverOptions>>& DriverOptionSpecs() {
  using D = DriverOptions;
  using contact::Range;
  const Range at_least_one = Range::at_least(1.0), non_negative = Range::at_least(0.0);
  static const std::vector<OptionSpec<D>> specs = {
      ChoiceOption("-physics", &D::physics, {"all", "wave", "heat"},
                   "Physics to run: all (waves, contact, heat as the scene needs), wave, heat"),
      ChoiceOption("-heat", &D::heat, {"auto", "on", "off"}, "Heat solver: auto (when friction can dissipate), on, off"),
      ChoiceOption("-thermoelastic", &D::thermoelastic, {"off", "one_way", "two_way"},
                   "Thermoelastic coupling: heating of the waves -T0 beta tr(eps_dot) (one_way: waves -> heat); "
                   "two_way: also the thermal stress -beta theta I on the waves (thermoelastic damping)"),
      RealOption("-heat_crack_power", &D::heat_crack_power, non_negative, "W/m^2",
                 "-physics heat: power per unit crack area on every crack"),
      GivenRealOption("-final_time", &D::final_time, Range::positive(), "s",
                      "Simulated time (default: the source duration)"),
      GivenRealOption("-couple_dt", &D::couple_dt, Range::positive(), "s",
                      "Heat coupling interval (default: 1/8 of the source period)"),
      IntOption("-heat_substeps", &D::heat_substeps, at_least_one,
                "Heat steps per coupling interval, each with the friction energy dissipated within it"),
      FlagOption("-heat_near_field", &D::near_field,
                 "Probes within reach of a crack add the friction heat of the last heat steps at wave-step "
                 "resolution, exactly (the heat mesh smooths the pulses)"),
      IntOption("-heat_near_field_steps", &D::near_field_steps, at_least_one,
                "Heat steps whose friction heat the crack probes take exactly (-heat_near_field)"),
      // PETSc counts steps in a PetscInt: a larger count would wrap around (a run "done in 1 step").
      RealOption("-max_steps", &D::max_steps, Range::between(1.0, static_cast<double>(PETSC_MAX_INT)), "",
                 "Largest number of wave steps a run may take (refused at setup with the estimate; at most PETSc's "
                 "step counter)"),
      RealOption("-checkpoint_every_s", &D::checkpoint_every_s, non_negative, "s",
                 "Wall seconds between checkpoints (DIR/checkpoint.h5, for -restart DIR) while the waves run; "
                 "0: only when SIGTERM, SIGINT or SIGUSR1 stops the run"),
      RealOption("-wave_quiet_fraction", &D::quiet_fraction, Range::closed_open(0.0, 1.0), "",
                 "Waves stop after the source once, for a whole period, the mechanical energy left "
                 "(a bound on the heat still to come) is below this fraction of the energy dissipated "
                 "(of its peak when nothing dissipates); 0: never"),
      RealListOption<D>("-output_times", &D::output_times, non_negative, "s", "Times of the fields in fields.h5"),
      IntOption<D>("-energy_every", &D::energy_every, at_least_one, "Steps between rows of energy.csv"),
      IntOption<D>("-probe_every", &D::probe_every, at_least_one, "Steps between rows of probes.csv"),
      RealListOption<D>("-probe_points", &D::probe_points, Range::any(), "m",
                        "Probe points x1,y1,x2,y2,... (3D: x1,y1,z1,...)"),
      RealListOption<D>("-crack_probe", &D::crack_probes, Range::between(0.0, 1.0), "",
                        "Crack probes: fractions of the crack length (0.5: centre)"),
      IntOption<D>("-crack_probe_crack", &D::crack_probe_crack, at_least_one,
                   "Crack of the crack probes (cracks are numbered from 1)"),
      IntOption<D>("-crack_state_every", &D::crack_state_every, non_negative,
                   "Steps between crack_state.csv records (0: none)"),
  };
  return specs;
}

PetscErrorCode ReadDriverOptions(MPI_Comm comm, DriverOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "Run control and recording", DriverOptionSpecs(), o, values));
  // Checked here, not only when the recorder opens probes.csv (the output directory exists by then).
  PetscCheck(o->probe_points.size() % o->dimension == 0, comm, PETSC_ERR_USER_INPUT,
             "-probe_points needs %s, got %zu numbers", o->dimension == 2 ? "x,y pairs" : "x,y,z triples in 3D",
             o->probe_points.size());
  std::sort(o->output_times.begin(), o->output_times.end());
  PetscFunctionReturn(0);
}

double CouplingInterval(const DriverOptions& options, double source_frequency) {
  return options.couple_dt > 0.0 ? options.couple_dt : 1.0 / (8.0 * source_frequency);
}

}  // namespace vibrotherm::coupling
