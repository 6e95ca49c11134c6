// The scene: every option of a simulation, read once and checked before any
// mesh or solver is built (each module reads its own prefix into its own part).
#pragma once

#include <petscsys.h>

#include "vibrotherm/contact/contact_parameters.hpp"
#include "vibrotherm/coupling/observe/camera_options.hpp"
#include "vibrotherm/coupling/run/driver_options.hpp"
#include "vibrotherm/coupling/continuation/continued_parts.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/interface/approach_profile.hpp"
#include "vibrotherm/mesh/specimen_options.hpp"
#include "vibrotherm/options/petsc/option_registry.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/material.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::coupling {

struct Scene {
  DriverOptions run;                 ///< physics switches, times, coupling, recording
  wave::ElasticMaterial material;
  wave::Excitation excitation;
  wave::WaveOptions wave;
  contact::ContactParameters contact;
  interface::ApproachProfile a0;
  heat::HeatOptions heat;
  CameraOptions camera;  ///< -camera*: the IR camera filming the heat field
  PeriodicOptions periodic;  ///< -periodic*: continuation of a periodic state
  mesh::SpecimenOptions specimen;  ///< -mesh_file, -specimen_*, -crack_*, -mesh_*, -edge_*, -heat_mesh*
  /// Every option ReadScene read, with its value as read (as -help shows it): the run record's.
  OptionValues values;
  double final_time = 0.0;  ///< -final_time, or the source duration
  double couple_dt = 0.0;   ///< -couple_dt, or 1/8 of the source period

  /// √(α · heat step): the layer the friction heat of one heat step fills.
  double exchange_length() const;
  /// Where the waves are expected to be over: 8 source periods after the source (the quiet
  /// rule stops them once they are; 7.2 in the paper scene), or -final_time.
  double waves_expected_end() const;
  /// The numbers a periodic continuation works with.
  ContinuationScene continuation() const;
};

/// Reads and checks every simulation option. Collective.
PetscErrorCode ReadScene(MPI_Comm comm, Scene* scene);

/// Adds the declarations of every option ReadScene reads (scene_options.cpp).
void AddSceneOptions(OptionRegistry* registry);

}  // namespace vibrotherm::coupling
