#include "vibrotherm/io/point_probes.hpp"

#include <petscdmplex.h>

#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::io {

PetscErrorCode PointProbes::Setup(const fe::LagrangeSpace& space, const std::vector<double>& xy,
                                  const std::string& path) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  space_ = &space;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCheck(xy.size() % 2 == 0, comm, PETSC_ERR_USER_INPUT, "-probe_points needs x,y pairs");
  points_.clear();
  probes_.clear();
  for (std::size_t i = 0; i < xy.size(); i += 2) {
    Probe p;
    std::array<double, 2> ref;
    PetscCall(space.Locate(xy[i], xy[i + 1], &p.cell, &ref));
    // The lowest rank holding the point evaluates it.
    PetscMPIInt mine = p.cell >= 0 ? rank : PETSC_MPI_INT_MAX, owner;
    PetscCallMPI(MPI_Allreduce(&mine, &owner, 1, MPI_INT, MPI_MIN, comm));
    PetscCheck(owner != PETSC_MPI_INT_MAX, comm, PETSC_ERR_USER_INPUT,
               "-probe_points: point %zu (%g, %g) lies outside the specimen", i / 2 + 1, xy[i], xy[i + 1]);
    if (owner != rank) p.cell = -1;
    if (p.cell >= 0) PetscCall(space.BasisAt(ref, &p.phi));
    points_.push_back({xy[i], xy[i + 1]});
    probes_.push_back(std::move(p));
  }
  if (rank == 0) {
    VibrothermCallCpp(PETSC_COMM_SELF, file_ = std::make_unique<AtomicFile>(path));
    file_->stream() << "t,probe,x,y,ux,uy,vx,vy,temperature,a,b,b0,N,T,state,power,W\n";
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
  std::vector<double> values(4 * points_.size(), 0.0), all(values.size());
  for (std::size_t p = 0; p < probes_.size(); ++p) {
    if (probes_[p].cell < 0) continue;
    PetscScalar *cu = nullptr, *cv = nullptr;
    PetscInt n = 0;
    PetscCall(DMPlexVecGetClosure(dm, section, u_local_, probes_[p].cell, &n, &cu));
    PetscCall(DMPlexVecGetClosure(dm, section, v_local_, probes_[p].cell, &n, &cv));
    for (std::size_t b = 0; b < probes_[p].phi.size(); ++b)
      for (int c = 0; c < 2; ++c) {
        values[4 * p + c] += probes_[p].phi[b] * PetscRealPart(cu[2 * b + c]);
        values[4 * p + 2 + c] += probes_[p].phi[b] * PetscRealPart(cv[2 * b + c]);
      }
    PetscCall(DMPlexVecRestoreClosure(dm, section, u_local_, probes_[p].cell, &n, &cu));
    PetscCall(DMPlexVecRestoreClosure(dm, section, v_local_, probes_[p].cell, &n, &cv));
  }
  PetscCallMPI(MPI_Reduce(values.data(), all.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, 0, comm));
  if (file_) {
    std::ostream& out = file_->stream();
    for (std::size_t p = 0; p < points_.size(); ++p)
      out << t << ',' << p << ',' << points_[p][0] << ',' << points_[p][1] << ',' << all[4 * p] << ','
          << all[4 * p + 1] << ',' << all[4 * p + 2] << ',' << all[4 * p + 3] << ",nan,nan,nan,nan,nan,nan,,nan,nan\n";
  }
  PetscFunctionReturn(0);
}

void PointProbes::WriteCrackRow(double t, std::size_t probe, double x, double y, double ux, double uy,
                                const double* c) {
  static const char* states[] = {"loss", "slide", "partial", "stick"};
  if (!file_) return;
  const int state = static_cast<int>(c[5]);
  file_->stream() << t << ',' << probe << ',' << x << ',' << y << ',' << ux << ',' << uy << ",nan,nan,nan," << c[0]
                  << ',' << c[1] << ',' << c[2] << ',' << c[3] << ',' << c[4] << ','
                  << (state >= 0 && state < 4 ? states[state] : "?") << ',' << c[6] << ',' << c[7] << '\n';
}

PetscErrorCode PointProbes::Finish() {
  PetscFunctionBeginUser;
  if (file_) VibrothermCallCpp(PETSC_COMM_SELF, file_->commit());
  PetscCall(VecDestroy(&u_local_));
  PetscCall(VecDestroy(&v_local_));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
