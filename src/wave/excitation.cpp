#include "vibrotherm/wave/excitation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace vibrotherm::wave {

namespace {

/// The amplitude A(t) and its derivatives: sin² blends from each level to the next.
void Envelope(const SourceTimeFunction& f, double t, double* a, double* da, double* dda) {
  *a = f.amplitude, *da = *dda = 0.0;
  const double blend = f.blend_time(), k = M_PI / (2.0 * blend);
  for (const SourceTimeFunction::Step& step : f.schedule) {
    if (t <= step.t) break;
    const double from = *a, jump = step.amplitude - from, tau = t - step.t;
    if (tau >= blend) {
      *a = step.amplitude, *da = *dda = 0.0;
      continue;
    }
    *a = from + jump * std::sin(k * tau) * std::sin(k * tau);
    *da = jump * k * std::sin(2.0 * k * tau);
    *dda = jump * 2.0 * k * k * std::cos(2.0 * k * tau);
  }
}

}  // namespace

double SourceTimeFunction::ramp_time() const {
  const double slowest = sweeping() ? std::min(sweep_from, sweep_to) : frequency;
  return std::min(ramp_cycles / slowest, 0.5 * duration);
}

double SourceTimeFunction::cycles(double t) const {
  if (!sweeping()) return frequency * t;
  return sweep_from * t + 0.5 * (sweep_to - sweep_from) * t * t / duration;
}

double SourceTimeFunction::frequency_at(double t) const {
  return sweeping() ? sweep_from + (sweep_to - sweep_from) * t / duration : frequency;
}

double SourceTimeFunction::time_of_cycle(double n) const {
  if (!sweeping()) return n / frequency;
  // c(t) = n: the root of (F2 − F1)/(2T) t² + F1 t − n = 0 with t ≥ 0, in the form that
  // stays exact when F2 → F1.
  const double a = 0.5 * (sweep_to - sweep_from) / duration, b = sweep_from;
  return 2.0 * n / (b + std::sqrt(std::max(0.0, b * b + 4.0 * a * n)));
}
double SourceTimeFunction::blend_time() const { return std::max(ramp_cycles, 1.0) / frequency; }

bool SourceTimeFunction::steady_stretch(double t, double* start, double* end) const {
  if (sweeping()) {  // a sweep never repeats itself
    *start = *end = 0.0;
    return false;
  }
  double from = running_at_start ? 0.0 : ramp_time();
  for (const Step& step : schedule) {
    if (t < step.t) break;
    from = step.t + blend_time();
  }
  double to = duration - ramp_time();
  for (const Step& step : schedule)
    if (step.t >= t) {
      to = std::min(to, step.t);
      break;
    }
  *start = from, *end = to;
  return t >= from && t <= to && to > from;
}

void SourceTimeFunction::window(double t, double* win, double* dwin, double* ddwin) const {
  *win = 1.0, *dwin = *ddwin = 0.0;
  if (t <= 0.0 || t >= duration) {
    *win = 0.0;
    return;
  }
  // sin²(π τ / (2 T_r)), τ the time from the nearer end.
  const double ramp = ramp_time();
  if (ramp > 0.0 && ((t < ramp && !running_at_start) || t > duration - ramp)) {
    const bool on = t < ramp;
    const double tau = on ? t : duration - t, sign = on ? 1.0 : -1.0, k = M_PI / (2.0 * ramp);
    *win = std::sin(k * tau) * std::sin(k * tau);
    *dwin = sign * k * std::sin(2.0 * k * tau);
    *ddwin = 2.0 * k * k * std::cos(2.0 * k * tau);
  }
}

double SourceTimeFunction::envelope(double t) const {
  double win, dwin, ddwin, a, da, dda;
  window(t, &win, &dwin, &ddwin);
  Envelope(*this, t, &a, &da, &dda);
  return a * win;
}

void SourceTimeFunction::evaluate(double t, double* g, double* dg, double* ddg) const {
  *g = *dg = *ddg = 0.0;
  if (t <= 0.0 || t >= duration) return;
  double win, dwin, ddwin;
  window(t, &win, &dwin, &ddwin);
  // g = A · (s · win): the carrier sin(φ), φ = 2π cycles(t), times the window, then the
  // amplitude's product rule (a sweep's φ'' = 2π (F2 − F1) / T; a constant frequency's 0).
  // (A constant frequency keeps the product w · t: its outputs stay bit for bit what they were.)
  const double w = 2.0 * M_PI * frequency_at(t), phase = sweeping() ? 2.0 * M_PI * cycles(t) : w * t;
  const double dw = sweeping() ? 2.0 * M_PI * (sweep_to - sweep_from) / duration : 0.0;
  const double s = std::sin(phase), c = std::cos(phase);
  const double h = s * win, dh = w * c * win + s * dwin;
  const double ddh = (dw * c - w * w * s) * win + 2.0 * w * c * dwin + s * ddwin;
  double a, da, dda;
  Envelope(*this, t, &a, &da, &dda);
  *g = a * h;
  *dg = a * dh + da * h;
  *ddg = a * ddh + 2.0 * da * dh + dda * h;
}

namespace {

/// -source_schedule pairs in time order, each change after the switch-on and done before the switch-off.
PetscErrorCode SetSchedule(MPI_Comm comm, const std::vector<double>& values, SourceTimeFunction* f) {
  PetscFunctionBeginUser;
  PetscCheck(values.size() % 2 == 0, comm, PETSC_ERR_USER_INPUT,
             "-source_schedule needs t,A pairs (got %zu values)", values.size());
  f->schedule.clear();
  for (std::size_t i = 0; i < values.size(); i += 2) {
    const double t = values[i], previous = f->schedule.empty() ? f->ramp_time() : f->schedule.back().t + f->blend_time();
    PetscCheck(std::isfinite(t) && std::isfinite(values[i + 1]), comm, PETSC_ERR_USER_INPUT,
               "-source_schedule: pair %zu is not finite", i / 2 + 1);
    PetscCheck(t >= previous && t + f->blend_time() <= f->duration - f->ramp_time(), comm, PETSC_ERR_USER_INPUT,
               "-source_schedule: the step at t = %g s must come after the switch-on or the previous step's blend "
               "(%g s) and end its blend (%g s) before the switch-off at %g s",
               t, previous, f->blend_time(), f->duration - f->ramp_time());
    f->schedule.push_back({t, values[i + 1]});
  }
  PetscFunctionReturn(0);
}

/// -source_sweep F1,F2: both frequencies positive and different; the highest sets
/// -source_frequency's roles (coupling interval, mesh checks); no amplitude schedule with it.
PetscErrorCode SetSweep(MPI_Comm comm, const std::vector<double>& values, bool no_schedule, SourceTimeFunction* f) {
  PetscFunctionBeginUser;
  if (values.empty()) PetscFunctionReturn(0);
  PetscCheck(values.size() == 2, comm, PETSC_ERR_USER_INPUT, "-source_sweep needs two frequencies F1,F2 [Hz] (got %zu values)",
             values.size());
  PetscCheck(values[0] != values[1], comm, PETSC_ERR_USER_INPUT,
             "-source_sweep %g,%g: the two frequencies are equal (a constant frequency is -source_frequency)", values[0],
             values[1]);
  PetscCheck(no_schedule, comm, PETSC_ERR_USER_INPUT,
             "-source_sweep with -source_schedule: a sweep takes one amplitude (-source_amplitude)");
  PetscCheck(f->duration > 0.0, comm, PETSC_ERR_USER_INPUT, "-source_sweep needs -source_duration > 0");
  f->sweep_from = values[0];
  f->sweep_to = values[1];
  f->frequency = std::max(values[0], values[1]);
  PetscFunctionReturn(0);
}

}  // namespace

const std::vector<OptionSpec<ExcitationOptions>>& ExcitationOptionSpecs() {
  using O = ExcitationOptions;
  using contact::Range;
  const auto signal = [](const OptionSpec<SourceTimeFunction>& option) {
    return NestedOption(&O::excitation, NestedOption(&Excitation::signal, option));
  };
  static const std::vector<OptionSpec<O>> specs = {
      NestedOption(&O::excitation, ChoiceOption("-source_type", &Excitation::type, {"displacement", "traction"},
                                                "Source on the source edge")),
      NestedOption(&O::excitation, ChoiceOption("-source_component", &Excitation::component, {"tangential", "normal"},
                                                "Direction of the source to the source edge")),
      signal(RealOption("-source_frequency", &SourceTimeFunction::frequency, Range::positive(), "Hz", "Frequency")),
      signal(RealOption("-source_amplitude", &SourceTimeFunction::amplitude, Range::any(), "",
                        "Amplitude: displacement [m] or traction [Pa]")),
      signal(RealOption("-source_duration", &SourceTimeFunction::duration, Range::at_least(0.0), "s",
                        "Duration of the excitation")),
      signal(RealOption("-source_ramp_cycles", &SourceTimeFunction::ramp_cycles, Range::at_least(0.0), "",
                        "Cycles of smooth switch-on and switch-off")),
      RealListOption("-source_schedule", &O::schedule, Range::any(), "",
                     "Amplitude steps t1,A1,t2,A2,...: from t_i [s] on amplitude A_i (blended over "
                     "max(-source_ramp_cycles, 1) cycles)"),
      RealListOption("-source_sweep", &O::sweep, Range::positive(), "Hz",
                     "A frequency sweep F1,F2, linear in time over -source_duration (replaces -source_frequency)"),
  };
  return specs;
}

PetscErrorCode ReadExcitation(MPI_Comm comm, Excitation* e, OptionValues* values) {
  PetscFunctionBeginUser;
  ExcitationOptions o{*e, {}, {}};
  PetscCall(ReadOptionSpecs(comm, "Excitation on the source edge", ExcitationOptionSpecs(), &o, values));
  *e = o.excitation;
  PetscCall(SetSweep(comm, o.sweep, o.schedule.empty(), &e->signal));
  PetscCall(SetSchedule(comm, o.schedule, &e->signal));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
