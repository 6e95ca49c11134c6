#include "vibrotherm/coupling/exchange/heat_sources.hpp"

#include "vibrotherm/coupling/exchange/replay_checkpoint.hpp"

namespace vibrotherm::coupling {

PetscErrorCode AddEnergyLoad(Vec E, double interval, Vec Q, double* deposited) {
  PetscFunctionBeginUser;
  PetscScalar energy;
  PetscCall(VecSum(E, &energy));
  *deposited += PetscRealPart(energy);
  PetscCall(VecAXPY(Q, 1.0 / interval, E));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeatSource::Setup(interface::CrackInterface* crack, const fe::LagrangeSpace& wave_space,
                                         const fe::LagrangeSpace& heat_space, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  crack_ = crack;
  comm_ = PetscObjectComm((PetscObject)heat_space.dm());
  PetscCall(transfer_.Setup(*crack, wave_space, specimen.wave_cracks, heat_space, specimen.heat_cracks,
                            specimen.crack_face_subdivisions));
  PetscFunctionReturn(0);
}

std::vector<double> FrictionHeatSource::Dissipated(double t) const {
  return mode_ == ReplayMode::Off ? crack_->dissipated_per_area() : replay_.At(t, mode_);
}

PetscErrorCode FrictionHeatSource::AddLoad(double t, double interval, Vec Q) {
  PetscFunctionBeginUser;
  const std::vector<double> W = Dissipated(t);
  PetscCall(transfer_.AddLoad(W, interval, Q));
  if (replay_.recording()) replay_.Sample(t, W);
  record_.Append(t, transfer_);
  // Σ w q Δt over the cells: exactly the energy the transfer moved in this step.
  double local = 0.0, step;
  for (std::size_t i = 0; i < crack_->cells().size(); ++i)
    local += crack_->cells()[i].weight * transfer_.density()[i] * interval;
  PetscCallMPI(MPI_Allreduce(&local, &step, 1, MPI_DOUBLE, MPI_SUM, comm_));
  deposited_ += step;
  PetscFunctionReturn(0);
}

void ReplayableHeatSource::SaveExchange(store::Checkpoint& checkpoint, const std::string& name,
                                        const std::vector<long long>& keys, const char* values_key,
                                        const std::vector<double>& values) const {
  checkpoint.PutShared(name + "/deposited", {deposited_});
  PutReplay(checkpoint, name, keys, replay_, mode_);  // a periodic recording, under way or replayed
  checkpoint.PutKeyed(name + "/" + values_key, keys, 1, values);
}

PetscErrorCode ReplayableHeatSource::RestoreExchange(const store::Checkpoint& checkpoint, const std::string& name,
                                                     const std::vector<long long>& keys, const char* values_key,
                                                     std::vector<double>* values) {
  PetscFunctionBeginUser;
  std::vector<double> deposited;
  PetscCall(checkpoint.GetShared(name + "/deposited", &deposited, 1));
  deposited_ = deposited[0];
  PetscCall(GetReplay(checkpoint, name, keys, &replay_, &mode_));
  PetscCall(checkpoint.GetKeyed(name + "/" + values_key, keys, 1, values));
  PetscFunctionReturn(0);
}

PetscErrorCode ReplayableHeatSource::StartRecording(double t) {
  PetscFunctionBeginUser;
  replay_.Start(t, Cumulative());
  PetscFunctionReturn(0);
}

PetscErrorCode ReplayableHeatSource::StopRecording() {
  PetscFunctionBeginUser;
  replay_.Stop();
  PetscFunctionReturn(0);
}

PetscErrorCode ReplayableHeatSource::Replay(ReplayMode mode) {
  PetscFunctionBeginUser;
  PetscCheck(mode == ReplayMode::Off || !replay_.empty(), comm(), PETSC_ERR_ORDER, "%s heat: nothing recorded to replay",
             name());
  mode_ = mode;
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeatSource::AddAverageLoad(Vec Q) {
  PetscFunctionBeginUser;
  std::vector<double> rates = replay_.increase();
  for (double& r : rates) r /= replay_.span();
  PetscCall(transfer_.AddRates(rates, Q));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeatSource::Finish(const std::string& dir) {
  PetscFunctionBeginUser;
  PetscCall(record_.Write(comm_, dir + "/crack_heat.h5", transfer_));
  crack_ = nullptr;
  PetscFunctionReturn(0);
}

std::vector<long long> FrictionHeatSource::CellKeys(const mesh::Specimen& specimen) const {
  std::vector<long long> keys;
  for (const interface::ContactCell& c : crack_->cells()) keys.push_back(specimen.wave_origin[c.plus]);
  return keys;
}

PetscErrorCode FrictionHeatSource::Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const {
  PetscFunctionBeginUser;
  const std::vector<long long> keys = CellKeys(specimen);
  record_.Save(checkpoint, keys);
  SaveExchange(checkpoint, "friction_heat", keys, "previous", transfer_.previous());
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeatSource::Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  const std::vector<long long> keys = CellKeys(specimen);
  PetscCall(record_.Restore(checkpoint, keys));
  // The energies the last exchange took (the interface's, or a replay's during a periodic continuation).
  std::vector<double> previous;
  PetscCall(RestoreExchange(checkpoint, "friction_heat", keys, "previous", &previous));
  transfer_.set_previous(previous);
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
