#include "vibrotherm/coupling/observe/camera_verdict.hpp"

#include <algorithm>
#include <cmath>

namespace vibrotherm::coupling {

FrameVerdict Judge(double t_end, const std::vector<double>& c, const std::vector<double>* d) {
  FrameVerdict v;
  v.t_end = t_end;
  if (c.empty()) return v;
  const auto defect = [&](std::size_t i) { return d == nullptr ? c[i] : d->empty() ? 0.0 : (*d)[i]; };
  std::size_t total = 0, signal = 0;
  double background = 0.0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i] > c[total]) total = i;
    if (defect(i) > defect(signal)) signal = i;
    background = std::max(background, c[i] - defect(i));
  }
  v.total_peak = c[total], v.total_pixel = static_cast<double>(total);
  v.defect_peak = defect(signal), v.defect_pixel = static_cast<double>(signal);
  v.background_peak = background;
  v.defect_at_total_peak = defect(total);
  return v;
}

namespace {

double Snr(double rise, double netd) {
  return netd > 0.0 ? rise / netd : (rise > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
}

double Contrast(const FrameVerdict& f) {
  return f.background_peak > 0.0 ? f.defect_peak / f.background_peak : std::numeric_limits<double>::infinity();
}

}  // namespace

DefectVerdict Summarise(const std::vector<FrameVerdict>& frames, const CameraCriteria& criteria) {
  DefectVerdict v;
  if (frames.empty()) return v;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const FrameVerdict& f = frames[k];
    if (f.defect_peak > frames[v.peak_frame].defect_peak) v.peak_frame = k;
    if (f.total_peak > frames[v.total_frame].total_peak) v.total_frame = k;
    const bool seen = f.defect_peak > 0.0 && Snr(f.defect_peak, criteria.netd) >= criteria.detect_snr &&
                      Contrast(f) >= criteria.detect_contrast;
    if (seen && !v.detectable) v.detectable = true, v.detection_time = f.t_end;
  }
  const FrameVerdict& peak = frames[v.peak_frame];
  v.peak_snr = Snr(peak.defect_peak, criteria.netd);
  v.contrast = Contrast(peak);
  const FrameVerdict& hottest = frames[v.total_frame];
  v.peak_on_defect = hottest.total_peak > 0.0 && hottest.defect_at_total_peak >= 0.5 * hottest.total_peak;
  return v;
}

}  // namespace vibrotherm::coupling
