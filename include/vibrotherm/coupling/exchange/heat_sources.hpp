// Exchanges into the heat equation: each source turns energy another physics
// deposited into a heat load, exactly (the energy of a heat step is the
// energy deposited in it). Adding a heating mechanism = one HeatSource.
#pragma once

#include <petscvec.h>

#include <string>

#include "vibrotherm/coupling/exchange/crack_heat_record.hpp"
#include "vibrotherm/coupling/exchange/friction_heat.hpp"
#include "vibrotherm/coupling/exchange/periodic_replay.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/mesh/specimen.hpp"

namespace vibrotherm::coupling {

/// A heat step's energy load E (heat dofs, J/m per dof) into Q as the rate E / interval, and its
/// total into *deposited. Collective.
PetscErrorCode AddEnergyLoad(Vec E, double interval, Vec Q, double* deposited);

class HeatSource {
 public:
  virtual ~HeatSource() = default;
  /// Q += the load [W/m per heat dof] of the energy deposited in the heat step (t − interval, t].
  virtual PetscErrorCode AddLoad(double t, double interval, Vec Q) = 0;
  /// The physics that fed it has stopped: write what it recorded into dir, let go of it.
  virtual PetscErrorCode Finish(const std::string& dir) = 0;
  /// Energy it has deposited so far [J/m].
  virtual double deposited() const = 0;
  /// Its name in summary.json and energy.csv (heat_<name>).
  virtual const char* name() const = 0;
  /// Checkpoints, taken right after a heat step: what it keeps that the
  /// physics it reads (restored before it) does not tell; and back.
  virtual PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const = 0;
  virtual PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) = 0;
  // Periodic continuation (periodic_continuation.hpp): a source that can replay what its
  // physics deposits over a recorded period, while that physics is suspended.
  virtual bool replayable() const { return false; }
  /// Records from t (a heat step's end) until StopRecording, sampling at every AddLoad ...
  virtual PetscErrorCode StartRecording(double /*t*/) { return PETSC_ERR_SUP; }
  virtual PetscErrorCode StopRecording() { return PETSC_ERR_SUP; }
  /// ... then deposits the recording periodically (phase-locked or averaged), or the live physics again (off).
  virtual PetscErrorCode Replay(ReplayMode /*mode*/) { return PETSC_ERR_SUP; }
  /// Q += the averaged replay's constant load [W/m per heat dof], exchanging nothing.
  virtual PetscErrorCode AddAverageLoad(Vec /*Q*/) { return PETSC_ERR_SUP; }
};

/// A source whose physics deposits a cumulative energy per item (a contact cell, a heat dof):
/// it records the items' cumulative energies over a period and replays them periodically.
class ReplayableHeatSource : public HeatSource {
 public:
  bool replayable() const override { return true; }
  PetscErrorCode StartRecording(double t) override;
  PetscErrorCode StopRecording() override;
  PetscErrorCode Replay(ReplayMode mode) override;
  bool replaying() const { return mode_ != ReplayMode::Off; }
  double deposited() const override { return deposited_; }

 protected:
  /// Checkpoints under `name`/: the energy deposited, the replay, and a value per item
  /// (`values_key`: what the source's next exchange starts from), keyed by `keys`; and back.
  void SaveExchange(store::Checkpoint& checkpoint, const std::string& name, const std::vector<long long>& keys,
                    const char* values_key, const std::vector<double>& values) const;
  PetscErrorCode RestoreExchange(const store::Checkpoint& checkpoint, const std::string& name,
                                 const std::vector<long long>& keys, const char* values_key,
                                 std::vector<double>* values);
  /// Each item's cumulative energy now, as the live physics has it (the recording's start).
  virtual std::vector<double> Cumulative() const = 0;
  virtual MPI_Comm comm() const = 0;
  PeriodicReplay replay_;
  ReplayMode mode_ = ReplayMode::Off;
  double deposited_ = 0.0;
};

/// Friction at the crack (crack law dissipation → line density on the crack),
/// recorded in crack_heat.h5.
class FrictionHeatSource final : public ReplayableHeatSource {
 public:
  PetscErrorCode Setup(interface::CrackInterface* crack, const fe::LagrangeSpace& wave_space,
                       const fe::LagrangeSpace& heat_space, const mesh::Specimen& specimen);
  PetscErrorCode AddLoad(double t, double interval, Vec Q) override;
  PetscErrorCode Finish(const std::string& dir) override;
  const char* name() const override { return "friction"; }
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const override;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) override;
  PetscErrorCode AddAverageLoad(Vec Q) override;
  const FrictionHeat& transfer() const { return transfer_; }
  /// Every owned cell's friction energy so far [J/m²] at t: the interface's, or the replay's.
  std::vector<double> Dissipated(double t) const;
  const interface::CrackInterface& crack() const { return *crack_; }
  /// Checkpoint keys of this rank's contact cells (their + point's origin).
  std::vector<long long> CellKeys(const mesh::Specimen& specimen) const;

 private:
  std::vector<double> Cumulative() const override { return crack_->dissipated_per_area(); }
  MPI_Comm comm() const override { return comm_; }
  interface::CrackInterface* crack_ = nullptr;
  FrictionHeat transfer_;
  CrackHeatRecord record_;
  MPI_Comm comm_ = MPI_COMM_NULL;
};

}  // namespace vibrotherm::coupling
