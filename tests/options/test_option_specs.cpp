// Requirement (issue 42 item 2): an option declared once (options/petsc/option_spec.hpp)
// gives its reading, its range check and its one-line error. For every declared list
// (-periodic*, -heat_* material and discretisation, -wave_*, -material_* and damping, -modes_*,
// the run control and recording, -camera*, -crack_a0*, -heat_bc* and the film, -source_*, the
// specimen, its mesh and heat mesh):
//  - the names are unique across the lists and each is read (set alone, it changes its field);
//  - with nothing given, every default lies in its range (the read succeeds);
//  - a value just outside a numeric range is refused with PETSC_ERR_USER_INPUT and a message
//    "<name> must be ..., got <value>"; an unknown choice names the option and the values.
#include <petscsys.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "vibrotherm/coupling/continuation/periodic_options.hpp"
#include "vibrotherm/coupling/observe/camera_options.hpp"
#include "vibrotherm/coupling/run/driver_options.hpp"
#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/interface/approach_profile.hpp"
#include "vibrotherm/heat/heat_boundary.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"
#include "vibrotherm/mesh/specimen_options.hpp"
#include "vibrotherm/modes/modal_analysis.hpp"
#include "vibrotherm/options/petsc/option_audit.hpp"
#include "vibrotherm/options/petsc/option_registry.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/wave_solver.hpp"
#include <gtest/gtest.h>

namespace vibrotherm::testing {
namespace {

PetscErrorCode KeepFirstMessage(MPI_Comm, int, const char*, const char*, PetscErrorCode n, PetscErrorType p,
                                const char* message, void* ctx) {
  auto* kept = static_cast<std::string*>(ctx);
  if (p == PETSC_ERROR_INITIAL && kept->empty()) *kept = message;
  return n;
}

/// Reads `specs` into a default Target with `given` as the only options; *message: the error's, if any.
template <class Target>
PetscErrorCode ReadWith(const std::vector<OptionSpec<Target>>& specs, const std::string& given, Target* target,
                        std::string* message, OptionValues* values = nullptr) {
  PetscOptions own;
  PetscCall(PetscOptionsCreate(&own));
  PetscCall(PetscOptionsInsertString(own, given.c_str()));
  PetscCall(PetscOptionsPush(own));
  PetscCall(PetscPushErrorHandler(KeepFirstMessage, message));
  const PetscErrorCode status = ReadOptionSpecs(PETSC_COMM_WORLD, "test", specs, target, values);
  PetscCall(PetscPopErrorHandler());
  PetscCall(PetscOptionsPop());
  PetscCall(PetscOptionsDestroy(&own));
  return status;
}

/// A value just outside spec's range (lo side if bounded below, else hi side); empty if unbounded.
std::string Outside(const contact::ParameterSpec& s) {
  const bool integer = s.type == contact::ParameterType::Integer;  // (a RealList: one entry outside)
  const double step = integer ? 1.0 : 1e-3 * std::max(1.0, std::abs(s.range.lo));
  double value;
  if (std::isfinite(s.range.lo)) value = s.range.lo_open ? s.range.lo : s.range.lo - step;
  else if (std::isfinite(s.range.hi)) value = s.range.hi_open ? s.range.hi : s.range.hi + step;
  else return "";
  char text[64];
  if (integer) std::snprintf(text, sizeof(text), "%lld", static_cast<long long>(value));
  else std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

/// `initial`: the field values before reading (a caller's defaults, such as -modes_target_frequency's).
template <class Target>
void CheckList(const std::vector<OptionSpec<Target>>& specs, std::set<std::string>* seen, Target initial = Target{}) {
  std::string message;
  Target read = initial;
  ASSERT_EQ(ReadWith(specs, "", &read, &message), 0) << message;  // every default in its range
  for (const OptionSpec<Target>& o : specs) {
    const contact::ParameterSpec& s = o.spec;
    EXPECT_TRUE(seen->insert(s.name).second) << s.name << " declared twice";
    const std::string bad = s.type == contact::ParameterType::Choice ? "no_such_value" : Outside(s);
    if (bad.empty()) continue;
    message.clear();
    Target target = initial;
    EXPECT_EQ(ReadWith(specs, s.name + " " + bad, &target, &message), PETSC_ERR_USER_INPUT) << s.name << " " << bad;
    EXPECT_EQ(message.rfind(s.name, 0), 0u) << message;  // the message starts with the option's name
    if (s.type == contact::ParameterType::Choice)
      EXPECT_NE(message.find("unknown value 'no_such_value'"), std::string::npos) << message;
    else
      EXPECT_NE(message.find(" must be "), std::string::npos) << message;
  }
}

TEST(OptionSpecs, DeclaredOnceCheckedAndRefusedNamingTheOption) {
  std::set<std::string> seen;
  CheckList(coupling::PeriodicOptionSpecs(), &seen);
  CheckList(heat::HeatMaterialOptionSpecs(), &seen);
  CheckList(heat::HeatDiscretisationOptionSpecs(), &seen);
  CheckList(wave::WaveOptionSpecs(), &seen);
  CheckList(wave::ElasticMaterialOptionSpecs(), &seen);
  modes::ModesOptions modes;  // ReadModesOptions's caller gives these two defaults
  modes.target_frequency = 1e4;
  modes.defect_radius = 1e-3;
  CheckList(modes::ModesOptionSpecs(), &seen, modes);
  CheckList(wave::MaterialDampingOptionSpecs(), &seen);
  CheckList(coupling::DriverOptionSpecs(), &seen);
  CheckList(coupling::CameraOptionSpecs(), &seen);
  CheckList(interface::ApproachProfileOptionSpecs(), &seen);
  heat::HeatBoundaryOptions edges;  // ReadHeatBoundaryOptions's caller gives -heat_T_ext's default (T0)
  edges.T_ext = 293.15;
  CheckList(heat::HeatBoundaryOptionSpecs(), &seen, edges);
  CheckList(wave::ExcitationOptionSpecs(), &seen);
  CheckList(mesh::SpecimenGeometryOptionSpecs(), &seen);
  CheckList(mesh::HeatMeshOptionSpecs(), &seen);
  CheckList(mesh::MeshSourceOptionSpecs(), &seen);
  EXPECT_GE(seen.size(), 115u);
}

TEST(OptionSpecs, EachOptionFillsItsField) {
  // A value inside the range, different from the default, reaches the field it names.
  std::string message;
  coupling::PeriodicOptions periodic;
  ASSERT_EQ(ReadWith(coupling::PeriodicOptionSpecs(), "-periodic_tol 0.25 -periodic_window 7 -periodic_mode mean "
                     "-periodic off", &periodic, &message), 0) << message;
  EXPECT_EQ(periodic.tol, 0.25);
  EXPECT_EQ(periodic.window, 7);
  EXPECT_TRUE(periodic.mean);
  EXPECT_EQ(periodic.choice, coupling::PeriodicChoice::Off);
  heat::HeatOptions heat;
  ASSERT_EQ(ReadWith(heat::HeatDiscretisationOptionSpecs(), "-heat_degree 2 -heat_lumped_mass 0", &heat, &message), 0);
  EXPECT_EQ(heat.degree, 2);
  EXPECT_FALSE(heat.lumped);
  wave::WaveOptions wave;
  ASSERT_EQ(ReadWith(wave::WaveOptionSpecs(), "-wave_lts on -wave_lts_cfl 0.5 -wave_start harmonic -wave_degree 1",
                     &wave, &message), 0) << message;
  EXPECT_TRUE(wave.lts.on);
  EXPECT_EQ(wave.lts.cfl, 0.5);
  EXPECT_EQ(wave.start, wave::WaveStart::kHarmonic);
  EXPECT_EQ(wave.degree, 1);
  coupling::DriverOptions driver;  // lists, and a value given where the default is derived
  ASSERT_EQ(ReadWith(coupling::DriverOptionSpecs(), "-output_times 2e-3,1e-3 -crack_probe 0.25,1 -final_time 0.5 "
                     "-physics wave -heat_near_field 0", &driver, &message), 0) << message;
  EXPECT_EQ(driver.output_times, (std::vector<double>{2e-3, 1e-3}));
  EXPECT_EQ(driver.crack_probes, (std::vector<double>{0.25, 1.0}));
  EXPECT_EQ(driver.final_time, 0.5);
  EXPECT_EQ(driver.physics, coupling::PhysicsChoice::Wave);
  EXPECT_FALSE(driver.near_field);
  interface::ApproachProfile a0;  // a choice into an enum, a text
  ASSERT_EQ(ReadWith(interface::ApproachProfileOptionSpecs(), "-crack_a0_profile file -crack_a0_file a0.csv "
                     "-crack_a0 1e-8", &a0, &message), 0) << message;
  EXPECT_EQ(a0.shape, interface::ApproachShape::File);
  EXPECT_EQ(a0.file, "a0.csv");
  EXPECT_EQ(a0.uniform, 1e-8);
  heat::HeatBoundaryOptions edges;  // a choice kept as text, into an array's entry
  ASSERT_EQ(ReadWith(heat::HeatBoundaryOptionSpecs(), "-heat_bc insulated -heat_bc_top convective -heat_T_ext 300",
                     &edges, &message), 0) << message;
  EXPECT_EQ(edges.all, "insulated");
  EXPECT_EQ(edges.side[static_cast<int>(mesh::Side::Top)], "convective");
  EXPECT_EQ(edges.side[static_cast<int>(mesh::Side::Left)], "");
  EXPECT_EQ(edges.T_ext, 300.0);
  wave::ExcitationOptions source;  // nested twice
  ASSERT_EQ(ReadWith(wave::ExcitationOptionSpecs(), "-source_type traction -source_frequency 2e4 -source_sweep 1e4,3e4",
                     &source, &message), 0) << message;
  EXPECT_EQ(source.excitation.type, wave::SourceType::Traction);
  EXPECT_EQ(source.excitation.signal.frequency, 2e4);
  EXPECT_EQ(source.sweep, (std::vector<double>{1e4, 3e4}));
  mesh::SpecimenGeometryInput specimen;  // an edge into an array's entry, a list of choices, a patch
  ASSERT_EQ(ReadWith(mesh::SpecimenGeometryOptionSpecs(), "-edge_left free -edge_back fixed -crack_shape ellipse,rectangle "
                     "-mesh_cell tri -specimen_depth 0.01 -source_patch_edge front -source_patch_width 0.004,0.002",
                     &specimen, &message), 0) << message;
  EXPECT_EQ(specimen.geometry.edges[static_cast<int>(mesh::Side::Left)], mesh::EdgeKind::Free);
  EXPECT_EQ(specimen.geometry.depth_edges[1], mesh::EdgeKind::Fixed);
  EXPECT_EQ(specimen.shapes, (std::vector<PetscInt>{1, 0}));
  EXPECT_EQ(specimen.cell, mesh::MeshCell::Triangle);
  EXPECT_TRUE(specimen.geometry.patch.on);
  EXPECT_EQ(specimen.geometry.patch.side, mesh::Side::Front);
  EXPECT_EQ(specimen.geometry.patch.width2, 0.002);
  mesh::HeatMeshInput heat_mesh;  // a size given is kept, one not given stays unset
  ASSERT_EQ(ReadWith(mesh::HeatMeshOptionSpecs(), "-heat_mesh_growth 1.5", &heat_mesh, &message), 0) << message;
  EXPECT_EQ(heat_mesh.options.growth, 1.5);
  EXPECT_FALSE(heat_mesh.options.h.has_value());
}

TEST(OptionSpecs, RecordTheValueAsHelpShowsIt) {
  // The run record's values come from the declarations: a real by %g, a list as typed, a
  // choice by name, a flag TRUE/FALSE, a list not given "none", one value per option.
  std::string message;
  coupling::DriverOptions driver;
  OptionValues values;
  ASSERT_EQ(ReadWith(coupling::DriverOptionSpecs(), "-final_time 1e-3 -output_times 5e-5,1e-4 -physics wave "
                     "-heat_substeps 4", &driver, &message, &values), 0) << message;
  EXPECT_EQ(values.size(), coupling::DriverOptionSpecs().size());
  EXPECT_EQ(values["-final_time"], "0.001");
  EXPECT_EQ(values["-couple_dt"], "-1");  // not given: the field's value (the default rule applies later)
  EXPECT_EQ(values["-output_times"], "5e-5,1e-4");
  EXPECT_EQ(values["-crack_probe"], "none");
  EXPECT_EQ(values["-physics"], "wave");
  EXPECT_EQ(values["-heat_substeps"], "4");
  EXPECT_EQ(values["-heat_near_field"], "TRUE");
  mesh::SpecimenGeometryInput specimen;
  values.clear();
  ASSERT_EQ(ReadWith(mesh::SpecimenGeometryOptionSpecs(), "-edge_left free -mesh_crack_mirror on", &specimen,
                     &message, &values), 0) << message;
  EXPECT_EQ(values["-edge_left"], "free");
  EXPECT_EQ(values["-mesh_crack_mirror"], "on");
  EXPECT_EQ(values["-crack_shape"], "rectangle");
}

TEST(OptionRegistry, HoldsExactlyTheOptionsTheSceneReads) {
  // The typo check knows vibrotherm's options from the registry alone: every option ReadScene
  // declares to PETSc (captured from PETSc's help printer, as -help shows them) must be in it,
  // and nothing in it may be an option no reader reads; the value each reader recorded is the
  // one PETSc's help line showed. Run in a process of its own (ctest
  // option_registry): PETSc prints an options block's help only the first time it is read.
  // Some values given (a real typed otherwise than %g shows it, a list, a choice, a text choice).
  PetscOptions given;
  ASSERT_EQ(PetscOptionsCreate(&given), 0);
  ASSERT_EQ(PetscOptionsInsertString(given, "-final_time 1e-3 -output_times 5e-5,1e-4 -source_frequency 2e5 "
                                     "-camera_fps 50 -heat_bc insulated -physics wave -wave_degree 1"), 0);
  ASSERT_EQ(PetscOptionsPush(given), 0);
  std::vector<DeclaredOption> captured;
  ASSERT_EQ(OptionAuditBegin(false), 0);
  coupling::Scene scene;
  const PetscErrorCode status = coupling::ReadScene(PETSC_COMM_WORLD, &scene);
  ASSERT_EQ(OptionAuditEnd(&captured), 0);
  ASSERT_EQ(PetscOptionsPop(), 0);
  ASSERT_EQ(PetscOptionsDestroy(&given), 0);
  ASSERT_EQ(status, 0);
  EXPECT_EQ(scene.values["-final_time"], "0.001");
  EXPECT_EQ(scene.values["-output_times"], "5e-5,1e-4");
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank != 0) return;  // the printer prints on rank 0
  OptionRegistry registry;
  coupling::AddSceneOptions(&registry);
  const std::vector<std::string> known = registry.names();
  std::set<std::string> read;
  for (const DeclaredOption& d : captured) {
    read.insert(d.name);
    EXPECT_TRUE(std::binary_search(known.begin(), known.end(), d.name)) << d.name << " is read but not in the registry";
    // The run record's value, from the declaration, is what PETSc's help showed.
    const auto value = scene.values.find(d.name);
    ASSERT_NE(value, scene.values.end()) << d.name << " read but its value not recorded";
    EXPECT_EQ(value->second, d.value) << d.name;
  }
  for (const std::string& name : known) EXPECT_TRUE(read.count(name)) << name << " is in the registry but never read";
  EXPECT_GE(known.size(), 120u);
  const std::vector<std::string> valued = registry.names_with_values();
  EXPECT_FALSE(std::binary_search(valued.begin(), valued.end(), "-camera"));  // a flag needs no value
  EXPECT_TRUE(std::binary_search(valued.begin(), valued.end(), "-mesh_h"));
}

}  // namespace
}  // namespace vibrotherm::testing
