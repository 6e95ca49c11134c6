#include "vibrotherm/coupling/run/heat_component.hpp"

#include <algorithm>

#include "vibrotherm/coupling/exchange/damping_heat_source.hpp"
#include "vibrotherm/coupling/exchange/thermal_stress.hpp"
#include "vibrotherm/coupling/exchange/thermoelastic_source.hpp"
#include "vibrotherm/coupling/exchange/thermoelastic_transfer.hpp"
#include "vibrotherm/heat/crack_power.hpp"
#include "vibrotherm/util/timed_stage.hpp"

namespace vibrotherm::coupling {

HeatComponent::HeatComponent() = default;
HeatComponent::~HeatComponent() {
  (void)VecDestroy(&load_);
  (void)VecDestroy(&defect_load_);
  (void)VecDestroy(&crack_load_);
}

PetscErrorCode HeatComponent::Setup(const mesh::Specimen& specimen, const Scene& scene, WaveComponent* waves,
                                    io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.heat);
  TimedStage stage;
  PetscCall(stage.Begin("Heat setup"));
  PetscCall(solver_.Setup(specimen.heat, scene.heat));
  summary->dofs_heat = solver_.dofs();
  if (solver_.coupled_stiffness_ratio() >= 0.0 && scene.run.physics != PhysicsChoice::Heat) {
    summary->derived["heat_stiffness_ratio"] = solver_.coupled_stiffness_ratio();
    summary->derived_rules["heat_stiffness_ratio"] =
        "max K_ii heat_dt / M_ii: up to 10 the coupled heat steps' CG takes Jacobi, not BoomerAMG (when not direct)";
  }
  const PetscInt ncracks = static_cast<PetscInt>(specimen.cracks.size());
  if (scene.run.physics == PhysicsChoice::Heat) {
    PetscCheck(ncracks > 0 || scene.run.heat_crack_power == 0.0, comm, PETSC_ERR_USER_INPUT,
               "-heat_crack_power needs a crack (-crack_center or crack curves in -mesh_file)");
    const std::vector<double> power(ncracks, scene.run.heat_crack_power);
    PetscCall(DMCreateGlobalVector(specimen.heat, &crack_load_));
    PetscCall(heat::CrackPowerLoad(solver_.space(), power, crack_load_));
    PetscCall(solver_.SetSourceLoad(crack_load_));
  } else if (waves && waves->crack()) {
    auto friction = std::make_unique<FrictionHeatSource>();
    PetscCall(friction->Setup(waves->crack(), waves->solver().space(), solver_.space(), specimen));
    friction_ = friction.get();
    sources_.push_back(std::move(friction));
  }
  if (waves && scene.run.thermoelastic != ThermoelasticChoice::Off) {
    PetscCall(SetupThermoelastic(scene, waves));
    // two_way: the thermal stress's stiffness may have shortened the wave step set up before.
    summary->derived["wave_dt"] = waves->solver().step().dt();
    summary->derived["wave_stable_dt"] = waves->solver().step().stable_dt();
  }
  if (waves && scene.material.damping_heat) {
    Mat D;
    PetscCall(AssembleDampingTransfer(waves->solver().space(), solver_.space(), &D));
    auto damping = std::make_unique<DampingHeatSource>();
    PetscCall(damping->Setup(&waves->solver(), D));
    PetscCall(MatDestroy(&D));
    sources_.push_back(std::move(damping));
  }
  PetscCall(DMCreateGlobalVector(specimen.heat, &load_));
  PetscCall(SetupDefectShare(scene));
  for (double s : scene.run.crack_probes) {
    const auto p = specimen.heat_cracks.line(scene.run.crack_probe_crack - 1).At(s);
    crack_probe_xy_.insert(crack_probe_xy_.end(), {p[0], p[1]});
  }
  std::vector<double> probes = scene.run.probe_points;
  probes.insert(probes.end(), crack_probe_xy_.begin(), crack_probe_xy_.end());
  PetscCall(probe_temperatures_.Setup(&solver_, probes));
  if (friction_ && scene.run.near_field)
    PetscCall(probe_temperatures_.SetupNearField(friction_->crack(), friction_->transfer(), scene.run.near_field_steps,
                                                 scene.couple_dt / scene.run.heat_substeps));
  PetscCall(stage.End(&summary->stages["heat_setup"]));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::SetupThermoelastic(const Scene& scene, WaveComponent* waves) {
  PetscFunctionBeginUser;
  const heat::HeatMaterial& m = scene.heat.material;
  const double beta = (3.0 * scene.material.lambda() + 2.0 * scene.material.shear_modulus()) * m.expansion;
  Mat B;
  PetscCall(AssembleThermoelasticTransfer(waves->solver().space(), solver_.space(), m.T0 * beta, &B));
  auto heating = std::make_unique<ThermoelasticSource>();
  PetscCall(heating->Setup(waves->solver(), B));
  sources_.push_back(std::move(heating));
  if (scene.run.thermoelastic == ThermoelasticChoice::TwoWay) {
    Vec c_inv;
    PetscCall(solver_.LumpedCapacityInverse(&c_inv));
    thermal_stress_ = std::make_unique<ThermalStress>();
    PetscCall(thermal_stress_->Setup(&waves->solver(), B, c_inv, solver_.rise(), m.T0));
    PetscCall(VecDestroy(&c_inv));
  }
  PetscCall(MatDestroy(&B));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::SetupDefectShare(const Scene& scene) {
  PetscFunctionBeginUser;
  const bool background = solver_.film_source() || std::any_of(sources_.begin(), sources_.end(), [this](const auto& s) {
                            return s.get() != friction_;
                          });
  const bool crack_heats = friction_ != nullptr || scene.run.physics == PhysicsChoice::Heat;
  defect_share_ = !crack_heats ? DefectShare::None : background ? DefectShare::Partial : DefectShare::Whole;
  if (defect_share_ != DefectShare::Partial) PetscFunctionReturn(0);
  PetscCall(solver_.EnablePartialRise());
  PetscCall(VecDuplicate(load_, &defect_load_));
  PetscCall(VecSet(defect_load_, 0.0));
  if (crack_load_) PetscCall(solver_.SetPartialLoad(crack_load_));  // -physics heat: the crack's given power
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::LoadSources(double t, bool averaged) {
  PetscFunctionBeginUser;
  PetscCall(VecSet(load_, 0.0));
  if (defect_load_) PetscCall(VecSet(defect_load_, 0.0));
  // Summed in the sources' order, the defect's share added where the friction's load falls.
  for (auto& source : sources_) {
    const bool defect = source.get() == friction_ && defect_load_;
    Vec into = defect ? defect_load_ : load_;
    if (averaged) PetscCall(source->AddAverageLoad(into));
    else PetscCall(source->AddLoad(t, t - solver_.time(), into));
    if (defect) PetscCall(VecAXPY(load_, 1.0, defect_load_));
  }
  if (defect_load_ && friction_) PetscCall(solver_.SetPartialLoad(defect_load_));
  PetscCall(solver_.SetSourceLoad(load_));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::StepTo(double t, bool sample_probes) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  if (!sources_.empty()) {
    PetscCall(LoadSources(t, false));
    for (auto& source : sources_) deposited_by_source_[source->name()] = source->deposited();
  }
  PetscCall(solver_.AdvanceInSteps(t, 1));
  if (sample_probes) PetscCall(SampleProbes());
  if (thermal_stress_) PetscCall(thermal_stress_->Update(solver_.rise(), t));
  seconds_ += MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::SampleProbes() {
  PetscFunctionBeginUser;
  if (friction_ && friction_->replaying()) probe_temperatures_.SampleFriction(solver_.time(), friction_->Dissipated(solver_.time()));
  PetscCall(probe_temperatures_.AfterHeatStep());
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::StopSources(const std::string& dir) {
  PetscFunctionBeginUser;
  if (thermal_stress_) PetscCall(thermal_stress_->Detach());
  thermal_stress_.reset();
  probe_temperatures_.StopNearField();
  if (sources_.empty()) PetscFunctionReturn(0);
  for (auto& source : sources_) PetscCall(source->Finish(dir));
  sources_.clear();
  friction_ = nullptr;
  PetscCall(VecSet(load_, 0.0));  // nothing heats any more
  PetscCall(solver_.SetSourceLoad(load_));
  if (defect_load_) PetscCall(solver_.SetPartialLoad(load_));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::Energy(io::EnergyRow* row) const {
  PetscFunctionBeginUser;
  heat::HeatAccounts accounts;
  PetscCall(solver_.Accounts(&accounts));
  row->heat_deposited = accounts.deposited;
  const auto by = [this](const char* name) {
    const auto it = deposited_by_source_.find(name);
    return it == deposited_by_source_.end() ? 0.0 : it->second;
  };
  row->heat_friction = by("friction");
  row->heat_thermoelastic = by("thermoelastic");
  row->heat_damping = by("damping");
  row->heat_boundary_loss = accounts.boundary_loss;
  row->heat_content = accounts.content;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::Summarise(io::RunSummary* summary) const {
  PetscFunctionBeginUser;
  summary->physics_ran.push_back("heat");
  summary->physics_time["heat"] = {0.0, solver_.time()};
  summary->steps_heat = solver_.steps();
  heat::HeatAccounts accounts;
  PetscCall(solver_.Accounts(&accounts));
  summary->heat_deposited = accounts.deposited;
  summary->heat_boundary_loss = accounts.boundary_loss;
  summary->heat_content = accounts.content;
  summary->stages["heat_steps"] = seconds_;
  for (const auto& [name, energy] : deposited_by_source_) summary->heat_deposited_by[name] = energy;
  if (deposited_by_source_.count("thermoelastic")) summary->physics_ran.push_back("thermoelastic");
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const {
  PetscFunctionBeginUser;
  PetscCall(solver_.Save(checkpoint, specimen.heat_origin));
  if (thermal_stress_) PetscCall(thermal_stress_->Save(checkpoint, specimen));
  for (const auto& source : sources_) PetscCall(source->Save(checkpoint, specimen));
  PetscCall(probe_temperatures_.Save(checkpoint, friction_ ? friction_->CellKeys(specimen) : std::vector<long long>{}));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  PetscCall(solver_.Restore(checkpoint, specimen.heat_origin));
  if (thermal_stress_) PetscCall(thermal_stress_->Restore(checkpoint, specimen));
  for (auto& source : sources_) {
    PetscCall(source->Restore(checkpoint, specimen));
    if (solver_.steps() > 0) deposited_by_source_[source->name()] = source->deposited();
  }
  PetscCall(probe_temperatures_.Restore(checkpoint, friction_ ? friction_->CellKeys(specimen) : std::vector<long long>{}));
  PetscFunctionReturn(0);
}

bool HeatComponent::replayable() const {
  return !thermal_stress_ &&
         std::all_of(sources_.begin(), sources_.end(), [](const auto& source) { return source->replayable(); });
}

PetscErrorCode HeatComponent::StartRecording(double t) {
  PetscFunctionBeginUser;
  for (auto& source : sources_) PetscCall(source->StartRecording(t));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::StopRecording() {
  PetscFunctionBeginUser;
  for (auto& source : sources_) PetscCall(source->StopRecording());
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::Replay(ReplayMode mode) {
  PetscFunctionBeginUser;
  for (auto& source : sources_) PetscCall(source->Replay(mode));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::StepAveraged(double t) {
  PetscFunctionBeginUser;
  const double t0 = MPI_Wtime();
  PetscCall(LoadSources(t, true));
  PetscCall(solver_.AdvanceInSteps(t, 1));
  seconds_ += MPI_Wtime() - t0;
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::SolverSnapshot(const mesh::Specimen& specimen, store::Checkpoint* snapshot) const {
  PetscFunctionBeginUser;
  PetscCall(solver_.Save(*snapshot, specimen.heat_origin));
  snapshot->IndexLocal();
  PetscFunctionReturn(0);
}

PetscErrorCode HeatComponent::RestoreSolver(const store::Checkpoint& snapshot, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  PetscCall(solver_.Restore(snapshot, specimen.heat_origin));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
