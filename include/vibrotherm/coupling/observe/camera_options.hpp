// The IR camera looking at the specimen's face (README "IR camera"): in plane
// strain the temperature is uniform through the depth, so the heat field is
// what the camera sees. Off unless -camera (or any -camera_* option) is given;
// defaults of a cooled MWIR camera.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::coupling {

struct CameraOptions {
  bool on = false;             ///< -camera, or any -camera_* option given (-camera 0: off)
  double fps = 100.0;          ///< -camera_fps: frames per second [1/s]
  double pixel = 5e-4;         ///< -camera_pixel: pixel size on the specimen [m]
  double netd = 0.02;          ///< -camera_netd: noise-equivalent temperature difference [K]
  double integration = 1e-3;   ///< -camera_integration: integration time of a frame [s]
  std::vector<double> window;  ///< -camera_window x0,y0,x1,y1 [m] (3D: u0,v0,u1,v1 of the face); empty: the specimen
  std::string face;            ///< -camera_face (3D): front|back|top|bottom|left|right; empty: front (camera_face.hpp)
  PetscInt samples = 6;        ///< -camera_pixel_samples: n × n points per pixel (area average)
  PetscInt seed = 1;           ///< -camera_seed: the noise's random seed
  double detect_snr = 5.0;     ///< -camera_detect_snr: the defect's signal over NETD that counts (Rose)
  /// -camera_detect_contrast: the defect's peak rise over the background heating's peak on the
  /// face (damping, thermoelastic, film heat) from which the defect stands out (camera_verdict.hpp)
  double detect_contrast = 1.0;
};

/// The camera's options, declared (option_spec.hpp).
const std::vector<OptionSpec<CameraOptions>>& CameraOptionSpecs();
/// Reads and checks -camera*. Collective. A bad value is one line naming the option.
PetscErrorCode ReadCameraOptions(MPI_Comm comm, CameraOptions* options, OptionValues* values = nullptr);

}  // namespace vibrotherm::coupling
