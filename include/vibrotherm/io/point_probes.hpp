// Point probes: a field of a LagrangeSpace evaluated at fixed points, written
// by rank 0 to probes.csv. Columns: t,probe,x,y,ux,uy,vx,vy,temperature and, for
// crack probes, a,b,b0,N,T,state,power,W (a column without data is nan); on a 3D
// mesh t,probe,x,y,z,ux,uy,uz,vx,vy,vz,temperature (no crack probes yet). Each
// point is evaluated by exactly one rank.
//
// Rows are held until Flush(): the temperature comes from the heat side
// (coupling/probe_temperatures.hpp), which gives it at every row time; a row
// at another time reads it interpolated linearly.
#pragma once

#include <petscvec.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/fe/point_location.hpp"
#include "vibrotherm/interface/crack_record.hpp"
#include "vibrotherm/store/atomic_file.hpp"

namespace vibrotherm::io {

/// Probe temperatures at increasing times; a time in between is interpolated linearly.
struct TemperatureSeries {
  std::vector<double> t;
  std::vector<std::vector<double>> T;  ///< T[k][probe] (point probes, then crack probes)
  double at(std::size_t probe, double time) const;
};

/// Locates the points xyz (dim() coordinates a point) in space and refuses, naming
/// -probe_points, one outside the specimen. Collective.
PetscErrorCode LocateProbePoints(const fe::LagrangeSpace& space, const std::vector<double>& xyz,
                                 std::vector<fe::LocatedPoint>* located);

class PointProbes {
 public:
  /// Locates the points (x, y pairs; x, y, z triples in 3D) in space; errors name -probe_points when a
  /// point lies outside the specimen. Rank 0 opens `path` (written atomically).
  /// resume_bytes >= 0: continue the interrupted run's file (checkpoint restart).
  PetscErrorCode Setup(const fe::LagrangeSpace& space, const std::vector<double>& xy, const std::string& path,
                       long long resume_bytes = -1);
  /// Checkpoints: bytes written (rank 0; no rows held), and leaving the file for a restart.
  long long bytes() const { return file_ ? file_->bytes() : 0; }
  void Keep() { if (file_) file_->keep(); }
  /// Holds one row per probe with displacement u and velocity v (global vectors).
  PetscErrorCode Record(double t, Vec u, Vec v);
  /// Holds a crack-probe row (rank 0).
  void RecordCrack(double t, std::size_t probe, const interface::CrackCellRecord& record);
  /// Writes the held rows; temperature from `temperature` (nullptr: nan).
  void Flush(const TemperatureSeries* temperature);
  /// Writes a row with only a temperature (after the waves have stopped).
  void WriteTemperature(double t, std::size_t probe, const std::array<double, 3>& x, double temperature);
  /// Publishes probes.csv (call once at the end of a successful run).
  PetscErrorCode Finish();
  std::size_t count() const { return points_.size(); }
  /// The points (z = 0 in 2D).
  const std::vector<std::array<double, 3>>& points() const { return points_; }

 private:
  struct Row {
    double t;
    std::size_t probe;
    double x, y, ux, uy, vx, vy;
    bool crack;
    interface::CrackCellRecord c;
    double z, uz, vz;  ///< 3D
  };
  const fe::LagrangeSpace* space_ = nullptr;
  int dim_ = 2;
  std::vector<std::array<double, 3>> points_;
  std::vector<fe::LocatedPoint> probes_;
  std::vector<Row> pending_;           ///< rank 0
  std::unique_ptr<store::AtomicFile> file_;  ///< rank 0
  Vec u_local_ = nullptr, v_local_ = nullptr;
};

}  // namespace vibrotherm::io
