// The IR camera's view of the heat field (README "IR camera"). Pixel value =
// the temperature rise averaged over the pixel's area (n × n sub-sample points
// per pixel, located once in the heat mesh with fe::CellLocator and evaluated
// with the heat basis: a sparse matrix pixels × heat dofs, built once, one
// MatMult per heat step) and over the frame's integration window in time
// (trapezoid over the heat steps inside it; the heat loop lands on window
// boundaries in the free phase, NextBoundary, and interpolates linearly inside
// a coupled step). Frame k integrates [k/fps, k/fps + integration]. Rank 0
// adds seeded Gaussian NETD noise and writes camera.h5 + camera.xmf. In 3D the camera
// films one face of the box (camera_face.hpp); pixels and -camera_window are in that
// face's (u, v) coordinates. Beside each frame the camera integrates the defect's own
// share of the rise the same way (camera_verdict.hpp; /camera/defect_k when it is not the
// whole frame) and judges from both whether it sees the defect.
#pragma once

#include <petscmat.h>

#include <array>
#include <random>
#include <string>
#include <vector>

#include "vibrotherm/coupling/observe/camera_face.hpp"
#include "vibrotherm/coupling/observe/camera_options.hpp"
#include "vibrotherm/coupling/observe/camera_verdict.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/io/camera_frames.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/io/run_summary.hpp"

namespace vibrotherm::coupling {

class HeatCamera {
 public:
  HeatCamera() = default;
  HeatCamera(const HeatCamera&) = delete;
  HeatCamera& operator=(const HeatCamera&) = delete;
  ~HeatCamera();
  /// The pixel grid over the window (checked inside the body), the frames that
  /// fit before final_time, the pixel matrix. Collective. *frames = 0: nothing to film.
  PetscErrorCode Setup(const heat::HeatSolver& heat, const CameraOptions& options, double final_time,
                       PetscInt* frames);
  /// The same on a heat space without its solver (tests).
  PetscErrorCode Setup(const fe::LagrangeSpace& space, const CameraOptions& options, double final_time,
                       PetscInt* frames);
  /// Pixels × heat dofs: a pixel's value is its row times the rise (null before Setup or without frames).
  Mat pixel_matrix() const { return S_; }
  const io::CameraGrid& grid() const { return grid_; }
  /// What of the rise is the defect's (default: all of it); Partial reads the heat solver's partial rise.
  void SetDefectShare(DefectShare share) { share_ = share; }
  /// Opens dir/camera.h5 (rank 0). Collective.
  PetscErrorCode Open(const std::string& dir);
  /// After every heat step and at t = 0: integrates the pixel averages; writes each completed frame. Collective.
  PetscErrorCode Sample(const heat::HeatSolver& heat);
  /// The next frame-window boundary after t (+inf when none): the free heat TS stops there.
  double NextBoundary(double t) const;
  /// Checkpoints: the open window's integral, the frames so far, the noise
  /// generator; and back, reopening dir/camera.h5 where it was (instead of Open). Collective.
  PetscErrorCode Save(store::Checkpoint& checkpoint) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const std::string& dir);
  /// Closes camera.h5, writes camera.xmf; camera_* of the summary. Collective.
  PetscErrorCode Finish(io::RunSummary* summary);

 private:
  PetscErrorCode Grid(double final_time);
  PetscErrorCode Assemble(const fe::LagrangeSpace& space);
  PetscErrorCode AddPoints(const fe::LagrangeSpace& space, const std::vector<int>& owner,
                           const std::vector<std::size_t>& found, const std::vector<PetscInt>& cells,
                           const std::vector<fe::ReferencePoint>& refs);
  PetscErrorCode Integrate(double t_prev, double t);
  PetscErrorCode EmitFrame();
  /// A frame's window mean on rank 0 (empty elsewhere); the integral restarts.
  PetscErrorCode GatherMean(Vec integral, std::vector<double>* mean);
  /// The pixel's centre in the camera's axes [m].
  std::array<double, 2> PixelCentre(double pixel) const;
  PetscErrorCode SummariseVerdict(io::CameraSummary* c) const;
  PetscErrorCode SayVerdict(const io::CameraSummary& c) const;
  /// Sub-sample point i (row-major pixels, n × n points each) in the body.
  std::array<double, 3> SamplePoint(std::size_t i) const;
  double start(PetscInt k) const { return static_cast<double>(k) / options_.fps; }

  CameraOptions options_;
  CameraFace face_;
  MPI_Comm comm_ = MPI_COMM_NULL;
  io::CameraGrid grid_;
  PetscInt frames_ = 0, frame_ = 0;
  Mat S_ = nullptr;  ///< pixels × heat dofs: area-average weights
  Vec current_ = nullptr, previous_ = nullptr, integral_ = nullptr, on_root_ = nullptr;
  DefectShare share_ = DefectShare::Whole;
  Vec defect_current_ = nullptr, defect_previous_ = nullptr, defect_integral_ = nullptr;  ///< Partial only
  VecScatter to_root_ = nullptr;
  double t_prev_ = -1.0;
  io::CameraFrames file_;
  std::mt19937_64 random_;
  std::vector<double> peak_clean_, peak_noisy_;  ///< per frame [K] (rank 0)
  std::vector<FrameVerdict> verdicts_;           ///< per frame (rank 0)
  PetscLogEvent event_ = 0;
};

}  // namespace vibrotherm::coupling
