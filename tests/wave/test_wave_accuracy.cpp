// Requirement: the wave solution converges to the exact plane P wave with the
// expected order under h-refinement with dt ∝ h (degree 1: ≥ 1.8 with velocity
// Verlet; degree 2: ≥ 2.7 with RK4, since velocity Verlet caps the order at 2);
// absorbing edges reflect < 3 % of a P and of an S pulse at normal incidence.
#include <gmsh.h>

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
  const PointSampler probe(w.solver.space(), xp, probe_y);
  w.solver.on_step = [&](const wave::WaveSolver& s) -> PetscErrorCode {
    const double value = probe.Sample(s)[component];
    for (ProbeWindow* win : {&incident, &reflected})
      if (s.time() >= win->t0 && s.time() <= win->t1) win->max = std::max(win->max, std::abs(value));
    return 0;
  };
  EXPECT_EQ(w.solver.AdvanceTo(t_back + burst), 0);
  return reflected.max / incident.max;
}

namespace {
TEST(AbsorbingEdges, NormalIncidenceReflectsLessThanThreePercent) {
  const char* burst = "-source_frequency 1e6 -source_amplitude 1e-8 -source_duration 2e-6 -source_ramp_cycles 1 -wave_degree 1 ";
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
  // Triangles: gmsh takes seconds to recombine this many quads.
  const std::string s = std::string("-specimen_width 0.12 -specimen_height 0.016 -mesh_h 2.5e-4 -mesh_h_crack 2.5e-4 -mesh_cell tri ") +
                        burst + "-edge_left free -edge_right free -source_component tangential";
  const double Rs = Reflection(s, cs, 0.016, 0.008, 0);
  EXPECT_LT(Rs, 0.03);
  RecordProperty("reflection_P", std::to_string(Rp));
  RecordProperty("reflection_S", std::to_string(Rs));
}

/// A strip [0, W] with a horizontal source top at y = top and an absorbing bottom
/// inclined at `angle_deg` (from (0, 0)); the sides are `sides` (roller for a
/// plane P wave, antisymmetric for a plane S wave: both keep the plane wave exact).
std::string InclinedBottomMesh(const char* sides, double W, double top, double angle_deg, double h) {
  const std::string path = ::testing::TempDir() + "inclined_" + sides + ".msh";
  PetscMPIInt rank;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (rank == 0) {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::model::add("inclined");
    const double rise = W * std::tan(angle_deg * M_PI / 180.0);
    const int p1 = gmsh::model::geo::addPoint(0, 0, 0, h), p2 = gmsh::model::geo::addPoint(W, rise, 0, h);
    const int p3 = gmsh::model::geo::addPoint(W, top, 0, h), p4 = gmsh::model::geo::addPoint(0, top, 0, h);
    const int bottom = gmsh::model::geo::addLine(p1, p2), right = gmsh::model::geo::addLine(p2, p3);
    const int topl = gmsh::model::geo::addLine(p3, p4), left = gmsh::model::geo::addLine(p4, p1);
    const int loop = gmsh::model::geo::addCurveLoop({bottom, right, topl, left});
    const int surface = gmsh::model::geo::addPlaneSurface({loop});
    gmsh::model::geo::synchronize();
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {bottom}), "absorbing");
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {topl}), "source");
    gmsh::model::setPhysicalName(1, gmsh::model::addPhysicalGroup(1, {left, right}), sides);
    gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {surface}), "specimen");
    gmsh::option::setNumber("Mesh.Algorithm", 6);  // triangles: recombining this many quads takes gmsh seconds
    gmsh::model::mesh::generate(2);
    gmsh::write(path);
    gmsh::finalize();
  }
  MPI_Barrier(PETSC_COMM_WORLD);
  return path;
}

TEST(AbsorbingEdges, ThirtyDegreeIncidenceReflectsLessThanTenPercent) {
  const double W = 0.01, top = 0.035, angle = 30.0, d = 0.012, h = 1.5e-4;
  const double probe_y = 0.5 * W * std::tan(angle * M_PI / 180.0) + d;
  ScopedWave probe_material("-mesh_h 0.05 -mesh_h_crack 0.05");
  const double cp = probe_material.material.cp(), cs = probe_material.material.cs();
  const char* burst = " -source_frequency 1e6 -source_amplitude 1e-8 -source_duration 2e-6 -source_ramp_cycles 1 -wave_degree 1";
  double R[2];
  for (int wave = 0; wave < 2; ++wave) {  // 0: P (normal source, roller sides); 1: S (tangential, antisymmetric)
    const bool P = wave == 0;
    const double c = P ? cp : cs, t_in = (top - probe_y) / c, t_back = t_in + 1.5 * d / c, b = 2e-6;
    const std::string mesh = InclinedBottomMesh(P ? "roller" : "antisymmetric", W, top, angle, h);
    ScopedWave w("-mesh_file " + mesh + burst + (P ? " -source_component normal" : " -source_component tangential"));
    ASSERT_EQ(w.status, 0);
    const PointSampler probe(w.solver.space(), 0.5 * W, probe_y);
    double incident = 0.0, reflected = 0.0;
    w.solver.on_step = [&](const wave::WaveSolver& s) -> PetscErrorCode {
      // After the incident burst has passed, anything at the probe (reflected P
      // and mode-converted S alike) came back from the inclined edge.
      const auto value = probe.Sample(s);
      const double magnitude = std::hypot(value[0], value[1]);
      if (s.time() <= t_in + b) incident = std::max(incident, magnitude);
      if (s.time() >= t_back - 0.05 * b) reflected = std::max(reflected, magnitude);
      return 0;
    };
    ASSERT_EQ(w.solver.AdvanceTo(t_back + 2 * b), 0);
    R[wave] = reflected / incident;
  }
  RecordProperty("reflection_P_30deg", std::to_string(R[0]));
  RecordProperty("reflection_S_30deg", std::to_string(R[1]));
  EXPECT_LT(R[0], 0.10);
  EXPECT_LT(R[1], 0.10);
}

}  // namespace
}  // namespace vibrotherm::testing
