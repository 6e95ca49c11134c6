// Whether the camera sees the DEFECT (not just any heat), frame by frame (plain C++).
// A frame holds the rise the camera reads, c (all heat), and the defect's own share
// of it, d: the rise the crack's friction heat alone causes (the heat solver's partial
// rise, by linearity; d = c when only the crack heats). The rest, b = c − d, is the
// background: material damping heat (largest where the velocity is, e.g. free corners),
// thermoelastic heat, a warm or cool ambient. Per frame:
//   signal     max d over the pixels (and where),
//   snr        signal / NETD,
//   contrast   signal / max b over the pixels (how the defect's hot spot compares with the
//              hottest background spot on the face; +inf without background),
//   detected   snr >= -camera_detect_snr and contrast >= -camera_detect_contrast,
// and where the hottest pixel of the whole frame is, and whether the defect makes it
// (d >= c/2 there). The run's verdict: the frame of the largest signal, the first frame
// detected (camera_detection_time), detectable if any frame is.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

namespace vibrotherm::coupling {

/// What of the heat field is the defect's own: all of it (only the crack heats), none (nothing
/// heats at the crack: an open crack, no crack), or a partial rise stepped beside it (the crack's
/// friction heat alone, when damping, thermoelastic or film heat heat the specimen too).
enum class DefectShare { Whole, None, Partial };

/// One frame's figures (rank 0 computes them from the gathered frame).
struct FrameVerdict {
  double t_end = 0.0;               ///< end of the frame's window [s]
  double total_peak = 0.0;          ///< max c [K]
  double total_pixel = 0.0;         ///< its pixel (row-major index)
  double defect_peak = 0.0;         ///< max d [K]
  double defect_pixel = 0.0;        ///< its pixel
  double background_peak = 0.0;     ///< max(b, 0) [K]
  double defect_at_total_peak = 0.0;  ///< d at the total peak's pixel [K]
  static constexpr std::size_t kValues = 7;  ///< for checkpoints (flattened in this order)
};

/// The figures of a frame of n pixels: c, and d (null: d = c, the crack the only heat; empty: d = 0).
FrameVerdict Judge(double t_end, const std::vector<double>& c, const std::vector<double>* d);

struct CameraCriteria {
  double netd = 0.02, detect_snr = 5.0, detect_contrast = 1.0;
};

/// The run's verdict over its frames.
struct DefectVerdict {
  double peak_snr = 0.0;           ///< the defect's largest signal / NETD
  double contrast = std::numeric_limits<double>::infinity();  ///< at the frame of that signal (+inf: no background)
  bool detectable = false;         ///< some frame detected
  double detection_time = -1.0;    ///< end of the first frame detected [s] (-1: none)
  std::size_t peak_frame = 0;      ///< frame of the largest signal
  std::size_t total_frame = 0;     ///< frame of the largest rise of all heat
  bool peak_on_defect = false;     ///< whether the defect makes that hottest pixel (d >= c/2 there)
};

DefectVerdict Summarise(const std::vector<FrameVerdict>& frames, const CameraCriteria& criteria);

}  // namespace vibrotherm::coupling
