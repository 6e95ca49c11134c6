#include "vibrotherm/coupling/observe/heat_camera.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <limits>
#include <map>

#include "vibrotherm/fe/cell_locator.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::coupling {
namespace {
constexpr double kMaxSamplePoints = 2e7;  ///< sub-sample points located at setup, at most

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}
}

HeatCamera::~HeatCamera() {
  (void)MatDestroy(&S_);
  (void)VecDestroy(&current_);
  (void)VecDestroy(&previous_);
  (void)VecDestroy(&integral_);
  (void)VecDestroy(&on_root_);
  for (Vec* v : {&defect_current_, &defect_previous_, &defect_integral_}) (void)VecDestroy(v);
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
    for (Vec* v : {&defect_current_, &defect_previous_, &defect_integral_}) {
      PetscCall(VecDuplicate(current_, v));
      PetscCall(VecZeroEntries(*v));
    }
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
  const bool partial = share_ == DefectShare::Partial && heat.partial_rise();
  if (partial) PetscCall(MatMult(S_, heat.partial_rise(), defect_current_));
  if (t_prev_ >= 0.0 && t > t_prev_) PetscCall(Integrate(t_prev_, t));
  PetscCall(VecCopy(current_, previous_));
  if (partial) PetscCall(VecCopy(defect_current_, defect_previous_));
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
      if (share_ == DefectShare::Partial)
        PetscCall(VecAXPBYPCZ(defect_integral_, w_prev, w_now, 1.0, defect_previous_, defect_current_));
    }
    if (t < b - 1e-9 * options_.integration) break;  // the window goes on
    PetscCall(EmitFrame());
    ++frame_;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode HeatCamera::GatherMean(Vec integral, std::vector<double>* mean) {
  PetscFunctionBeginUser;
  PetscCall(VecScale(integral, 1.0 / options_.integration));
  PetscCall(VecScatterBegin(to_root_, integral, on_root_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(to_root_, integral, on_root_, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecZeroEntries(integral));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  mean->clear();
  if (rank == 0) {
    const PetscScalar* a;
    PetscInt n;
    PetscCall(VecGetLocalSize(on_root_, &n));
    PetscCall(VecGetArrayRead(on_root_, &a));
    mean->assign(a, a + n);
    PetscCall(VecRestoreArrayRead(on_root_, &a));
  }
  PetscFunctionReturn(0);
}

/// The window's mean to rank 0, NETD noise added there, both written; the defect's share beside it.
PetscErrorCode HeatCamera::EmitFrame() {
  PetscFunctionBeginUser;
  std::vector<double> clean, noisy, defect;
  PetscCall(GatherMean(integral_, &clean));
  if (share_ == DefectShare::Partial) PetscCall(GatherMean(defect_integral_, &defect));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  const double a = start(frame_);
  if (rank == 0) {
    std::normal_distribution<double> noise(0.0, options_.netd);
    noisy = clean;
    if (options_.netd > 0.0)
      for (double& v : noisy) v += noise(random_);
    peak_clean_.push_back(*std::max_element(clean.begin(), clean.end()));
    peak_noisy_.push_back(*std::max_element(noisy.begin(), noisy.end()));
    if (share_ == DefectShare::None) defect.assign(clean.size(), 0.0);
    verdicts_.push_back(Judge(a + options_.integration, clean, share_ == DefectShare::Whole ? nullptr : &defect));
  }
  PetscCall(RunOnRoot(comm_, [&] {
    file_.Write(static_cast<int>(frame_), a, a + options_.integration, clean, noisy);
    if (share_ != DefectShare::Whole) file_.WriteDefect(static_cast<int>(frame_), a, a + options_.integration, defect);
  }));
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
  c.detect_contrast = options_.detect_contrast;
  c.defect_share = share_ == DefectShare::Whole ? "whole" : share_ == DefectShare::None ? "none" : "partial";
  PetscCall(SummariseVerdict(&c));
  PetscCall(SayVerdict(c));
  PetscFunctionReturn(0);
}

std::array<double, 2> HeatCamera::PixelCentre(double pixel) const {
  const std::size_t p = static_cast<std::size_t>(pixel), row = p / grid_.cols, col = p % grid_.cols;
  return {grid_.x0 + (col + 0.5) * grid_.pixel, grid_.y0 + (row + 0.5) * grid_.pixel};
}

/// The verdict about the defect (camera_verdict.hpp) from rank 0's frames, on every rank.
PetscErrorCode HeatCamera::SummariseVerdict(io::CameraSummary* c) const {
  PetscFunctionBeginUser;
  const CameraCriteria criteria{options_.netd, options_.detect_snr, options_.detect_contrast};
  const DefectVerdict v = Summarise(verdicts_, criteria);
  const FrameVerdict none;
  const FrameVerdict& hot = verdicts_.empty() ? none : verdicts_[v.total_frame];
  const FrameVerdict& seen = verdicts_.empty() ? none : verdicts_[v.peak_frame];
  const auto at = PixelCentre(hot.total_pixel), defect_at = PixelCentre(seen.defect_pixel);
  const double mid = 0.5 * options_.integration;
  double values[17] = {hot.total_peak, static_cast<double>(v.total_frame), hot.t_end - mid, at[0], at[1],
                       v.peak_on_defect ? 1.0 : 0.0, seen.defect_peak, seen.t_end - mid, defect_at[0], defect_at[1],
                       seen.background_peak, v.peak_snr, v.contrast, v.detectable ? 1.0 : 0.0, v.detection_time,
                       static_cast<double>(v.peak_frame), hot.defect_at_total_peak};
  PetscCallMPI(MPI_Bcast(values, 17, MPI_DOUBLE, 0, comm_));
  c->peak_rise = frames_ > 0 ? values[0] : std::numeric_limits<double>::quiet_NaN();
  c->peak_frame = static_cast<long long>(values[1]);
  c->peak_time = values[2];
  c->peak_at = {values[3], values[4]};
  c->peak_on_defect = values[5] != 0.0;
  c->defect_peak_rise = values[6];
  const bool signal = values[6] > 0.0, nan = std::numeric_limits<double>::quiet_NaN();  // no signal: nowhere
  c->defect_peak_time = signal ? values[7] : nan;
  c->defect_peak_at = {signal ? values[8] : nan, signal ? values[9] : nan};
  c->background_peak_rise = values[10];
  c->peak_snr = values[11];
  c->contrast = values[12];
  c->detectable = values[13] != 0.0;
  c->detection_time = values[14];
  c->defect_peak_frame = static_cast<long long>(values[15]);
  c->total_peak_snr = options_.netd > 0.0 ? values[0] / options_.netd : std::numeric_limits<double>::infinity();
  PetscFunctionReturn(0);
}

/// The verdict in words (the console's last lines of a run with a camera).
PetscErrorCode HeatCamera::SayVerdict(const io::CameraSummary& c) const {
  PetscFunctionBeginUser;
  const std::string contrast = std::isfinite(c.contrast)
                                   ? Format("%.3g", c.contrast) + "x the background's hottest pixel (needed " +
                                         Format("%g", c.detect_contrast) + ")"
                                   : "no background heat";
  std::string line;
  if (c.detectable)
    line = "the defect is detectable from t = " + Format("%.4g", c.detection_time) + " s (its own rise " +
           Format("%.3g", c.defect_peak_rise) + " K: SNR " + Format("%.3g", c.peak_snr) + ", needed " +
           Format("%g", c.detect_snr) + "; " + contrast + ")";
  else if (c.defect_share == "none")
    line = "the defect is not detectable: nothing heats at the crack (its faces neither rub nor slip: see -crack_law, "
           "-crack_a0 and the drive)";
  else
    line = "the defect is not detectable: its own rise " + Format("%.3g", c.defect_peak_rise) + " K is SNR " +
           Format("%.3g", c.peak_snr) + " (needed " + Format("%g", c.detect_snr) + "); " + contrast;
  PetscCall(PetscPrintf(comm_, "Camera: %s\n", line.c_str()));
  if (!c.peak_on_defect && c.peak_rise > 0.0)
    PetscCall(PetscPrintf(comm_, "Camera: its hottest pixel (%s K at %s, %s m, t = %s s) is background heat (material "
                                 "damping, thermoelastic or film heat), not the defect\n",
                          Format("%.3g", c.peak_rise).c_str(), Format("%.4g", c.peak_at[0]).c_str(),
                          Format("%.4g", c.peak_at[1]).c_str(), Format("%.4g", c.peak_time).c_str()));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
