#include "vibrotherm/io/point_probes.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

double TemperatureSeries::at(std::size_t probe, double time) const {
  if (t.empty() || probe >= T.front().size()) return NAN;
  const std::size_t k = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), time) - t.begin());
  if (k == t.size()) return T.back()[probe];
  if (k == 0 || t[k] == time) return T[k][probe];
  const double s = (time - t[k - 1]) / (t[k] - t[k - 1]);
  return (1.0 - s) * T[k - 1][probe] + s * T[k][probe];
}

PetscErrorCode LocateProbePoints(const fe::LagrangeSpace& space, const std::vector<double>& xyz,
                                 std::vector<fe::LocatedPoint>* located) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)space.dm());
  const std::size_t D = static_cast<std::size_t>(space.dim());
  PetscCheck(xyz.size() % D == 0, comm, PETSC_ERR_USER_INPUT, "-probe_points needs %s",
             D == 2 ? "x,y pairs" : "x,y,z triples in 3D");
  std::vector<bool> inside;
  PetscCall(fe::LocatePoints(space, xyz, located, &inside));
  for (std::size_t i = 0; i < inside.size(); ++i) {
    if (D == 2)
      PetscCheck(inside[i], comm, PETSC_ERR_USER_INPUT, "-probe_points: point %zu (%g, %g) lies outside the specimen",
                 i + 1, xyz[2 * i], xyz[2 * i + 1]);
    PetscCheck(inside[i], comm, PETSC_ERR_USER_INPUT, "-probe_points: point %zu (%g, %g, %g) lies outside the specimen",
               i + 1, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PointProbes::Setup(const fe::LagrangeSpace& space, const std::vector<double>& xy,
                                  const std::string& path, long long resume_bytes) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  space_ = &space;
  dim_ = space.dim();
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(LocateProbePoints(space, xy, &probes_));
  points_.clear();
  for (std::size_t i = 0; i < probes_.size(); ++i)
    points_.push_back({xy[dim_ * i], xy[dim_ * i + 1], dim_ == 3 ? xy[3 * i + 2] : 0.0});
  if (rank == 0) {
    VibrothermCallCpp(PETSC_COMM_SELF, file_ = store::OpenAtomicFile(path, resume_bytes));
    // 12 significant digits (2-rank runs equal serial ones to 1e-10 of the amplitude),
    // the temperature 17 (a rise of 1e-7 K on 293 K); a third smaller than all at 17.
    file_->stream().precision(12);
    if (resume_bytes < 0)
      file_->stream() << (dim_ == 2 ? "t,probe,x,y,ux,uy,vx,vy,temperature,a,b,b0,N,T,state,power,W\n"
                                    : "t,probe,x,y,z,ux,uy,uz,vx,vy,vz,temperature\n");
  }
  PetscCall(DMCreateLocalVector(dm, &u_local_));
  PetscCall(DMCreateLocalVector(dm, &v_local_));
  PetscFunctionReturn(0);
}

PetscErrorCode PointProbes::Record(double t, Vec u, Vec v) {
  PetscFunctionBeginUser;
  if (points_.empty()) PetscFunctionReturn(0);
  DM dm = space_->dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscCall(DMGlobalToLocal(dm, u, INSERT_VALUES, u_local_));
  PetscCall(DMGlobalToLocal(dm, v, INSERT_VALUES, v_local_));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  const int D = dim_, stride = 2 * D;  // u then v, D components each
  std::vector<double> values(stride * points_.size(), 0.0), all(values.size());
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    if (probes_[p].cell < 0) continue;
    PetscScalar *cu = nullptr, *cv = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm, section, u_local_, probes_[p].cell, &n, &cu));
    PetscCall(DMPlexVecGetClosure(dm, section, v_local_, probes_[p].cell, &n, &cv));
    for (std::size_t b = 0; b < probes_[p].phi.size(); ++b)
      for (int c = 0; c < D; ++c) {
        values[stride * p + c] += probes_[p].phi[b] * PetscRealPart(cu[D * b + c]);
        values[stride * p + D + c] += probes_[p].phi[b] * PetscRealPart(cv[D * b + c]);
      }
    PetscCall(DMPlexVecRestoreClosure(dm, section, u_local_, probes_[p].cell, &n, &cu));
    PetscCall(DMPlexVecRestoreClosure(dm, section, v_local_, probes_[p].cell, &n, &cv));
  }
  PetscCallMPI(MPI_Reduce(values.data(), all.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, 0, comm));
  if (file_)
    for (std::size_t p = 0; p < points_.size(); ++p) {
      const double* u = &all[stride * p];
      pending_.push_back({t, p, points_[p][0], points_[p][1], u[0], u[1], u[D], u[D + 1], false, {}, points_[p][2],
                          D == 3 ? u[2] : 0.0, D == 3 ? u[5] : 0.0});
    }
  PetscFunctionReturn(0);
}

void PointProbes::RecordCrack(double t, std::size_t probe, const interface::CrackCellRecord& c) {
  if (!file_) return;
  pending_.push_back({t, probe, c.x, c.y, c.ux, c.uy, NAN, NAN, true, c, 0.0, 0.0, 0.0});
}

void PointProbes::Flush(const TemperatureSeries* temperature) {
  if (!file_) return;
  std::ostream& out = file_->stream();
  for (const Row& r : pending_) {
    const double T = temperature ? temperature->at(r.probe, r.t) : NAN;
    if (dim_ == 3) {
      out << r.t << ',' << r.probe << ',' << r.x << ',' << r.y << ',' << r.z << ',' << r.ux << ',' << r.uy << ','
          << r.uz << ',' << r.vx << ',' << r.vy << ',' << r.vz << ',' << std::setprecision(17) << T
          << std::setprecision(12) << '\n';
      continue;
    }
    out << r.t << ',' << r.probe << ',' << r.x << ',' << r.y << ',' << r.ux << ',' << r.uy << ',' << r.vx << ','
        << r.vy << ',' << std::setprecision(17) << T << std::setprecision(12);
    if (r.crack) {
      out << ',' << r.c.a << ',' << r.c.b << ',' << r.c.b0 << ',' << r.c.N << ',' << r.c.T << ','
          << contact::to_string(r.c.state) << ',' << r.c.power << ',' << r.c.W << '\n';
    } else {
      out << ",nan,nan,nan,nan,nan,,nan,nan\n";
    }
  }
  pending_.clear();
}

void PointProbes::WriteTemperature(double t, std::size_t probe, const std::array<double, 3>& x, double temperature) {
  if (!file_) return;
  std::ostream& out = file_->stream();
  out << t << ',' << probe << ',' << x[0] << ',' << x[1];
  if (dim_ == 3) {  // t,probe,x,y,z,ux,uy,uz,vx,vy,vz,temperature
    out << ',' << x[2] << ",nan,nan,nan,nan,nan,nan," << std::setprecision(17) << temperature
        << std::setprecision(12) << '\n';
    return;
  }
  out << ",nan,nan,nan,nan," << std::setprecision(17) << temperature << std::setprecision(12)
      << ",nan,nan,nan,nan,nan,,nan,nan\n";
}

PetscErrorCode PointProbes::Finish() {
  PetscFunctionBeginUser;
  Flush(nullptr);
  if (file_) VibrothermCallIo(PETSC_COMM_SELF, file_->commit());
  PetscCall(VecDestroy(&u_local_));
  PetscCall(VecDestroy(&v_local_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
