#include "vibrotherm/wave/excitation.hpp"

#include "vibrotherm/util/option_choice.hpp"

#include <cmath>
#include <string>

namespace vibrotherm::wave {

void SourceTimeFunction::evaluate(double t, double* g, double* dg, double* ddg) const {
  *g = *dg = *ddg = 0.0;
  if (t <= 0.0 || t >= duration) return;
  const double w = 2.0 * M_PI * frequency;
  const double ramp = std::min(ramp_cycles / frequency, 0.5 * duration);
  // Window w(t) and its derivatives: sin²(π τ / (2 T_r)), τ the time from the nearer end.
  double win = 1.0, dwin = 0.0, ddwin = 0.0;
  if (ramp > 0.0 && (t < ramp || t > duration - ramp)) {
    const bool on = t < ramp;
    const double tau = on ? t : duration - t, sign = on ? 1.0 : -1.0, k = M_PI / (2.0 * ramp);
    win = std::sin(k * tau) * std::sin(k * tau);
    dwin = sign * k * std::sin(2.0 * k * tau);
    ddwin = 2.0 * k * k * std::cos(2.0 * k * tau);
  }
  const double s = std::sin(w * t), c = std::cos(w * t);
  *g = amplitude * s * win;
  *dg = amplitude * (w * c * win + s * dwin);
  *ddg = amplitude * (-w * w * s * win + 2.0 * w * c * dwin + s * ddwin);
}

PetscErrorCode ReadExcitation(MPI_Comm comm, Excitation* e) {
  PetscFunctionBeginUser;
  PetscInt type = e->type == SourceType::Displacement ? 0 : 1, component = e->component == SourceComponent::Tangential ? 0 : 1;
  PetscOptionsBegin(comm, nullptr, "Excitation on the source edge", nullptr);
  PetscCall(OptionsChoice(PetscOptionsObject, "-source_type", "Source on the source edge", {"displacement", "traction"},
                          &type, nullptr));
  PetscCall(OptionsChoice(PetscOptionsObject, "-source_component", "Direction of the source to the source edge",
                          {"tangential", "normal"}, &component, nullptr));
  PetscCall(PetscOptionsReal("-source_frequency", "Frequency [Hz]", nullptr, e->signal.frequency, &e->signal.frequency,
                             nullptr));
  PetscCall(PetscOptionsReal("-source_amplitude", "Amplitude: displacement [m] or traction [Pa]", nullptr,
                             e->signal.amplitude, &e->signal.amplitude, nullptr));
  PetscCall(PetscOptionsReal("-source_duration", "Duration of the excitation [s]", nullptr, e->signal.duration,
                             &e->signal.duration, nullptr));
  PetscCall(PetscOptionsReal("-source_ramp_cycles", "Cycles of smooth switch-on and switch-off", nullptr,
                             e->signal.ramp_cycles, &e->signal.ramp_cycles, nullptr));
  PetscOptionsEnd();
  e->type = type == 0 ? SourceType::Displacement : SourceType::Traction;
  e->component = component == 0 ? SourceComponent::Tangential : SourceComponent::Normal;
  PetscCheck(e->signal.frequency > 0.0, comm, PETSC_ERR_USER_INPUT, "-source_frequency must be > 0");
  PetscCheck(e->signal.duration >= 0.0, comm, PETSC_ERR_USER_INPUT, "-source_duration must be >= 0");
  PetscCheck(e->signal.ramp_cycles >= 0.0, comm, PETSC_ERR_USER_INPUT, "-source_ramp_cycles must be >= 0");
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
