#include "vibrotherm/io/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vibrotherm::io {

std::string StepCount(long long steps, double t, double t_end, double dt) {
  char text[160];
  if (t >= t_end)  // the waves outlast their expected end: no count to show
    std::snprintf(text, sizeof(text), "step %lld, past the expected end (t = %.4g s): the waves are not quiet yet", steps,
                  t_end);
  else
    std::snprintf(text, sizeof(text), "step %lld/%.0f", steps, static_cast<double>(steps) + std::ceil((t_end - t) / dt));
  return text;
}

std::string StepShare(long long steps, double left) {
  const double total = static_cast<double>(steps) + std::ceil(std::max(0.0, left));
  char text[96];
  std::snprintf(text, sizeof(text), "step %lld/%.0f (%.1f %%)", steps, total,
                total > 0.0 ? 100.0 * static_cast<double>(steps) / total : 100.0);
  return text;
}

void Progress::Start(MPI_Comm comm, std::string label, double t_begin, double t_end, double dt, bool log_time) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  speaker_ = rank == 0;
  label_ = std::move(label);
  t_begin_ = t_begin;
  t_end_ = t_end;
  dt_ = dt;
  counts_steps_ = dt > 0.0;
  log_time_ = log_time && t_begin > 0.0;
  wall_start_ = wall_last_ = MPI_Wtime();
  steps_start_ = steps_last_ = steps_printed_ = -1;
  outlook_steps_ = -1.0;
  outlook_note_.clear();
}

void Progress::SetOutlook(double steps, long long at, std::string note) {
  outlook_steps_ = steps;
  outlook_at_ = at;
  outlook_note_ = std::move(note);
}

double Progress::Fraction(double t) const {
  if (t_end_ <= t_begin_) return 1.0;
  const double f = log_time_ ? std::log(t / t_begin_) / std::log(t_end_ / t_begin_) : (t - t_begin_) / (t_end_ - t_begin_);
  return std::clamp(f, 0.0, 1.0);
}

PetscErrorCode Progress::Update(double t, long long steps) {
  PetscFunctionBeginUser;
  if (steps_start_ < 0) steps_start_ = steps;
  // The step now, from the last step taken: the contact may have shrunk it since Start. Only
  // for a phase that counts steps (started with a step): a heat phase has none to count.
  if (counts_steps_ && steps > steps_last_ && steps_last_ >= 0 && t > t_last_) dt_ = (t - t_last_) / static_cast<double>(steps - steps_last_);
  steps_last_ = steps, t_last_ = t;
  const double now = MPI_Wtime();
  if (!speaker_ || now - wall_last_ < 2.0) PetscFunctionReturn(0);
  // The rate over about the last 10 s (a busy machine's speed changes; the first line: since Start).
  const double recent = (steps - steps_printed_) / (now - wall_last_);
  rate_ = steps_printed_ < 0 ? (steps - steps_start_) / (now - wall_start_)
                             : rate_ + (recent - rate_) * (1.0 - std::exp(-(now - wall_last_) / 10.0));
  wall_last_ = now;
  steps_printed_ = steps;
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "%s\n", Line(t, steps, now - wall_start_).c_str()));
  PetscFunctionReturn(0);
}

std::string Progress::Line(double t, long long steps, double elapsed) const {
  if (counts_steps_) return WaveLine(t, steps);
  const double done = Fraction(t), eta = done > 0 ? elapsed * (1.0 - done) / done : 0.0;
  char text[256];
  std::snprintf(text, sizeof(text), "%s: t = %.4g s (%.1f %%%s), step %lld, ETA %.0f s", label_.c_str(), t,
                100.0 * done, log_time_ ? " in log time" : "", steps, eta);
  return text;
}

std::string Progress::WaveLine(double t, long long steps) const {
  const std::string note = outlook_note_.empty() ? "" : "; " + outlook_note_;
  char text[512];
  if (t >= t_end_ && outlook_steps_ < 0.0) {
    std::snprintf(text, sizeof(text), "%s: t = %.4g s, %s, %.3g steps/s%s", label_.c_str(), t,
                  StepCount(steps, t, t_end_, dt_).c_str(), rate_, note.c_str());
    return text;
  }
  const double resolved = std::ceil(std::max(0.0, t_end_ - t) / dt_);
  const double left = outlook_steps_ >= 0.0 ? std::max(0.0, outlook_steps_ - static_cast<double>(steps - outlook_at_))
                                            : resolved;
  char eta[96];
  if (outlook_steps_ >= 0.0)  // a continuation expected: when, and the bound without it
    std::snprintf(eta, sizeof(eta), "ETA ~%.0f s (resolved to the end: %.0f s)", left / rate_, resolved / rate_);
  else if (!outlook_note_.empty())  // it may become periodic and end sooner
    std::snprintf(eta, sizeof(eta), "ETA up to %.0f s (resolved to the end)", left / rate_);
  else
    std::snprintf(eta, sizeof(eta), "ETA %.0f s", left / rate_);
  std::snprintf(text, sizeof(text), "%s: t = %.4g s, %s, %.3g steps/s, %s%s", label_.c_str(), t,
                StepShare(steps, left).c_str(), rate_, eta, note.c_str());
  return text;
}

PetscErrorCode Progress::Done(double t, long long steps) {
  PetscFunctionBeginUser;
  if (!speaker_) PetscFunctionReturn(0);
  const double elapsed = MPI_Wtime() - wall_start_;
  PetscCall(PetscFPrintf(PETSC_COMM_SELF, PETSC_STDERR, "%s: done, t = %.4g s, %lld steps in %.2f s\n", label_.c_str(), t,
                         steps, elapsed));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
