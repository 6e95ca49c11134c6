#include "vibrotherm/coupling/exchange/heat_camera.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

#include "vibrotherm/fe/cell_locator.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::coupling {
namespace {
constexpr double kMaxSamplePoints = 2e7;  ///< sub-sample points located at setup, at most
}

HeatCamera::~HeatCamera() {
  (void)MatDestroy(&S_);
  (void)VecDestroy(&current_);
  (void)VecDestroy(&previous_);
  (void)VecDestroy(&integral_);
  (void)VecDestroy(&on_root_);
  (void)VecScatterDestroy(&to_root_);
}

PetscErrorCode HeatCamera::Setup(const heat::HeatSolver& heat, const CameraOptions& options, double final_time,
                                 PetscInt* frames) {
  return Setup(heat.space(), options, final_time, frames);
}

PetscErrorCode HeatCamera::Setup(const fe::LagrangeSpace& space, const CameraOptions& options, double final_time,
                                 PetscInt* frames) {
  PetscFunctionBeginUser;
  options_ = options;
  comm_ = PetscObjectComm((PetscObject)space.dm());
  PetscClassId id;
  PetscLogEvent setup_event;
  PetscCall(PetscClassIdRegister("vibrotherm camera", &id));
  PetscCall(PetscLogEventRegister("CameraSetup", id, &setup_event));
  PetscCall(PetscLogEventRegister("CameraFrames", id, &event_));
  PetscCall(PetscLogEventBegin(setup_event, 0, 0, 0, 0));
  PetscCall(face_.Setup(space.dm(), options_.face));
  PetscCall(Grid(final_time));
  *frames = frames_;
  if (frames_ > 0) {
    PetscCall(Assemble(space));
    PetscCall(MatCreateVecs(S_, nullptr, &current_));
    PetscCall(VecDuplicate(current_, &previous_));
    PetscCall(VecDuplicate(current_, &integral_));
    PetscCall(VecZeroEntries(integral_));
    PetscCall(VecScatterCreateToZero(current_, &to_root_, &on_root_));
    random_.seed(static_cast<std::uint64_t>(options_.seed));
  }
  PetscCall(PetscLogEventEnd(setup_event, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/// The window (given, or the face's extent), the pixel grid centred in it, the frames before final_time.
PetscErrorCode HeatCamera::Grid(double final_time) {
  PetscFunctionBeginUser;
  const std::array<double, 4> b = face_.bounds();
  const double lo[2] = {b[0], b[1]}, hi[2] = {b[2], b[3]};
  std::vector<double> w = options_.window.empty() ? std::vector<double>{lo[0], lo[1], hi[0], hi[1]} : options_.window;
  const double tol = 1e-9 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  PetscCheck(w[0] >= lo[0] - tol && w[1] >= lo[1] - tol && w[2] <= hi[0] + tol && w[3] <= hi[1] + tol, comm_,
             PETSC_ERR_USER_INPUT, "-camera_window %g,%g,%g,%g extends outside the body [%g, %g] x [%g, %g] m", w[0],
             w[1], w[2], w[3], lo[0], hi[0], lo[1], hi[1]);
  const double p = options_.pixel;
  grid_.pixel = p;
  grid_.cols = static_cast<std::size_t>(std::floor((w[2] - w[0]) / p * (1 + 1e-12)));
  grid_.rows = static_cast<std::size_t>(std::floor((w[3] - w[1]) / p * (1 + 1e-12)));
  PetscCheck(grid_.cols >= 1 && grid_.rows >= 1, comm_, PETSC_ERR_USER_INPUT,
             "-camera_pixel %g m is larger than the window (%g x %g m)", p, w[2] - w[0], w[3] - w[1]);
  const double points = static_cast<double>(grid_.rows * grid_.cols) * options_.samples * options_.samples;
  PetscCheck(points <= kMaxSamplePoints, comm_, PETSC_ERR_USER_INPUT,
             "-camera_pixel %g m with -camera_pixel_samples %" PetscInt_FMT " gives %.3g sub-sample points (at most "
             "%.3g): use larger pixels, fewer samples or a smaller -camera_window",
             p, options_.samples, points, kMaxSamplePoints);
  // Whole pixels only, centred in the window (less than a pixel left over on each axis).
  grid_.x0 = w[0] + 0.5 * (w[2] - w[0] - p * grid_.cols);
  grid_.y0 = w[1] + 0.5 * (w[3] - w[1] - p * grid_.rows);
  const double tau = options_.integration;
  frames_ = final_time >= tau * (1 - 1e-12)
                ? static_cast<PetscInt>(std::floor((final_time - tau) * options_.fps * (1 + 1e-12) + 1e-9)) + 1
                : 0;
  if (frames_ == 0)
    PetscCall(PetscPrintf(comm_, "vibrotherm: warning: the run (%g s) is shorter than one camera frame "
                                 "(-camera_integration %g s): no camera.h5\n", final_time, tau));
  PetscFunctionReturn(0);
}

std::array<double, 3> HeatCamera::SamplePoint(std::size_t i) const {
  const std::size_t n = static_cast<std::size_t>(options_.samples), per_pixel = n * n;
  const std::size_t pixel = i / per_pixel, sub = i % per_pixel;
  const std::size_t row = pixel / grid_.cols, col = pixel % grid_.cols;
  const double u = (static_cast<double>(sub % n) + 0.5) / n, v = (static_cast<double>(sub / n) + 0.5) / n;
  return face_.Point(grid_.x0 + (col + u) * grid_.pixel, grid_.y0 + (row + v) * grid_.pixel);
}

/// S: row p = the mean over pixel p's sub-sample points (midpoint rule) of the heat basis there.
PetscErrorCode HeatCamera::Assemble(const fe::LagrangeSpace& space) {
  PetscFunctionBeginUser;
  const std::size_t n = grid_.rows * grid_.cols * static_cast<std::size_t>(options_.samples * options_.samples);
  fe::CellLocator locator;
  PetscCall(locator.Setup(space));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  std::vector<int> owner(n, INT_MAX);
  std::vector<std::size_t> found;
  std::vector<PetscInt> cells;
  std::vector<fe::ReferencePoint> refs;
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<double, 3> x = SamplePoint(i);
    PetscInt cell;
    fe::ReferencePoint ref = {0.0, 0.0, 0.0};
    locator.Locate(x.data(), &cell, &ref);
    if (cell < 0) continue;
    owner[i] = rank;
    found.push_back(i);
    cells.push_back(cell);
    refs.push_back(ref);
  }
  // A point on a partition boundary belongs to the lowest rank holding it: counted once.
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, owner.data(), static_cast<int>(n), MPI_INT, MPI_MIN, comm_));
  Vec u;
  PetscInt cols, global_cols;
  PetscCall(DMGetGlobalVector(space.dm(), &u));
  PetscCall(VecGetLocalSize(u, &cols));
  PetscCall(VecGetSize(u, &global_cols));
  PetscCall(DMRestoreGlobalVector(space.dm(), &u));
  const PetscInt pixels = static_cast<PetscInt>(grid_.rows * grid_.cols);
  PetscCall(MatCreateAIJ(comm_, PETSC_DECIDE, cols, pixels, global_cols, 16, nullptr, 16, nullptr, &S_));
  PetscCall(MatSetOption(S_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(AddPoints(space, owner, found, cells, refs));
  PetscCall(MatAssemblyBegin(S_, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(S_, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatCamera::AddPoints(const fe::LagrangeSpace& space, const std::vector<int>& owner,
                                     const std::vector<std::size_t>& found, const std::vector<PetscInt>& cells,
                                     const std::vector<fe::ReferencePoint>& refs) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  const std::size_t per_pixel = static_cast<std::size_t>(options_.samples * options_.samples);
  // Points outside the body (a window over a non-rectangular mesh) do not count: a
  // pixel is the mean over its points inside; a pixel with none reads 0 (T0).
  std::vector<int> inside(grid_.rows * grid_.cols, 0);
  for (std::size_t i = 0; i < owner.size(); ++i)
    if (owner[i] != INT_MAX) ++inside[i / per_pixel];
  DM dm = space.dm();
  PetscSection local, global;
  PetscCall(DMGetLocalSection(dm, &local));
  PetscCall(DMGetGlobalSection(dm, &global));
  std::vector<double> phi;
  for (std::size_t k = 0; k < found.size(); ++k) {
    if (owner[found[k]] != rank) continue;
    const PetscInt row = static_cast<PetscInt>(found[k] / per_pixel);
    PetscCall(space.BasisAt(refs[k], &phi));
    PetscInt nc, *idx = nullptr;
    PetscCall(DMPlexGetClosureIndices(dm, local, global, cells[k], PETSC_TRUE, &nc, &idx, nullptr, nullptr));
    std::vector<PetscInt> columns(nc);
    std::vector<double> values(nc);
    for (PetscInt b = 0; b < nc; ++b) {
      columns[b] = idx[b] >= 0 ? idx[b] : -(idx[b] + 1);
      values[b] = phi[b] / inside[row];
    }
    PetscCall(DMPlexRestoreClosureIndices(dm, local, global, cells[k], PETSC_TRUE, &nc, &idx, nullptr, nullptr));
    PetscCall(MatSetValues(S_, 1, &row, nc, columns.data(), values.data(), ADD_VALUES));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HeatCamera::Open(const std::string& dir) {
  PetscFunctionBeginUser;
  if (frames_ == 0) PetscFunctionReturn(0);
  const std::map<std::string, double> attributes = {{"fps", options_.fps},
                                                    {"pixel", grid_.pixel},
                                                    {"netd", options_.netd},
                                                    {"integration", options_.integration},
                                                    {"seed", static_cast<double>(options_.seed)},
                                                    {"samples", static_cast<double>(options_.samples)}};
  PetscCall(RunOnRoot(comm_, [&] { file_.Open(dir + "/camera.h5", grid_, attributes); }));
  PetscFunctionReturn(0);
}

PetscErrorCode HeatCamera::Sample(const heat::HeatSolver& heat) {
  PetscFunctionBeginUser;
  if (frame_ >= frames_) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(event_, 0, 0, 0, 0));
  const double t = heat.time();
  PetscCall(MatMult(S_, heat.rise(), current_));
  if (t_prev_ >= 0.0 && t > t_prev_) PetscCall(Integrate(t_prev_, t));
  PetscCall(VecCopy(current_, previous_));
  t_prev_ = t;
  PetscCall(PetscLogEventEnd(event_, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/// Adds ∫ over [t_prev, t] ∩ window of the pixels, linear in time between the two samples
/// (the trapezoid rule, exact for that interpolant, on any part of the step).
PetscErrorCode HeatCamera::Integrate(double tp, double t) {
  PetscFunctionBeginUser;
  const double h = t - tp;
  while (frame_ < frames_) {
    const double a = start(frame_), b = a + options_.integration;
    const double lo = std::max(a, tp), hi = std::min(b, t);
    if (hi > lo) {
      const double w_prev = ((t - lo) * (t - lo) - (t - hi) * (t - hi)) / (2 * h);
      const double w_now = ((hi - tp) * (hi - tp) - (lo - tp) * (lo - tp)) / (2 * h);
      PetscCall(VecAXPBYPCZ(integral_, w_prev, w_now, 1.0, previous_, current_));
    }
    if (t < b - 1e-9 * options_.integration) break;  // the window goes on
    PetscCall(EmitFrame());
    ++frame_;
  }
  PetscFunctionReturn(0);
}

/// The window's mean to rank 0, NETD noise added there, both written.
PetscErrorCode HeatCamera::EmitFrame() {
  PetscFunctionBeginUser;
  PetscCall(VecScale(integral_, 1.0 / options_.integration));
  PetscCall(VecScatterBegin(to_root_, integral_, on_root_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_root_, integral_, on_root_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecZeroEntries(integral_));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  std::vector<double> clean, noisy;
  if (rank == 0) {
    const PetscScalar* a;
    PetscInt n;
    PetscCall(VecGetLocalSize(on_root_, &n));
    PetscCall(VecGetArrayRead(on_root_, &a));
    clean.assign(a, a + n);
    PetscCall(VecRestoreArrayRead(on_root_, &a));
    std::normal_distribution<double> noise(0.0, options_.netd);
    noisy = clean;
    if (options_.netd > 0.0)
      for (double& v : noisy) v += noise(random_);
    peak_clean_.push_back(*std::max_element(clean.begin(), clean.end()));
    peak_noisy_.push_back(*std::max_element(noisy.begin(), noisy.end()));
  }
  const double a = start(frame_);
  PetscCall(RunOnRoot(comm_, [&] { file_.Write(static_cast<int>(frame_), a, a + options_.integration, clean, noisy); }));
  PetscFunctionReturn(0);
}

double HeatCamera::NextBoundary(double t) const {
  const double eps = 1e-12 * std::max(1.0, t);
  for (PetscInt k = frame_; k < frames_; ++k)
    for (double b : {start(k), start(k) + options_.integration})
      if (b > t + eps) return b;
  return std::numeric_limits<double>::infinity();
}

PetscErrorCode HeatCamera::Finish(io::RunSummary* summary) {
  PetscFunctionBeginUser;
  if (frames_ == 0) PetscFunctionReturn(0);
  if (frame_ < frames_)  // the heat ended inside a window (a run stopped short of -final_time)
    PetscCall(PetscPrintf(comm_, "vibrotherm: warning: camera: the heat ended at t = %g s, inside frame %" PetscInt_FMT
                                 ": %" PetscInt_FMT " frames written\n", t_prev_, frame_, frame_));
  frames_ = frame_;
  PetscCall(RunOnRoot(comm_, [&] { file_.Finish(); }));
  io::CameraSummary& c = summary->camera;
  c.frames = frames_;
  c.rows = static_cast<long long>(grid_.rows);
  c.cols = static_cast<long long>(grid_.cols);
  c.netd = options_.netd;
  c.detect_snr = options_.detect_snr;
  double best[2] = {-std::numeric_limits<double>::infinity(), 0.0};  // peak clean rise, its frame
  for (std::size_t k = 0; k < peak_clean_.size(); ++k)
    if (peak_clean_[k] > best[0]) best[0] = peak_clean_[k], best[1] = static_cast<double>(k);
  PetscCallMPI(MPI_Bcast(best, 2, MPI_DOUBLE, 0, comm_));
  c.peak_rise = frames_ > 0 ? best[0] : std::numeric_limits<double>::quiet_NaN();
  c.peak_frame = static_cast<long long>(best[1]);
  c.peak_time = start(c.peak_frame) + 0.5 * options_.integration;
  c.peak_snr = options_.netd > 0.0 ? best[0] / options_.netd : std::numeric_limits<double>::infinity();
  c.detectable = c.peak_snr >= options_.detect_snr;
  double first = -1.0;  // the first frame the camera would see the crack in
  for (std::size_t k = 0; k < peak_clean_.size() && first < 0.0; ++k)
    if (options_.netd > 0.0 && peak_clean_[k] / options_.netd >= options_.detect_snr)
      first = start(static_cast<PetscInt>(k)) + options_.integration;
  PetscCallMPI(MPI_Bcast(&first, 1, MPI_DOUBLE, 0, comm_));
  c.detection_time = first;
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
