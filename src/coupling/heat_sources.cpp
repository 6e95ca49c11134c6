#include "vibrotherm/coupling/heat_sources.hpp"

namespace vibrotherm::coupling {

PetscErrorCode FrictionHeatSource::Setup(interface::CrackInterface* crack, const fe::LagrangeSpace& wave_space,
                                         const fe::LagrangeSpace& heat_space, PetscInt ncracks) {
  PetscFunctionBeginUser;
  crack_ = crack;
  comm_ = PetscObjectComm((PetscObject)heat_space.dm());
  PetscCall(transfer_.Setup(*crack, wave_space, heat_space, ncracks));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeatSource::AddLoad(double t, double interval, Vec Q) {
  PetscFunctionBeginUser;
  PetscCall(transfer_.AddLoad(crack_->dissipated_per_area(), interval, Q));
  record_.Append(t, transfer_);
  // Σ w q Δt over the cells: exactly the energy the transfer moved in this step.
  double local = 0.0, step;
  for (std::size_t i = 0; i < crack_->cells().size(); ++i)
    local += crack_->cells()[i].weight * transfer_.density()[i] * interval;
  PetscCallMPI(MPI_Allreduce(&local, &step, 1, MPI_DOUBLE, MPI_SUM, comm_));
  deposited_ += step;
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

PetscErrorCode FrictionHeatSource::Save(io::Checkpoint& checkpoint, const mesh::Specimen& specimen) const {
  PetscFunctionBeginUser;
  checkpoint.PutShared("friction_heat/deposited", {deposited_});
  record_.Save(checkpoint, CellKeys(specimen));
  PetscFunctionReturn(0);
}

PetscErrorCode FrictionHeatSource::Restore(const io::Checkpoint& checkpoint, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  std::vector<double> deposited;
  PetscCall(checkpoint.GetShared("friction_heat/deposited", &deposited, 1));
  deposited_ = deposited[0];
  PetscCall(record_.Restore(checkpoint, CellKeys(specimen)));
  // The last exchange took the energies the interface holds now (checkpoints follow a heat step).
  transfer_.set_previous(crack_->dissipated_per_area());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
