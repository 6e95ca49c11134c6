// Requirement: the wave solution converges to the exact plane P wave with the
// expected order under h-refinement with dt ∝ h (degree 1: ≥ 1.8 with velocity
// Verlet; degree 2: ≥ 2.7 with RK4, since velocity Verlet caps the order at 2);
// absorbing edges reflect < 3 % of a P and of an S pulse at normal incidence.
#include <algorithm>
#include <cmath>

#include "wave_test_support.hpp"

namespace vibrotherm::testing {
namespace {

/// A vertical plane P wave from a normal displacement source on the top edge,
/// between roller sides: u = (0, g(t − (H − y)/c_p)).
std::string PlaneWaveOptions(double h, int degree, const char* ts) {
  char text[512];
  std::snprintf(text, sizeof(text),
                "-specimen_width 0.004 -specimen_height 0.02 -mesh_h %g -mesh_h_crack %g -edge_left roller "
                "-edge_right roller -edge_bottom absorbing -source_component normal -source_frequency 1e6 "
                "-source_amplitude 1e-8 -source_duration 1 -source_ramp_cycles 1 -wave_degree %d -wave_cfl 0.5 %s",
                h, h, degree, ts);
  return text;
}

double PlaneWaveError(double h, int degree, const char* ts) {
  ScopedWave w(PlaneWaveOptions(h, degree, ts));
  EXPECT_EQ(w.status, 0);
  const double t_end = 2.2e-6, H = 0.02, cp = w.material.cp();  // front at 13 mm: no reflection yet
  EXPECT_EQ(w.solver.AdvanceTo(t_end), 0);
  EXPECT_NEAR(w.solver.time(), t_end, 1e-12 * t_end) << "the TS must stop exactly at the requested time";
  const auto& sig = w.excitation.signal;
  double norm;
  const double err = w.L2Error(
      [&](double, double y) {
        double g, dg, ddg;
        sig.evaluate(t_end - (H - y) / cp, &g, &dg, &ddg);
        return std::array<double, 2>{0.0, g};
      },
      &norm);
  return err / norm;
}

TEST(WaveConvergence, DegreeOneSecondOrder) {
  const double e1 = PlaneWaveError(4e-4, 1, ""), e2 = PlaneWaveError(2e-4, 1, ""), e3 = PlaneWaveError(1e-4, 1, "");
  const double order = std::log2(e2 / e3);
  RecordProperty("errors", std::to_string(e1) + " " + std::to_string(e2) + " " + std::to_string(e3));
  EXPECT_GT(std::log2(e1 / e2), 1.8) << e1 << " " << e2;
  EXPECT_GT(order, 1.8) << e2 << " " << e3;
  EXPECT_LT(e3, 0.05);
}

TEST(WaveConvergence, DegreeTwoThirdOrder) {
  const char* rk4 = "-wave_ts_type rk -wave_ts_rk_type 4";
  const double e1 = PlaneWaveError(8e-4, 2, rk4), e2 = PlaneWaveError(4e-4, 2, rk4), e3 = PlaneWaveError(2e-4, 2, rk4);
  RecordProperty("errors", std::to_string(e1) + " " + std::to_string(e2) + " " + std::to_string(e3));
  EXPECT_GT(std::log2(e1 / e2), 2.7) << e1 << " " << e2;
  EXPECT_GT(std::log2(e2 / e3), 2.7) << e2 << " " << e3;
}

/// Largest |u| component at a probe over [t0, t1], sampled every step.
struct ProbeWindow {
  double t0, t1, max = 0.0;
};

/// Reflection of a 2-cycle burst from the bottom edge, seen at mid-height.
}  // namespace
double Reflection(const std::string& options, double c, double H, double probe_y, int component) {
  ScopedWave w(options);
  EXPECT_EQ(w.status, 0);
  const double burst = 2e-6, t_in = (H - probe_y) / c, t_back = (H + probe_y) / c;
  // The reflection cannot reach the probe before t_back; the incident burst (with
  // its dispersive tail) has passed by then since 2 probe_y / c > 1.5 burst.
  ProbeWindow incident{t_in, t_in + burst}, reflected{t_back - 0.05 * burst, t_back + burst};
  const double xp = 0.5 * std::stod(options.substr(options.find("-specimen_width ") + 16));
  PetscInt cell;
  std::array<double, 2> ref;
  w.solver.space().Locate(xp, probe_y, &cell, &ref);
  std::vector<double> phi;
  if (cell >= 0) w.solver.space().BasisAt(ref, &phi);
  w.solver.on_step = [&](const wave::WaveSolver& s) -> PetscErrorCode {
    DM dm = s.space().dm();
    Vec u, v, ul;
    PetscCall(s.GetFields(&u, &v));
    PetscCall(DMGetLocalVector(dm, &ul));
    PetscCall(DMGlobalToLocal(dm, u, INSERT_VALUES, ul));
    double value = 0.0;
    if (cell >= 0) {
      PetscSection section;
      PetscScalar* cu = nullptr;
      PetscInt n;
      PetscCall(DMGetLocalSection(dm, &section));
      PetscCall(DMPlexVecGetClosure(dm, section, ul, cell, &n, &cu));
      for (std::size_t b = 0; b < phi.size(); ++b) value += phi[b] * PetscRealPart(cu[2 * b + component]);
      PetscCall(DMPlexVecRestoreClosure(dm, section, ul, cell, &n, &cu));
    }
    PetscCall(DMRestoreLocalVector(dm, &ul));
    PetscCall(s.RestoreFields(&u, &v));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
    for (ProbeWindow* win : {&incident, &reflected})
      if (s.time() >= win->t0 && s.time() <= win->t1) win->max = std::max(win->max, std::abs(value));
    return 0;
  };
  EXPECT_EQ(w.solver.AdvanceTo(t_back + burst), 0);
  return reflected.max / incident.max;
}

namespace {
TEST(AbsorbingEdges, NormalIncidenceReflectsLessThanThreePercent) {
  const char* burst = "-source_frequency 1e6 -source_amplitude 1e-8 -source_duration 2e-6 -source_ramp_cycles 1 ";
  // P: roller sides keep the plane wave exact.
  const std::string p = std::string("-specimen_width 0.004 -specimen_height 0.02 -mesh_h 2e-4 -mesh_h_crack 2e-4 ") +
                        burst + "-edge_left roller -edge_right roller -source_component normal";
  ScopedWave probe_material("-mesh_h 0.05 -mesh_h_crack 0.05");
  const double cp = probe_material.material.cp(), cs = probe_material.material.cs();
  const double Rp = Reflection(p, cp, 0.02, 0.01, 1);
  EXPECT_LT(Rp, 0.03);
  // The same with a free bottom reflects fully: the measurement sees reflections.
  EXPECT_GT(Reflection(p + " -edge_bottom free", cp, 0.02, 0.01, 1), 0.8);
  // S: a wide plate, probe far from the free sides.
  const std::string s = std::string("-specimen_width 0.12 -specimen_height 0.016 -mesh_h 2.5e-4 -mesh_h_crack 2.5e-4 ") +
                        burst + "-edge_left free -edge_right free -source_component tangential";
  const double Rs = Reflection(s, cs, 0.016, 0.008, 0);
  EXPECT_LT(Rs, 0.03);
  RecordProperty("reflection_P", std::to_string(Rp));
  RecordProperty("reflection_S", std::to_string(Rs));
}

}  // namespace
}  // namespace vibrotherm::testing
