#include "run.hpp"

#include <set>
#include <string>
#include <vector>

#include "vibrotherm/coupling/run/model_validity.hpp"
#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/coupling/run/simulation.hpp"
#include "vibrotherm/io/mesh_output.hpp"
#include "vibrotherm/io/run_log.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/geometry_script.hpp"
#include "vibrotherm/mesh/mesh_summary.hpp"
#include "vibrotherm/mesh/plex/metis_partitioner.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/modes/modes_run.hpp"
#include "vibrotherm/options/petsc/option_audit.hpp"
#include "vibrotherm/options/petsc/option_registry.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/stop_signals.hpp"
#include "vibrotherm/util/version.hpp"
#include "output_directory.hpp"
#include "restart.hpp"
#include "run_record.hpp"

namespace vibrotherm::app {
namespace {

struct AppOptions {
  bool mesh_only = false, modes = false, allow_unknown = false;
  bool overwrite = false;  ///< -overwrite: discard an interrupted run's checkpoint in -output_dir
  bool debug = false;      ///< read by the error handler (util/errors.hpp); declared here
  PetscBool help = PETSC_FALSE;  ///< asked by the user (the option audit adds -help for itself)
  std::string output_dir = "results/run";
  std::string restart;  ///< -restart DIR: continue the run whose checkpoint is in DIR
};

const std::vector<OptionSpec<AppOptions>>& AppOptionSpecs() {
  using A = AppOptions;
  static const std::vector<OptionSpec<A>> specs = {
      FlagOption("-mesh_only", &A::mesh_only, "Build the specimen mesh, write it and stop"),
      FlagOption("-modes", &A::modes, "Natural modes of the cracked specimen (SLEPc) instead of a time run"),
      TextOption("-output_dir", &A::output_dir, "Output directory (scripts/run: results/<options-file-stem>)"),
      TextOption("-restart", &A::restart,
                 "Continue the interrupted run whose outputs and checkpoint.h5 are in this directory (the same "
                 "options; it becomes the output directory)"),
      FlagOption("-overwrite", &A::overwrite,
                 "Write into an -output_dir that holds an earlier run's results or an interrupted run's checkpoint, "
                 "replacing them (without it such a directory is refused; -restart continues an interrupted run)"),
      FlagOption("-allow_unknown", &A::allow_unknown,
                 "Pass options vibrotherm does not know on to PETSc (a warning, not an error)"),
      FlagOption("-debug", &A::debug, "Errors with PETSc's full trace after the one line, MPI_Abort's banner and "
                 "HDF5's diagnostics"),
  };
  return specs;
}

/// Every option vibrotherm declares: its own, the scene's and -modes'.
OptionRegistry DeclaredOptions() {
  OptionRegistry registry;
  registry.Add(AppOptionSpecs()).Add(modes::ModesOptionSpecs());
  coupling::AddSceneOptions(&registry);
  return registry;
}

PetscErrorCode ReadAppOptions(MPI_Comm comm, AppOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "vibrotherm", AppOptionSpecs(), o, values));
  bool dir_set;
  PetscCall(OptionGiven(nullptr, "-output_dir", &dir_set));
  if (!o->restart.empty()) {
    PetscCheck(!dir_set || SameDirectory(o->output_dir, o->restart), comm, PETSC_ERR_USER_INPUT,
               "-restart %s writes into that directory: -output_dir %s is another one", o->restart.c_str(),
               o->output_dir.c_str());
    PetscCheck(!o->modes && !o->mesh_only, comm, PETSC_ERR_USER_INPUT, "-restart continues a time run, not -modes or -mesh_only");
    o->output_dir = o->restart;
  }
  PetscFunctionReturn(0);
}

/// -help: the main options of the PETSc objects under vibrotherm's prefixes (a
/// run reads them from the objects themselves, with every other option of
/// theirs, and refuses one none of them read).
PetscErrorCode ListSolverOptions(MPI_Comm comm) {
  PetscFunctionBeginUser;
  PetscCall(mesh::RegisterMetisPartitioner());
  PetscPartitioner partitioner;  // prints -petscpartitioner_type with the types and the default of this build
  PetscCall(PetscPartitionerCreate(comm, &partitioner));
  PetscCall(PetscPartitionerSetFromOptions(partitioner));
  PetscCall(PetscPartitionerDestroy(&partitioner));
  struct Entry {
    const char* name;
    std::string value;
    const char* text;
  };
  const Entry entries[] = {
      {"-wave_ts_type", "velocityverlet",
       "Wave TS: velocityverlet (vibrotherm's own), basicsymplectic, rk, ssp or alpha2 (implicit)"},
      {"-wave_ts_rk_type", "4", "-wave_ts_type rk: 1fe, 2a, 3 or 4 (fixed steps)"},
      {"-heat_ts_type", "beuler", "Heat TS while the waves run (fixed steps; -heat_ksp_*, -heat_pc_*: its linear solver)"},
      {"-heat_free_ts_type", "cn", "Heat TS after the waves (-heat_free_ksp_*, -heat_free_pc_*: its linear solver)"},
      {"-heat_free_ts_adapt_type", "ladder",
       "Its steps: ladder (doubling every -heat_free_ts_adapt_ladder_steps steps, ratio "
       "-heat_free_ts_adapt_ladder_ratio) or basic (PETSc's error control)"}};
  PetscOptionsBegin(comm, nullptr,
                    "PETSc solvers (any option of -wave_ts_*, -heat_ts_*, -heat_free_ts_*, -heat_ksp_*, -heat_pc_*, "
                    "-modes_eps_*, -modes_st_*, -petscpartitioner_*; refused when none of them reads it)", nullptr);
  for (const Entry& e : entries) {
    char value[64];
    PetscCall(PetscStrncpy(value, e.value.c_str(), sizeof(value)));
    PetscCall(PetscOptionsString(e.name, e.text, nullptr, value, value, sizeof(value), nullptr));
  }
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

/// Every option of every module, whatever the scene (-help lists them, and a run
/// checks the command line against them before meshing), with their values checked.
PetscErrorCode DeclareOptions(MPI_Comm comm, const coupling::Scene& scene, OptionValues* values) {
  PetscFunctionBeginUser;
  modes::ModesOptions modes;
  PetscCall(modes::ReadModesOptions(comm, scene.excitation.signal.frequency, 0.01, &modes, values));
  PetscFunctionReturn(0);
}

/// -help: every option, vibrotherm's and the main ones of its PETSc objects (printed while read).
PetscErrorCode PrintHelp(MPI_Comm comm, const coupling::Scene& scene) {
  PetscFunctionBeginUser;
  PetscCall(DeclareOptions(comm, scene, nullptr));
  PetscCall(ListSolverOptions(comm));
  std::vector<DeclaredOption> printed;
  PetscCall(OptionAuditEnd(&printed));
  PetscCall(io::RunLogClose());
  PetscFunctionReturn(0);
}

/// Before meshing (which may take minutes): no likely typo of a vibrotherm option,
/// every value there, and an output directory this run may use. *values: the -modes_* options'
/// values added.
PetscErrorCode CheckBeforeMeshing(MPI_Comm comm, const AppOptions& app, const coupling::Scene& scene,
                                  const OptionRegistry& registry, OptionValues* values, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  PetscCall(DeclareOptions(comm, scene, values));
  // Likely typos now (PETSc's objects declare their options later); -allow_unknown's warning comes once, after.
  if (!app.allow_unknown) PetscCall(CheckUnknownOptions(comm, registry.names(), false, true));
  PetscCall(CheckMissingValues(comm, registry.names_with_values()));
  // A wave no mesh of the requested sizes can carry, refused before meshing with them.
  if (scene.run.physics != coupling::PhysicsChoice::Heat && !app.modes && !app.mesh_only) {
    PetscCall(coupling::CheckSourceBeforeMeshing(comm, scene, mesh::FinestRequestedElement(scene.specimen), summary));
  }
  // A file in its place, another run there, an interrupted run's checkpoint, an earlier run's results: refused now.
  PetscCall(CheckOutputDirectory(comm, app.output_dir, !app.restart.empty(), app.overwrite));
  PetscFunctionReturn(0);
}

/// Builds what the options describe (all input checked, nothing written); restarting:
/// the state will come from the checkpoint.
PetscErrorCode Build(MPI_Comm comm, const AppOptions& app, const coupling::Scene& scene,
                     const mesh::SpecimenOptions& specimen_options, mesh::Specimen* specimen,
                     coupling::Simulation* simulation, modes::ModesRun* modes_run, io::RunSummary* summary) {
  PetscFunctionBeginUser;
  PetscCall(mesh::CheckSpecimenMemory(comm, scene.specimen, scene.wave.degree, scene.exchange_length()));
  const double t = MPI_Wtime();
  const mesh::LtsWeighting lts{scene.wave.lts.on, scene.wave.lts.max_levels, scene.wave.lts.wiggle};
  stop_signals::EnterSetup("meshing");
  PetscCall(mesh::SpecimenCreate(comm, specimen_options, scene.exchange_length(), specimen, lts));
  summary->stages["mesh"] = MPI_Wtime() - t;
  PetscCall(mesh::ComputeMeshSummary(*specimen, &summary->mesh));
  PetscCall(mesh::PrintMeshSummary(comm, summary->mesh));
  stop_signals::EnterSetup(app.modes ? "the natural modes (-modes)" : "the setup of the solvers");
  if (app.modes && !app.mesh_only) PetscCall(modes_run->Setup(*specimen, scene, summary));
  if (app.modes || app.mesh_only) PetscFunctionReturn(0);
  if (scene.run.physics != coupling::PhysicsChoice::Heat)
    PetscCall(coupling::CheckSourceValidity(comm, scene, summary->mesh.h_max, summary));
  PetscCall(simulation->Setup(*specimen, scene, summary, !app.restart.empty()));
  PetscFunctionReturn(0);
}

/// A .geo (-mesh_file, -heat_mesh_file) becomes the mesh gmsh makes of it, in the output
/// directory; each such mesh is the directory's setup file (gone again if the run stops in its
/// setup), also those of a call that failed part way.
PetscErrorCode MeshScripts(MPI_Comm comm, OutputDirectory* output, mesh::MeshSource* source) {
  PetscFunctionBeginUser;
  std::vector<std::string> meshed;
  stop_signals::EnterSetup("meshing");
  const PetscErrorCode meshing = mesh::MeshGeometryScripts(comm, output->dir(), source, &meshed);
  for (const std::string& file : meshed) output->AddSetupFile(file);
  PetscCall(meshing);
  PetscFunctionReturn(0);
}

/// -restart: the checkpoint read and compared with the options known before meshing.
PetscErrorCode ReadCheckpointEarly(MPI_Comm comm, const AppOptions& app, const std::vector<std::string>& command_line,
                                   const OptionValues& recorded, store::Checkpoint* checkpoint) {
  PetscFunctionBeginUser;
  std::set<std::string> names;
  for (const auto& [name, value] : recorded) names.insert(name);
  PetscCall(ReadRestart(comm, app.restart, OptionFingerprint(OptionRecords(command_line, recorded)), names, checkpoint));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode Run(MPI_Comm comm, const std::vector<std::string>& command_line, int* status) {
  PetscFunctionBeginUser;
  *status = 0;
  const double t0 = MPI_Wtime();
  bool version;
  PetscCall(OptionGiven(nullptr, "-version", &version));
  if (version) {  // PETSc has printed its own version already
    PetscCall(PetscPrintf(comm, "vibrotherm %s\n", vibrotherm::version()));
    PetscFunctionReturn(0);
  }
  PetscCall(io::RunLogInstall());  // vibrotherm.log gets everything printed from here on
  AppOptions app;
  PetscCall(PetscOptionsHasHelp(nullptr, &app.help));
  PetscCall(OptionAuditBegin(app.help));  // every reader declares its options from here on
  OptionValues read;  // every vibrotherm option's value as its reader read it
  PetscCall(ReadAppOptions(comm, &app, &read));
  coupling::Scene scene;
  PetscCall(coupling::ReadScene(comm, &scene));
  if (app.help) PetscFunctionReturn(PrintHelp(comm, scene));
  read.insert(scene.values.begin(), scene.values.end());
  io::RunSummary summary;
  const OptionRegistry registry = DeclaredOptions();
  PetscCall(CheckBeforeMeshing(comm, app, scene, registry, &read, &summary));
  std::vector<DeclaredOption> declared;  // the options PETSc's printer showed (those of PETSc's objects)
  OptionAuditDeclared(&declared);
  // The directory is this run's from now on: a second run started at the same time is refused before it meshes.
  const std::string dir = app.output_dir;
  OutputDirectory output;
  PetscCall(output.Claim(comm, dir));
  store::Checkpoint checkpoint(comm);
  if (!app.restart.empty())
    PetscCall(ReadCheckpointEarly(comm, app, command_line, RecordedOptions(registry, read, declared), &checkpoint));
  mesh::Specimen specimen;
  coupling::Simulation simulation;
  modes::ModesRun modes_run;
  mesh::SpecimenOptions specimen_options = scene.specimen;
  PetscCall(MeshScripts(comm, &output, &specimen_options.source));
  PetscCall(Build(comm, app, scene, specimen_options, &specimen, &simulation, &modes_run, &summary));
  // Every PETSc object is set up: its options were read by now (before any step).
  PetscCall(OptionAuditEnd(&declared));
  PetscCall(CheckUnknownOptions(comm, registry.names(), app.allow_unknown));
  // -mesh_only builds no solver: their options cannot be read then, which is no sign of a typo.
  if (!app.mesh_only) PetscCall(CheckSolverOptionsRead(comm, declared, app.allow_unknown));
  RecordRun(command_line, RecordedOptions(registry, read, declared), scene, &summary);

  // Everything has been checked (and the checkpoint read): outputs from here on.
  coupling::RunControl control;
  control.fingerprint = OptionFingerprint(summary.option_values);
  if (!app.restart.empty()) {
    PetscCall(CheckRestartOptions(comm, dir, control.fingerprint, checkpoint));
    control.restart = &checkpoint;
    summary.restarted_from = dir + "/checkpoint.h5";
  }
  PetscCall(output.Prepare(comm, control.restart != nullptr));
  PetscCall(io::RunLogOpen(comm, dir + "/vibrotherm.log"));
  PetscLogStage output_stage;
  PetscCall(PetscLogStageRegister("Output", &output_stage));
  double t = MPI_Wtime();
  PetscCall(PetscLogStagePush(output_stage));
  PetscCall(io::WriteMeshes({{"wave", specimen.wave}, {"heat", specimen.heat}}, dir + "/mesh.h5"));
  PetscCall(PetscLogStagePop());
  summary.stages["output"] = MPI_Wtime() - t;
  if (app.modes && !app.mesh_only) PetscCall(modes_run.Write(dir));
  else if (!app.mesh_only) PetscCall(simulation.Run(dir, &summary, control));
  summary.wall_time_s = MPI_Wtime() - t0;
  summary.complete = simulation.interrupted_by() == 0;
  if (summary.complete && !app.mesh_only) PetscCall(WarnUnreadSolverOptions(comm, declared));
  PetscCall(io::RunLogPublish());  // summary.json, the run's record, comes last
  PetscCall(io::WriteRunSummary(comm, dir + "/summary.json", summary));
  if (summary.complete) PetscCall(RemoveCheckpoint(comm, dir));
  PetscCall(PetscPrintf(comm, "outputs in %s%s\n", dir.c_str(), summary.complete ? "" : " (incomplete: summary.json says \"complete\": false)"));
  // Stopped by a signal: the shell's convention for it, 128 + the signal.
  *status = summary.complete ? 0 : 128 + simulation.interrupted_by();
  PetscCall(mesh::SpecimenDestroy(&specimen));
  PetscCall(io::RunLogClose());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::app
