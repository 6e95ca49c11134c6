// The explicit wave step: dt < (ω dt)_max / ω_max, with ω_max² ≤ ω_bulk² +
// ω_contact² (Weyl: the crack adds a positive semidefinite stiffness).
//   bulk     ω_bulk from SLEPc, once (plus a bound of any body force's stiffness:
//            the two-way thermal stress);
//   contact  ω_contact² from the crack interface's current tangent stiffness.
// Rule -wave_contact_step:
//   current     (default) the step starts from the contact as it is (the
//               initial approach); the first step after which cfl × the limit
//               falls below it, it shrinks to the smaller of 90 % of itself and
//               cfl × the limit at twice the current contact stiffness. The
//               check after every step is exact (the Weyl bound; one reduction
//               of a scalar); a run sees a few reductions (summary.json);
//   worst_case  the step starts from every cell pressed twice the source
//               amplitude beyond its initial approach (the rule before issue 17;
//               safe but several times smaller than needed in the paper scene).
// Steps are rounded down to 4 significant digits so that runs on different rank
// counts (whose eigenvalue solves differ in the last digits) share a time grid;
// with a quantum q (WaveOptions::step_quantum: the heat step of a periodic
// source) every step is q/n for a whole n, so that source periods end on steps.
#pragma once

#include <petscsys.h>

#include <vector>

namespace vibrotherm::wave {

enum class ContactStepRule { kCurrent, kWorstCase };

class StepControl {
 public:
  /// omega_dt_max = 0: an implicit type (no limit). fixed_dt > 0: the user's step.
  PetscErrorCode Setup(MPI_Comm comm, double omega_max, double omega_dt_max, double cfl, double fixed_dt,
                       const char* ts_type, double quantum = 0.0);
  /// The initial step with the contact stiffness omega2 (rule's state) included.
  void IncludeContact(double omega2);
  /// A stiffness added to the bulk (a body force's, bounded by omega2): ω_bulk² += omega2,
  /// the step shrinks if it must (refused when -wave_dt is given and no longer stable).
  PetscErrorCode IncludeBulkStiffness(double omega2, const char* what);
  /// After a step, with the contact's current omega2: *changed when the step shrank. With a
  /// quantum, off a quantum boundary (at_quantum false) a step still within the stability limit
  /// is kept until the boundary, so that quanta stay whole numbers of steps.
  PetscErrorCode Check(double omega2, double time, PetscInt steps, bool at_quantum, bool* changed);
  double quantum() const { return quantum_; }
  double dt() const { return dt_; }
  double stable_dt() const { return stable_dt_; }
  double omega_dt_max() const { return omega_dt_max_; }
  bool implicit() const { return omega_dt_max_ <= 0.0; }
  PetscInt reductions() const { return reductions_; }
  /// Its state (step, limit, reductions) as numbers, and back (checkpoints).
  std::vector<double> state() const { return {dt_, stable_dt_, static_cast<double>(reductions_)}; }
  void set_state(const std::vector<double>& s) {
    dt_ = s.at(0), stable_dt_ = s.at(1), reductions_ = static_cast<PetscInt>(s.at(2));
  }
  /// Local time stepping: the step is the macro step H, fixed (the contact's level changes instead).
  void UseMacroStep(double H) { dt_ = H; }
  /// Rounded down to 4 significant digits.
  static double RoundDown(double raw);
  /// The largest q/n (n whole) not above RoundDown(raw); RoundDown(raw) itself when q <= 0.
  static double Quantized(double raw, double q);

 private:
  double Limit(double omega2) const;  ///< (ω dt)_max / √(ω_bulk² + omega2)
  MPI_Comm comm_ = MPI_COMM_NULL;
  double omega_max_ = 0.0, omega_dt_max_ = 0.0, cfl_ = 0.9, fixed_dt_ = 0.0, quantum_ = 0.0;
  double dt_ = 0.0, stable_dt_ = 0.0;
  double contact_omega2_ = 0.0;  ///< the contact's in the initial step (IncludeContact)
  PetscInt reductions_ = 0;
};

}  // namespace vibrotherm::wave
