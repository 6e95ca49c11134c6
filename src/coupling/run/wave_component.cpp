#include "vibrotherm/coupling/run/wave_component.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "vibrotherm/coupling/continuation/saved_wave_state.hpp"
#include "vibrotherm/io/point_probes.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/util/stop_signals.hpp"
#include "vibrotherm/util/timed_stage.hpp"

namespace vibrotherm::coupling {
namespace {

/// Probe points are input too: all inside the specimen before anything is written.
PetscErrorCode CheckProbePoints(const fe::LagrangeSpace& space, const std::vector<double>& xyz) {
  PetscFunctionBeginUser;
  std::vector<fe::LocatedPoint> located;
  PetscCall(io::LocateProbePoints(space, xyz, &located));
  PetscFunctionReturn(0);
}

/// Worst-case approach of -wave_contact_step worst_case: twice the displacement
/// amplitude the source imposes (for a traction source, the displacement of a
/// plane S wave, A / (ρ c_s ω)).
double WorstCaseApproach(const Scene& scene) {
  const double omega = 2.0 * M_PI * scene.excitation.signal.frequency;
  const double amplitude = scene.excitation.type == wave::SourceType::Displacement
                               ? scene.excitation.signal.amplitude
                               : scene.excitation.signal.amplitude / (scene.material.density * scene.material.cs() * omega);
  return 2.0 * std::abs(amplitude);
}

/// Scenes that run but cannot mean what their user wants: said once, at setup.
PetscErrorCode WarnAboutTheSource(DM dm, const Scene& scene, double dt) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt faces = 0, total;
  PetscBool has;
  PetscCall(DMHasLabel(dm, "source", &has));
  if (has) PetscCall(DMGetStratumSize(dm, "source", 1, &faces));
  PetscCallMPI(MPI_Allreduce(&faces, &total, 1, MPIU_INT, MPI_SUM, comm));
  if (total == 0)
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: the specimen has no source edge (-edge_* source, or a 'source' "
                                "curve in -mesh_file): nothing excites the waves\n"));
  const double steps_per_period = 1.0 / (scene.excitation.signal.frequency * dt);
  if (steps_per_period < 10.0)
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: -source_frequency %g Hz: a period is only %.3g wave steps of %g s; "
                                "the source is not resolved (refine the time step with -wave_cfl or -wave_dt)\n",
                          scene.excitation.signal.frequency, steps_per_period, dt));
  PetscFunctionReturn(0);
}

/// Levels of local time stepping in summary.json: steps, cells and dofs per level, the contact's, the bound.
void ReportLevels(const wave::LtsStepper& lts, io::RunSummary* summary) {
  summary->derived["wave_lts_levels"] = static_cast<double>(lts.levels());
  summary->derived["wave_lts_speedup_bound"] = lts.speedup_bound();
  summary->derived["wave_lts_contact_level"] = static_cast<double>(lts.contact_level());
  summary->derived["wave_lts_halvings"] = static_cast<double>(lts.halvings());
  for (PetscInt l = 0; l < lts.levels(); ++l) {
    const std::string key = "wave_lts_level" + std::to_string(l);
    summary->derived[key + "_dt"] = std::ldexp(lts.macro_step(), -static_cast<int>(l));
    summary->derived[key + "_cells"] = static_cast<double>(lts.info()[l].cells);
    summary->derived[key + "_dofs"] = static_cast<double>(lts.info()[l].dofs);
  }
  summary->derived_rules["wave_lts"] =
      "on: level l steps H/2^l (wave_lts_level<l>_dt, _cells, _dofs: cells of the level, dofs moving at its rate); "
      "speed-up bound: cell updates at the finest element step over those of the levels";
}

}  // namespace

PetscErrorCode WaveComponent::Setup(const mesh::Specimen& specimen, const Scene& scene, io::RunSummary* summary,
                                    bool restarting) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  TimedStage stage;
  PetscCall(stage.Begin("Wave setup"));
  solver_ = std::make_unique<wave::WaveSolver>();
  PetscCall(solver_->Setup(specimen.wave, scene.material, scene.excitation, scene.wave));
  std::unique_ptr<contact::CrackLaw> law;
  VibrothermCallCpp(comm, law = contact::create_crack_law(scene.contact));
  summary->dissipated_energy_by_crack.assign(specimen.cracks.size(), 0.0);  // a crack without contact cells: 0
  if (!specimen.cracks.empty() && law->has_contact()) {
    crack_ = std::make_unique<interface::CrackInterface>();
    PetscCall(crack_->Setup(solver_->space(), specimen.wave_cracks, solver_->op().mass(), std::move(law), scene.a0));
    PetscCall(solver_->SetInterface(crack_.get(), WorstCaseApproach(scene)));
    summary->contact_cells = crack_->global_cells();
  }
  if (!restarting) PetscCall(StartWaves(specimen, scene));  // a restart's state is the checkpoint's
  PetscCall(stage.End(&summary->stages["wave_setup"]));
  if (solver_->lts()) PetscCall(solver_->lts()->View(comm));
  summary->derived["wave_dt"] = solver_->step().dt();
  summary->derived["wave_stable_dt"] = solver_->step().stable_dt();
  const char* rule = scene.wave.contact_step == wave::ContactStepRule::kWorstCase
                         ? "-wave_cfl x the stability limit (bulk, and the contact at a0 + twice the source amplitude), "
                           "rounded down to 4 digits"
                         : "-wave_cfl x the stability limit (bulk, and the contact at its initial approach), rounded down "
                           "to 4 digits; shrunk when the contact stiffens (wave_dt_reductions, wave_dt_final)";
  summary->derived_rules["wave_dt"] = scene.wave.dt > 0 ? "-wave_dt" : rule;
  if (solver_->lts()) {
    summary->derived_rules["wave_dt"] =
        "local time stepping: the macro step H, the largest 2^l x -wave_lts_cfl x level l's own stability limit, "
        "rounded down to 4 digits (levels: wave_lts_*)";
    ReportLevels(*solver_->lts(), summary);
  } else if (scene.wave.lts.on) {
    summary->derived_rules["wave_lts"] = solver_->lts_note();
  }
  PetscCall(WarnAboutTheSource(specimen.wave, scene, solver_->step().dt()));
  // Refused now, not after hours: the step count the run would need (the waves may stop earlier when quiet).
  // A periodic continuation may skip nearly all of them: then the steps taken are counted instead.
  const double steps = std::ceil(scene.final_time / solver_->step().dt());
  if (scene.periodic.on) max_steps_ = scene.run.max_steps;
  PetscCheck(scene.periodic.on || steps <= scene.run.max_steps, comm, PETSC_ERR_USER_INPUT,
             "the run needs up to %.3g wave steps (dt = %g s to -final_time %g s), more than -max_steps %.3g: shorten "
             "-final_time, soften the contact law or raise -max_steps",
             steps, solver_->step().dt(), scene.final_time, scene.run.max_steps);
  PetscCall(CheckProbePoints(solver_->space(), scene.run.probe_points));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::StartWaves(const mesh::Specimen& specimen, const Scene& scene) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)specimen.wave);
  if (scene.wave.start == wave::WaveStart::kState) {
    stop_signals::EnterSetup("the warm start");
    PetscCall(StartFromSavedState(scene.wave.start_state, specimen, scene.excitation, solver_.get()));
  }
  if (scene.wave.start != wave::WaveStart::kHarmonic) PetscFunctionReturn(0);
  // Linearized about its rest state, a crack whose faces carry no load (a0 <= 0) has no stiffness:
  // the steady response would let the faces pass through each other.
  double most = -INFINITY, global;
  if (crack_)
    for (const interface::ContactCell& c : crack_->cells()) most = std::max(most, c.a0);
  PetscCallMPI(MPI_Allreduce(&most, &global, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCheck(!crack_ || global > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-wave_start harmonic: the crack is not pre-closed (-crack_a0 %g): the linearized contact of an "
             "unloaded crack lets its faces pass through each other; start at rest or pre-close it (-crack_a0 > 0)",
             global);
  stop_signals::EnterSetup("the harmonic start");
  PetscCall(solver_->StartHarmonic());
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::Advance(PetscInt steps, double t_end) {
  PetscFunctionBeginUser;
  if (solver_->StepsUntil(t_end) <= steps) PetscCall(solver_->AdvanceTo(t_end));
  else PetscCall(solver_->AdvanceSteps(steps));
  PetscCall(CheckStepBudget());
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::AdvanceTo(double t_end) {
  PetscFunctionBeginUser;
  PetscCall(solver_->AdvanceTo(t_end));
  PetscCall(CheckStepBudget());
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::CheckStepBudget() const {
  PetscFunctionBeginUser;
  PetscCheck(max_steps_ == 0.0 || solver_->steps() <= max_steps_, PetscObjectComm((PetscObject)solver_->space().dm()),
             PETSC_ERR_USER_INPUT,
             "the run has taken %" PetscInt_FMT " wave steps, more than -max_steps %.3g (the waves have not become "
             "periodic; periodic.csv has the change per period): shorten -final_time, loosen -periodic_tol or raise "
             "-max_steps",
             solver_->steps(), max_steps_);
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::Stop(io::RunSummary* summary) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)solver_->space().dm());
  summary->physics_ran.push_back("wave");
  summary->physics_time["wave"] = {0.0, solver_->time()};
  if (crack_) {
    summary->physics_ran.push_back("contact");
    summary->physics_time["contact"] = {0.0, solver_->time()};
    double stored, seconds = crack_->seconds();
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &seconds, 1, MPI_DOUBLE, MPI_MAX, comm));
    summary->stages["contact"] = seconds;  // part of wave_steps
    PetscCall(crack_->Energies(&stored, &summary->dissipated_energy));
    std::vector<double> by_crack;
    PetscCall(crack_->DissipatedByCrack(&by_crack));
    by_crack.resize(std::max(by_crack.size(), summary->dissipated_energy_by_crack.size()), 0.0);
    summary->dissipated_energy_by_crack = by_crack;
    PetscCall(crack_->MaxFrictionExcess(&summary->max_friction_excess));
  }
  summary->wave_dt_reductions = solver_->dt_reductions();
  summary->derived["wave_dt_final"] = solver_->step().dt();
  if (solver_->lts()) ReportLevels(*solver_->lts(), summary);
  summary->dofs_wave = solver_->op().dofs();
  summary->steps_wave = solver_->steps();
  solver_->on_step = nullptr;
  crack_.reset();
  solver_.reset();
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::Save(store::Checkpoint& checkpoint, const mesh::Specimen& specimen) const {
  PetscFunctionBeginUser;
  PetscCall(solver_->Save(checkpoint, specimen.wave_origin));
  if (crack_) PetscCall(crack_->Save(checkpoint, specimen.wave_origin));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::Restore(const store::Checkpoint& checkpoint, const mesh::Specimen& specimen) {
  PetscFunctionBeginUser;
  PetscCall(solver_->Restore(checkpoint, specimen.wave_origin));
  if (crack_) PetscCall(crack_->Restore(checkpoint, specimen.wave_origin));
  PetscFunctionReturn(0);
}

PetscErrorCode WaveComponent::Snapshot(const mesh::Specimen& specimen, store::Checkpoint* snapshot) const {
  PetscFunctionBeginUser;
  PetscCall(Save(*snapshot, specimen));
  snapshot->IndexLocal();
  PetscFunctionReturn(0);
}

std::vector<double> WaveComponent::Accumulated() const {
  std::vector<double> values = solver_->Accumulated();
  if (crack_) {
    const std::vector<double> crack = crack_->Accumulated();
    values.insert(values.end(), crack.begin(), crack.end());
  }
  return values;
}

PetscErrorCode WaveComponent::ResumeFrom(const store::Checkpoint& snapshot, const mesh::Specimen& specimen,
                                         const std::vector<double>& increments) {
  PetscFunctionBeginUser;
  PetscCall(Restore(snapshot, specimen));
  const std::size_t n = solver_->Accumulated().size();
  PetscCall(solver_->JumpAhead(std::vector<double>(increments.begin(), increments.begin() + n)));
  if (crack_) crack_->JumpAhead(std::vector<double>(increments.begin() + n, increments.end()));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
