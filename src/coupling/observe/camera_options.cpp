#include "vibrotherm/coupling/observe/camera_options.hpp"

#include "vibrotherm/coupling/observe/camera_face.hpp"
#include "vibrotherm/options/query/option_query.hpp"

namespace vibrotherm::coupling {
namespace {

/// What no single option's range says: the face is a face, the integration fits in a frame, the window
/// is a rectangle.
PetscErrorCode CheckCameraOptions(MPI_Comm comm, const CameraOptions& o) {
  PetscFunctionBeginUser;
  PetscCheck(o.face.empty() || IsCameraFace(o.face), comm, PETSC_ERR_USER_INPUT,
             "-camera_face %s: unknown face (front, back, top, bottom, left, right)", o.face.c_str());
  PetscCheck(o.fps == 0.0 || o.integration <= (1.0 / o.fps) * (1 + 1e-12), comm, PETSC_ERR_USER_INPUT,
             "-camera_integration %g s is longer than the frame period 1/-camera_fps = %g s", o.integration,
             1.0 / o.fps);
  if (!o.window.empty()) {
    const std::vector<double>& w = o.window;
    PetscCheck(w.size() == 4, comm, PETSC_ERR_USER_INPUT, "-camera_window needs 4 values x0,y0,x1,y1, got %zu",
               w.size());
    PetscCheck(w[2] > w[0] && w[3] > w[1], comm, PETSC_ERR_USER_INPUT,
               "-camera_window %g,%g,%g,%g is empty: x1 > x0 and y1 > y0 needed", w[0], w[1], w[2], w[3]);
  }
  PetscFunctionReturn(0);
}

}  // namespace

const std::vector<OptionSpec<CameraOptions>>& CameraOptionSpecs() {
  using C = CameraOptions;
  using contact::Range;
  static const std::vector<OptionSpec<C>> specs = {
      FlagOption("-camera", &C::on,
                 "Film the specimen's face with an IR camera: camera.h5/xmf (any -camera_* option switches it on "
                 "too; -camera 0: off)"),
      RealOption("-camera_fps", &C::fps, Range::at_least(0.0), "1/s", "Camera frames per second (0: no camera)"),
      RealOption("-camera_pixel", &C::pixel, Range::positive(), "m", "Camera pixel size on the specimen"),
      RealOption("-camera_netd", &C::netd, Range::positive(), "K",
                 "Camera noise-equivalent temperature difference, the noise std (every camera has noise: "
                 "detectability is the peak rise over it; the noise-free frames are in camera.h5 as clean_k)"),
      RealOption("-camera_integration", &C::integration, Range::positive(), "s",
                 "Camera integration time of a frame (<= 1/fps)"),
      RealListOption("-camera_window", &C::window, Range::any(), "m",
                     "Camera field of view x0,y0,x1,y1 (default: the specimen)"),
      IntOption("-camera_pixel_samples", &C::samples, Range::between(1.0, 64.0),
                "Camera: n x n points per pixel for its area average"),
      IntOption("-camera_seed", &C::seed, Range::any(), "Camera: seed of the NETD noise"),
      RealOption("-camera_detect_snr", &C::detect_snr, Range::positive(), "",
                 "Camera: the defect's peak SNR (its own rise / NETD) from which it counts as detectable"),
      RealOption("-camera_detect_contrast", &C::detect_contrast, Range::at_least(0.0), "",
                 "Camera: the defect's peak rise over the background heating's peak (damping, thermoelastic) from "
                 "which the defect stands out (0: any)"),
      TextOption("-camera_face", &C::face,
                 "Camera (3D specimens): the face it films, front|back|top|bottom|left|right (front: z = max)"),
  };
  return specs;
}

PetscErrorCode ReadCameraOptions(MPI_Comm comm, CameraOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  PetscCall(ReadOptionSpecs(comm, "IR camera (README \"IR camera\")", CameraOptionSpecs(), o, values));
  // -camera decides when given; otherwise any -camera_* option given switches the camera on.
  bool on_given = false, any_given = false;
  for (const OptionSpec<CameraOptions>& option : CameraOptionSpecs()) {
    bool given;
    PetscCall(OptionGiven(nullptr, option.spec.name.c_str(), &given));
    (option.spec.name == "-camera" ? on_given : any_given) |= given;
  }
  o->on = (on_given ? o->on : any_given) && o->fps > 0.0;
  PetscCall(CheckCameraOptions(comm, *o));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
