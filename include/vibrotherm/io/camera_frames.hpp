// camera.h5 + camera.xmf: the IR camera's frames (rank 0 only; HDF5 C API).
// Layout (every dataset has a string attribute `units`):
//   /camera/frame_k   rows × cols [K]: temperature rise the camera reads (with NETD noise)
//   /camera/clean_k   rows × cols [K]: the same frame without noise
//   /camera/defect_k  rows × cols [K]: the defect's own share of clean_k (the crack's friction heat
//                     alone), written when other heat shares the frame or none is the defect's
//                     both with attributes `time` (window centre), `window_start`, `window_end` [s]
//   /camera/time      frames × 3 [s]: centre, start, end of each frame's integration window
//   /camera/x, /y     pixel centres [m] (cols, rows); row 0 is the bottom row (y ascending)
//   group /camera attributes: fps, pixel, netd, integration, seed, window (x0 y0 x1 y1 imaged)
// The .h5 is written as .partial and renamed by Finish; the .xmf (a temporal
// collection of one-pixel-thick 3DCoRectMesh slabs, frames as cell data, which both
// ParaView XDMF readers show in the x-y plane) is written last.
#pragma once

#include <hdf5.h>

#include <map>
#include <string>
#include <vector>

namespace vibrotherm::io {

struct CameraGrid {
  std::size_t rows = 0, cols = 0;
  double x0 = 0.0, y0 = 0.0;  ///< lower-left corner of pixel (0, 0) [m]
  double pixel = 0.0;         ///< pixel size [m]
};

class CameraFrames {
 public:
  CameraFrames() = default;
  CameraFrames(const CameraFrames&) = delete;
  CameraFrames& operator=(const CameraFrames&) = delete;
  ~CameraFrames();
  /// Creates "<path>.partial" with the grid and the group attributes. Throws std::runtime_error naming the path.
  void Open(const std::string& h5_path, const CameraGrid& grid, const std::map<std::string, double>& attributes);
  /// Restart: reopens the "<path>.partial" an interrupted run left, keeping its
  /// first `kept` frames (later ones are dropped) and their time rows. Throws naming the path.
  void Reopen(const std::string& h5_path, const CameraGrid& grid, int kept, const std::vector<double>& times);
  /// Centre, start and end of every frame written (checkpoints).
  const std::vector<double>& times() const { return times_; }
  /// Frame k integrated over [start, end]: clean and noisy values, rows × cols row-major.
  void Write(int k, double start, double end, const std::vector<double>& clean, const std::vector<double>& noisy);
  /// The defect's share of frame k (after Write).
  void WriteDefect(int k, double start, double end, const std::vector<double>& defect);
  /// Flushes everything written to disk (after each frame).
  void Flush();
  /// Writes the time table, closes and renames the .h5, then writes the .xmf.
  void Finish();
  bool open() const { return file_ >= 0; }

 private:
  void WriteArray(const std::string& name, const std::vector<double>& values, std::size_t rows, std::size_t cols,
                  const std::string& units, const std::map<std::string, double>& attributes);
  void WriteXdmf() const;
  std::string path_;
  hid_t file_ = -1, group_ = -1;
  CameraGrid grid_;
  std::vector<double> times_;  ///< centre, start, end per frame
  bool defect_ = false;        ///< defect_k written
};

}  // namespace vibrotherm::io
