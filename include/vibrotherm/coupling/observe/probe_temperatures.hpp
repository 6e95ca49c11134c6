// The probes' temperature at every row of probes.csv while the waves run. The
// heat solver knows its field at the heat steps only; a probe row between two
// of them reads the quadratic through the last three heat steps' values (the
// field's rise at the probe, 24 samples a period by default: a thermoelastic
// swing within 0.1 %), and a probe within reach of a crack adds the friction
// heat of the last heat steps at wave-step resolution (crack_near_field.hpp),
// which the heat mesh smooths.
#pragma once

#include <petscsys.h>

#include <deque>
#include <memory>
#include <vector>

#include "vibrotherm/coupling/exchange/crack_near_field.hpp"
#include "vibrotherm/heat/heat_probes.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/io/point_probes.hpp"

namespace vibrotherm::coupling {

class ProbeTemperatures {
 public:
  /// The probes at `points` (x, y pairs; x, y, z triples in 3D) of the heat solver's field. Collective.
  PetscErrorCode Setup(heat::HeatSolver* heat, const std::vector<double>& points);
  /// Friction heats: the crack's near field for the probes (K = steps heat steps,
  /// expected heat step length heat_step). Collective.
  PetscErrorCode SetupNearField(const interface::CrackInterface& crack, const FrictionHeat& friction, PetscInt steps,
                                double heat_step);
  /// The friction has stopped (the crack interface goes): the field alone from here on.
  void StopNearField() { near_.reset(); }
  const CrackNearField* near_field() const { return near_.get(); }
  /// After every wave step (ending at t); row: probes.csv has a row at t.
  void AfterWaveStep(double t, bool row);
  /// CrackNearField::Pause/Restart at the heat's time.
  void PauseNearField() {
    if (near_) near_->Pause(heat_->time());
  }
  void RestartNearField() {
    if (near_) near_->Restart(heat_->time());
  }
  /// The friction energies at t while a replay stands in for the waves (the near field's samples).
  void SampleFriction(double t, const std::vector<double>& W) {
    if (near_) near_->SampleEnergies(t, W);
  }
  /// After every heat step while the waves run: the rows it closes. Collective.
  PetscErrorCode AfterHeatStep();
  /// Temperatures [K] since the last call: at every row and heat step end while the
  /// waves run, else at the heat's time. Collective.
  PetscErrorCode Collect(io::TemperatureSeries* series);
  /// Checkpoints (between coupling intervals: no row pending): the last heat steps' values
  /// and the near field; and back. Collective.
  PetscErrorCode Save(store::Checkpoint& checkpoint, const std::vector<long long>& cell_keys) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const std::vector<long long>& cell_keys);

 private:
  // Everything per heat step is this rank's part (its dofs, its contact cells): the
  // ranks' parts are added once per coupling interval, in Collect.
  struct Sample {
    double t;
    std::vector<double> rise;  ///< the field's rise at each probe: this rank's part
  };
  struct Row {
    double t;
    std::vector<double> part;  ///< per probe: this rank's part of the rise
  };
  /// This rank's part of φ_pᵀθ for every probe (no communication).
  PetscErrorCode PartialRise(std::vector<double>* rise) const;
  /// The field's rise at the probes, on every rank. Collective.
  PetscErrorCode FieldRise(std::vector<double>* rise) const;
  std::vector<std::vector<std::pair<PetscInt, double>>> functionals_;  ///< per probe: (owned local row, weight)
  heat::HeatSolver* heat_ = nullptr;
  heat::HeatProbes probes_;  ///< the points located in the heat mesh
  std::unique_ptr<CrackNearField> near_;
  std::deque<Sample> samples_;  ///< the last three heat steps (t = 0 counts)
  std::vector<double> rows_;    ///< row times not yet closed by a heat step
  std::vector<Row> closed_;     ///< rows closed since the last Collect
};

}  // namespace vibrotherm::coupling
