// A specimen plus a WaveSolver configured from an options string, for tests.
#pragma once

#include <cmath>
#include <functional>
#include <memory>

#include "mesh_test_support.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

namespace vibrotherm::testing {

/// Displacement of a wave solver at a fixed point, reduced over ranks.
class PointSampler {
 public:
  PointSampler(const fe::LagrangeSpace& space, double x, double y) : space_(space) {
    std::array<double, 2> ref;
    space.Locate(x, y, &cell_, &ref);
    if (cell_ >= 0) space.BasisAt(ref, &phi_);
  }
  /// u at the point (collective).
  std::array<double, 2> Sample(const wave::WaveSolver& s) const {
    DM dm = space_.dm();
    Vec u, v, ul;
    s.GetFields(&u, &v);
    DMGetLocalVector(dm, &ul);
    DMGlobalToLocal(dm, u, INSERT_VALUES, ul);
    double value[2] = {0.0, 0.0};
    if (cell_ >= 0) {
      PetscSection section;
      PetscScalar* cu = nullptr;
      PetscInt n;
      DMGetLocalSection(dm, &section);
      DMPlexVecGetClosure(dm, section, ul, cell_, &n, &cu);
      for (std::size_t q = 0; q < phi_.size(); ++q)
        for (int k = 0; k < 2; ++k) value[k] += phi_[q] * PetscRealPart(cu[2 * q + k]);
      DMPlexVecRestoreClosure(dm, section, ul, cell_, &n, &cu);
    }
    DMRestoreLocalVector(dm, &ul);
    s.RestoreFields(&u, &v);
    MPI_Allreduce(MPI_IN_PLACE, value, 2, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    return {value[0], value[1]};
  }

 private:
  const fe::LagrangeSpace& space_;
  PetscInt cell_ = -1;
  std::vector<double> phi_;
};

struct ScopedWave {
  std::unique_ptr<ScopedSpecimen> specimen;
  wave::WaveSolver solver;
  wave::ElasticMaterial material;
  wave::Excitation excitation;
  PetscErrorCode status = 0;
  explicit ScopedWave(const std::string& options) {
    specimen = std::make_unique<ScopedSpecimen>(options);
    status = specimen->status;
    wave::WaveOptions wo;
    if (!status) status = wave::ReadElasticMaterial(PETSC_COMM_WORLD, &material);
    if (!status) status = wave::ReadExcitation(PETSC_COMM_WORLD, &excitation);
    if (!status) status = wave::ReadWaveOptions(PETSC_COMM_WORLD, &wo);
    if (!status) status = solver.Setup(specimen->specimen.wave, material, excitation, wo);
  }
  /// Discrete total energy: kinetic + strain + the integrator's term.
  double discrete_energy() const {
    wave::WaveEnergy e;
    solver.Energy(&e);
    return e.kinetic + e.strain + e.integrator;
  }
  /// Σ over local nodes of f(node x, node y, ux, uy) reduced over ranks (global vector values).
  double L2Error(const std::function<std::array<double, 2>(double, double)>& exact, double* norm) const {
    const fe::LagrangeSpace& space = solver.space();
    DM dm = space.dm();
    Vec u, v, ul;
    solver.GetFields(&u, &v);
    DMGetLocalVector(dm, &ul);
    DMGlobalToLocal(dm, u, INSERT_VALUES, ul);
    PetscSection section;
    DMGetLocalSection(dm, &section);
    fe::CellQuadrature q;
    std::vector<double> xy;
    double err = 0.0, ref = 0.0;
    for (PetscInt c : space.cells()) {
      space.Evaluate(c, &q);
      space.QuadraturePoints(c, &xy);
      PetscScalar* cu = nullptr;
      PetscInt n;
      DMPlexVecGetClosure(dm, section, ul, c, &n, &cu);
      for (int p = 0; p < q.points; ++p) {
        double uh[2] = {0, 0};
        for (int b = 0; b < q.nodes; ++b)
          for (int k = 0; k < 2; ++k) uh[k] += q.value[p * q.nodes + b] * PetscRealPart(cu[2 * b + k]);
        const auto ue = exact(xy[2 * p], xy[2 * p + 1]);
        err += q.weight[p] * ((uh[0] - ue[0]) * (uh[0] - ue[0]) + (uh[1] - ue[1]) * (uh[1] - ue[1]));
        ref += q.weight[p] * (ue[0] * ue[0] + ue[1] * ue[1]);
      }
      DMPlexVecRestoreClosure(dm, section, ul, c, &n, &cu);
    }
    DMRestoreLocalVector(dm, &ul);
    solver.RestoreFields(&u, &v);
    double local[2] = {err, ref}, global[2];
    MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    *norm = std::sqrt(global[1]);
    return std::sqrt(global[0]);
  }
};

}  // namespace vibrotherm::testing
