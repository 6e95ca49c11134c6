// Point probes: a field of a LagrangeSpace evaluated at fixed points, written
// by rank 0 to probes.csv. Columns: t,probe,x,y,ux,uy,vx,vy,temperature and, for
// crack probes, a,b,b0,N,T,state,power,W (a column without data is nan). Each
// point is evaluated by exactly one rank.
#pragma once

#include <petscvec.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/io/atomic_file.hpp"

namespace vibrotherm::io {

class PointProbes {
 public:
  /// Locates the points (x, y pairs) in space; errors name -probe_points when a
  /// point lies outside the specimen. Rank 0 opens `path` (written atomically).
  PetscErrorCode Setup(const fe::LagrangeSpace& space, const std::vector<double>& xy, const std::string& path);
  /// Appends one row per probe with displacement u and velocity v (global vectors).
  PetscErrorCode Record(double t, Vec u, Vec v);
  /// Appends a crack-probe row (rank 0): x, y, ux, uy of the + node, then a, b, b0, N, T, state, power, W.
  void WriteCrackRow(double t, std::size_t probe, double x, double y, double ux, double uy, const double* crack);
  /// Publishes probes.csv (call once at the end of a successful run).
  PetscErrorCode Finish();
  std::size_t count() const { return points_.size(); }

 private:
  struct Probe {
    PetscInt cell = -1;  ///< local cell if this rank evaluates it
    std::vector<double> phi;
  };
  const fe::LagrangeSpace* space_ = nullptr;
  std::vector<std::array<double, 2>> points_;
  std::vector<Probe> probes_;
  std::unique_ptr<AtomicFile> file_;  ///< rank 0
  Vec u_local_ = nullptr, v_local_ = nullptr;
};

}  // namespace vibrotherm::io
