#include "vibrotherm/coupling/observe/camera_options.hpp"

#include <cmath>

#include "vibrotherm/coupling/observe/camera_face.hpp"
#include "vibrotherm/options/petsc/option_list.hpp"

namespace vibrotherm::coupling {
namespace {

/// One line naming the option for every value no camera can have.
PetscErrorCode CheckCameraOptions(MPI_Comm comm, const CameraOptions& o) {
  PetscFunctionBeginUser;
  const std::pair<const char*, double> finite[] = {{"-camera_fps", o.fps},
                                                    {"-camera_pixel", o.pixel},
                                                    {"-camera_netd", o.netd},
                                                    {"-camera_integration", o.integration},
                                                    {"-camera_detect_snr", o.detect_snr},
                                                    {"-camera_detect_contrast", o.detect_contrast}};
  for (const auto& [option, value] : finite)
    PetscCheck(std::isfinite(value), comm, PETSC_ERR_USER_INPUT, "%s must be finite, got %g", option, value);
  PetscCheck(o.fps >= 0.0, comm, PETSC_ERR_USER_INPUT, "-camera_fps must be >= 0 (0: no camera), got %g", o.fps);
  PetscCheck(o.pixel > 0.0, comm, PETSC_ERR_USER_INPUT, "-camera_pixel must be > 0, got %g", o.pixel);
  PetscCheck(o.netd > 0.0, comm, PETSC_ERR_USER_INPUT,
             "-camera_netd must be > 0 (every camera has noise: detectability is the peak rise over it; the noise-free "
             "frames are in camera.h5 as clean_k), got %g", o.netd);
  PetscCheck(o.face.empty() || IsCameraFace(o.face), comm, PETSC_ERR_USER_INPUT,
             "-camera_face %s: unknown face (front, back, top, bottom, left, right)", o.face.c_str());
  PetscCheck(o.integration > 0.0, comm, PETSC_ERR_USER_INPUT, "-camera_integration must be > 0, got %g",
             o.integration);
  PetscCheck(o.fps == 0.0 || o.integration <= (1.0 / o.fps) * (1 + 1e-12), comm, PETSC_ERR_USER_INPUT,
             "-camera_integration %g s is longer than the frame period 1/-camera_fps = %g s", o.integration,
             1.0 / o.fps);
  PetscCheck(o.samples >= 1 && o.samples <= 64, comm, PETSC_ERR_USER_INPUT,
             "-camera_pixel_samples must be in [1, 64], got %" PetscInt_FMT, o.samples);
  PetscCheck(o.detect_snr > 0.0, comm, PETSC_ERR_USER_INPUT, "-camera_detect_snr must be > 0, got %g", o.detect_snr);
  PetscCheck(o.detect_contrast >= 0.0, comm, PETSC_ERR_USER_INPUT, "-camera_detect_contrast must be >= 0, got %g",
             o.detect_contrast);
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

PetscErrorCode ReadCameraOptions(MPI_Comm comm, CameraOptions* o) {
  PetscFunctionBeginUser;
  PetscBool on = o->on ? PETSC_TRUE : PETSC_FALSE, on_set = PETSC_FALSE;
  PetscBool given[10] = {};
  char face[64] = "";
  PetscOptionsBegin(comm, nullptr, "IR camera (README \"IR camera\")", nullptr);
  PetscCall(PetscOptionsBool("-camera", "Film the specimen's face with an IR camera: camera.h5/xmf (any -camera_* "
                             "option switches it on too; -camera 0: off)", nullptr, on, &on, &on_set));
  PetscCall(PetscOptionsReal("-camera_fps", "Camera frames per second (0: no camera)", nullptr, o->fps, &o->fps,
                             &given[0]));
  PetscCall(PetscOptionsReal("-camera_pixel", "Camera pixel size on the specimen [m]", nullptr, o->pixel, &o->pixel,
                             &given[1]));
  PetscCall(PetscOptionsReal("-camera_netd", "Camera noise-equivalent temperature difference (noise std) [K]",
                             nullptr, o->netd, &o->netd, &given[2]));
  PetscCall(PetscOptionsReal("-camera_integration", "Camera integration time of a frame [s] (<= 1/fps)", nullptr,
                             o->integration, &o->integration, &given[3]));
  PetscCall(OptionsRealList(PetscOptionsObject, "-camera_window",
                            "Camera field of view x0,y0,x1,y1 [m] (default: the specimen)", &o->window, &given[4]));
  PetscCall(PetscOptionsInt("-camera_pixel_samples", "Camera: n x n points per pixel for its area average", nullptr,
                            o->samples, &o->samples, &given[5]));
  PetscCall(PetscOptionsInt("-camera_seed", "Camera: seed of the NETD noise", nullptr, o->seed, &o->seed, &given[6]));
  PetscCall(PetscOptionsReal("-camera_detect_snr", "Camera: the defect's peak SNR (its own rise / NETD) from which "
                             "it counts as detectable", nullptr, o->detect_snr, &o->detect_snr, &given[7]));
  PetscCall(PetscOptionsReal("-camera_detect_contrast", "Camera: the defect's peak rise over the background "
                             "heating's peak (damping, thermoelastic) from which the defect stands out (0: any)",
                             nullptr, o->detect_contrast, &o->detect_contrast, &given[9]));
  PetscCall(PetscOptionsString("-camera_face", "Camera (3D specimens): the face it films, front|back|top|bottom|left|"
                               "right (front: z = max)", nullptr, face, face, sizeof(face), &given[8]));
  PetscOptionsEnd();
  o->face = face;
  bool any = false;
  for (PetscBool g : given) any = any || g;
  o->on = (on_set ? static_cast<bool>(on) : any) && o->fps > 0.0;
  PetscCall(CheckCameraOptions(comm, *o));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
