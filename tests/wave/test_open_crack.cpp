// Requirement: a crack without a contact law is traction-free: a wave hitting
// it changes the transmitted signal relative to the uncracked specimen, and
// the crack faces separate (a non-zero displacement jump across the crack).
#include <algorithm>
#include <cmath>

#include "wave_test_support.hpp"

namespace vibrotherm::testing {
namespace {

const std::string kScene =
    "-specimen_width 0.05 -specimen_height 0.06 -mesh_h 1e-3 -mesh_h_crack 5e-4 -source_frequency 2e5 "
    "-source_amplitude 1e-7 -source_duration 1.5e-5 -source_ramp_cycles 1 -wave_degree 1 ";
const std::string kCrack = "-crack_center 0.025,0.03 -crack_length 0.03 -crack_angle 0 ";

/// u_x history at a point below the crack, and the largest crack-face jump seen.
struct Observation {
  std::vector<double> t, ux;
  /// u_x at time t by linear interpolation.
  double at(double time) const {
    const auto it = std::lower_bound(t.begin(), t.end(), time);
    if (it == t.begin()) return ux.front();
    if (it == t.end()) return ux.back();
    const std::size_t k = it - t.begin();
    const double s = (time - t[k - 1]) / (t[k] - t[k - 1]);
    return (1 - s) * ux[k - 1] + s * ux[k];
  }
  double max_jump = 0.0, max_u = 0.0;
};

Observation Observe(const std::string& options) {
  Observation o;
  ScopedWave w(options);
  EXPECT_EQ(w.status, 0);
  const fe::LagrangeSpace& space = w.solver.space();
  DM dm = space.dm();
  const PointSampler probe_below(space, 0.025, 0.012);
  // Crack node pairs: the tensor edges of the cohesive cells (side A, side B vertices).
  std::vector<std::array<PetscInt, 2>> pairs;
  PetscInt cStart, cEnd;
  DMPlexGetHeightStratum(dm, 0, &cStart, &cEnd);
  for (PetscInt c = cStart; c < cEnd; ++c) {
    bool cohesive;
    mesh::IsCohesiveCell(dm, c, &cohesive);
    if (!cohesive) continue;
    const PetscInt* cone;
    DMPlexGetCone(dm, c, &cone);
    for (int k = 2; k < 4; ++k) {
      const PetscInt* vv;
      DMPlexGetCone(dm, cone[k], &vv);
      if (vv[0] != vv[1]) pairs.push_back({vv[0], vv[1]});
    }
  }
  w.solver.on_step = [&](const wave::WaveSolver& s) -> PetscErrorCode {
    Vec u, v, ul;
    PetscCall(s.GetFields(&u, &v));
    PetscCall(DMGetLocalVector(dm, &ul));
    PetscCall(DMGlobalToLocal(dm, u, INSERT_VALUES, ul));
    PetscSection section;
    PetscCall(DMGetLocalSection(dm, &section));
    const PetscScalar* a;
    PetscCall(VecGetArrayRead(ul, &a));
    double jump = 0.0;
    for (const auto& p : pairs) {
      PetscInt oa, ob;
      PetscCall(PetscSectionGetOffset(section, p[0], &oa));
      PetscCall(PetscSectionGetOffset(section, p[1], &ob));
      jump = std::max(jump, std::hypot(a[oa] - a[ob], a[oa + 1] - a[ob + 1]));
    }
    PetscCall(VecRestoreArrayRead(ul, &a));
    PetscCall(DMRestoreLocalVector(dm, &ul));
    PetscCall(s.RestoreFields(&u, &v));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &jump, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD));
    const double probe = probe_below.Sample(s)[0];
    o.t.push_back(s.time());
    o.ux.push_back(probe);
    o.max_jump = std::max(o.max_jump, jump);
    o.max_u = std::max(o.max_u, std::abs(probe));
    return 0;
  };
  EXPECT_EQ(w.solver.AdvanceTo(3e-5), 0);  // the S wave (3.2 km/s) crosses the crack at ~9 µs, the probe at ~15 µs
  return o;
}

TEST(OpenCrack, ChangesTheTransmittedWaveAndOpens) {
  const Observation intact = Observe(kScene), cracked = Observe(kScene + kCrack);
  double diff = 0.0, ref = 0.0;
  for (std::size_t k = 0; k < intact.ux.size(); ++k) {
    const double c = cracked.at(intact.t[k]);
    diff += (c - intact.ux[k]) * (c - intact.ux[k]);
    ref += intact.ux[k] * intact.ux[k];
  }
  EXPECT_GT(std::sqrt(diff / ref), 0.3) << "the crack should block a large part of the shear wave";
  EXPECT_EQ(intact.max_jump, 0.0);
  EXPECT_GT(cracked.max_jump, 0.1 * cracked.max_u) << "the faces of an open crack move apart";
  EXPECT_GT(cracked.max_jump, 1e-9);
}

}  // namespace
}  // namespace vibrotherm::testing
