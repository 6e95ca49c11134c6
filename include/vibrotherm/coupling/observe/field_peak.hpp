// The largest temperature rise over the whole heat field (every heat dof), at
// every heat step, with its time and place: summary.json
// field_max_temperature_rise and field_max_temperature_rise_at (not just probes).
#pragma once

#include <petscvec.h>

#include <array>

#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/io/run_summary.hpp"

namespace vibrotherm::coupling {

/// The rise [K] up to which constant conductivity, capacity and elastic
/// constants hold to about a percent (aluminium, steel): beyond it, a model-validity warning.
constexpr double kConstantPropertyRise = 10.0;

class FieldPeak {
 public:
  FieldPeak() = default;
  FieldPeak(const FieldPeak&) = delete;
  FieldPeak& operator=(const FieldPeak&) = delete;
  ~FieldPeak();
  /// The heat dofs' coordinates as global vectors (to say where the peak is). Collective.
  PetscErrorCode Setup(const fe::LagrangeSpace& space);
  /// One VecMax of the rise; the place is looked up only when the peak grows. A
  /// warning when it first exceeds the constant-property range. Collective.
  PetscErrorCode Update(const heat::HeatSolver& heat);
  /// The peak, and the warning when it left the constant-property range.
  void Summarise(io::RunSummary* summary) const;
  /// The peak so far (checkpoints).
  const io::FieldPeakSummary& peak() const { return peak_; }
  void set_peak(const io::FieldPeakSummary& peak) {
    peak_ = peak;
    peak_.dimension = dim_;
  }

 private:
  std::string ValidityWarning() const;
  std::array<Vec, 3> axes_ = {nullptr, nullptr, nullptr};  ///< node coordinates (z in 3D only)
  int dim_ = 2;
  io::FieldPeakSummary peak_;
};

}  // namespace vibrotherm::coupling
