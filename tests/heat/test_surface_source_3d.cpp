// Requirement (issue 26, item 4): heat in 3D with the friction power as a
// surface density on a planar crack (coupling/exchange/surface_transfer),
// on hexahedral meshes graded towards the source, against closed forms
// (k = ρ c_p = κ = 1, disc radius a = 1, q = 1 W/m² of crack: the power q πa²
// enters the body, half through each face):
//  (a) a disc source on from t = 0 in an infinite body, on its axis:
//        T(z, t) = (q√(κt)/k) [ierfc(|z|/(2√(κt))) − ierfc(√(a² + z²)/(2√(κt)))]
//      (point-source kernel integrated over the disc and in time; steady limit
//      q(√(a² + z²) − |z|)/(2k)); one quarter of the body (x, y ≥ 0, its two cut
//      planes insulated: symmetry), outer faces held at T0 at x, y = 4, z = ±3
//      (6√(κt) beyond the disc at t = 0.25: they cannot matter). The error at
//      three refinements falls at an observed order near 2 (measured 2.28);
//  (b) a disc at depth d parallel to an insulated face, on that face above the
//      centre: twice (a) at z = d (its image), 3D-NOTES.md §4.3,
//        T(t) = (2q√(κt)/k) [ierfc(d/(2√(κt))) − ierfc(√(a² + d²)/(2√(κt)))] → q(√(a² + d²) − d)/k;
//  (c) on an insulated box the heat content equals the deposited energy t·q·area
//      to rounding, and 2 ranks give the serial temperatures;
//  (d) a uniform density over whole faces of the heat mesh (2 × 2 Gauss points a
//      face) gives the load q ∫ψ_h dA exactly, degrees 1 and 2.
// A transfer giving half the power is caught by (a)'s tolerance (a control in the test).
// Tetrahedra: DISABLED_DiscOnTetrahedra (by hand; their mesh setup is slow, MEASUREMENTS.md).
#include <gtest/gtest.h>
#include <petscdmplex.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "graded_box_support.hpp"
#include "vibrotherm/coupling/exchange/surface_transfer.hpp"
#include "vibrotherm/heat/heat_probes.hpp"
#include "vibrotherm/heat/heat_solver.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::testing {
namespace {

constexpr double kRadius = 1.0, kFlux = 1.0;

double Ierfc(double x) { return std::exp(-x * x) / std::sqrt(M_PI) - x * std::erfc(x); }

/// (a): the rise on the axis of a disc source in an infinite body (k = κ = 1).
double DiscAxisRise(double z, double t) {
  const double s = 2.0 * std::sqrt(t);
  return kFlux * std::sqrt(t) * (Ierfc(std::abs(z) / s) - Ierfc(std::hypot(kRadius, z) / s));
}

/// One 3D heat problem: the mesh's node lines, its sink faces, the disc's plane, the probes.
struct Problem {
  std::array<std::vector<double>, 3> nodes;
  std::function<bool(const double*)> sink;
  double disc_z = 0.0;
  int radial = 16, angular = 24;  ///< the disc's source points (a quarter disc)
  std::vector<double> probes;     ///< x, y, z triples
  double power_factor = 1.0;      ///< 1: the true power (< 1: the control of a wrong transfer)
  const char* ts_type = "beuler";
  bool simplex = false;  ///< tetrahedra (each box cell in 6) instead of hexahedra  ///< the coupled TS (backward Euler, the run's; cn: second order in time)
};

struct Outcome {
  std::vector<double> rise;  ///< at the probes
  double content = 0.0, deposited = 0.0, boundary_loss = 0.0, load_total = 0.0, power = 0.0;
  PetscInt dofs = 0;
};

/// This rank's share of the quarter disc's points (contiguous blocks by rank).
coupling::SurfacePoints RankShare(MPI_Comm comm, const Problem& p) {
  const geometry::Frame<3> frame = geometry::FrameFromNormal({0, 0, 1}, {1, 0, 0});
  const coupling::SurfacePoints all =
      coupling::DiscSector({0, 0, p.disc_z}, frame, kRadius, 0.0, 0.5 * M_PI, p.radial, p.angular);
  PetscMPIInt rank, size;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  coupling::SurfacePoints mine;
  for (std::size_t i = all.size() * rank / size; i < all.size() * (rank + 1) / size; ++i) {
    mine.x.push_back(all.x[i]);
    mine.area.push_back(all.area[i]);
  }
  return mine;
}

/// Backward Euler to t_end on a geometric ladder: [0, t_end/2^rungs], then doubling, `steps` each.
PetscErrorCode Advance(heat::HeatSolver& heat, double t_end, int rungs, int steps) {
  PetscFunctionBeginUser;
  for (int k = rungs; k >= 0; --k) PetscCall(heat.AdvanceInSteps(std::ldexp(t_end, -k), steps));
  PetscFunctionReturn(0);
}

PetscErrorCode Solve(MPI_Comm comm, const Problem& p, double t_end, int rungs, int steps, Outcome* out) {
  PetscFunctionBeginUser;
  DM dm;
  PetscCall(GradedBox(comm, p.nodes, p.simplex, p.sink, &dm));
  {
    heat::HeatOptions options;
    options.material.density = options.material.capacity = options.material.conductivity = 1.0;
    heat::HeatSolver heat;
    PetscCall(PetscOptionsSetValue(nullptr, "-heat_ts_type", p.ts_type));
    PetscCall(heat.Setup(dm, options));
    PetscCall(PetscOptionsClearValue(nullptr, "-heat_ts_type"));
    coupling::SurfaceHeatTransfer transfer;
    const coupling::SurfacePoints mine = RankShare(comm, p);
    PetscCall(transfer.Setup(heat.space(), mine));
    Vec Q;
    PetscCall(DMCreateGlobalVector(dm, &Q));
    PetscCall(VecSet(Q, 0.0));
    PetscCall(transfer.AddRates(std::vector<double>(mine.size(), kFlux * p.power_factor), Q));
    PetscCall(heat.SetSourceLoad(Q));
    PetscScalar total;
    PetscCall(VecSum(Q, &total));
    PetscCall(VecDestroy(&Q));
    out->load_total = PetscRealPart(total);
    out->power = kFlux * transfer.area();
    PetscCall(Advance(heat, t_end, rungs, steps));
    out->rise.clear();
    for (std::size_t i = 0; i + 2 < p.probes.size(); i += 3) {
      double T;
      PetscCall(heat::TemperatureAt(heat, &p.probes[i], &T));
      out->rise.push_back(T - heat.material().T0);
    }
    heat::HeatAccounts accounts;
    PetscCall(heat.Accounts(&accounts));
    out->content = accounts.content;
    out->deposited = accounts.deposited;
    out->boundary_loss = accounts.boundary_loss;
    out->dofs = heat.dofs();
  }
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

/// (a)'s body at refinement n: x, y ∈ [0, 4] (n cells), z ∈ [−3, 3] (2n), uniform near the disc.
Problem InfiniteBody(int n) {
  Problem p;
  p.nodes = {GradedAxis(1.25, 4.0, 0.6, n), GradedAxis(1.25, 4.0, 0.6, n), MirroredAxis(GradedAxis(1.0, 3.0, 0.6, n))};
  p.sink = [](const double* c) { return c[0] > 1e-9 && c[1] > 1e-9; };  // the cut planes x = 0, y = 0 insulated
  p.radial = 4 * n;
  p.angular = 6 * n;
  p.probes = {0, 0, 0, 0, 0, 0.25, 0, 0, 0.5};
  return p;
}

/// The largest error of (a) at the probes, relative to the centre's rise.
double InfiniteBodyError(const Problem& p, const Outcome& out, double t) {
  double worst = 0.0;
  for (std::size_t i = 0; i < out.rise.size(); ++i)
    worst = std::max(worst, std::abs(out.rise[i] - DiscAxisRise(p.probes[3 * i + 2], t)) / DiscAxisRise(0.0, t));
  return worst;
}

// (a): second order in space (Crank-Nicolson on the ladder: the time error, 1e-5, is not what is measured).
TEST(SurfaceSource3D, DiscInInfiniteBodyConverges) {
  const double t = 0.25;
  const std::vector<int> levels = {8, 12, 16};
  std::vector<double> errors;
  for (int n : levels) {
    Problem p = InfiniteBody(n);
    p.ts_type = "cn";
    Outcome out;
    ASSERT_EQ(Solve(PETSC_COMM_WORLD, p, t, 5, 12, &out), 0);
    errors.push_back(InfiniteBodyError(p, out, t));
    PetscPrintf(PETSC_COMM_WORLD, "disc in an infinite body, n = %d (%d dofs): centre %.6g (exact %.6g), error %.3e\n",
                n, static_cast<int>(out.dofs), out.rise[0], DiscAxisRise(0.0, t), errors.back());
  }
  const double order = std::log(errors.front() / errors.back()) / std::log(double(levels.back()) / levels.front());
  PetscPrintf(PETSC_COMM_WORLD, "observed order %.2f\n", order);
  EXPECT_LT(errors.back(), 3e-3);
  EXPECT_GT(order, 1.8);
  for (std::size_t k = 1; k < errors.size(); ++k) EXPECT_LT(errors[k], errors[k - 1]);
  // The control: half the power (a transfer that loses half) is far outside the tolerance.
  Problem half = InfiniteBody(levels.front());
  half.power_factor = 0.5;
  half.ts_type = "cn";
  Outcome out;
  ASSERT_EQ(Solve(PETSC_COMM_WORLD, half, t, 5, 12, &out), 0);
  EXPECT_GT(InfiniteBodyError(half, out, t), 10 * errors.front());
}

// (a) on tetrahedra (each graded box cell in 6, KuhnSimplices): not run by ctest, 6 min for the
// three levels (the 3D tetrahedral mesh's setup, not its steps); --gtest_also_run_disabled_tests.
TEST(SurfaceSource3D, DISABLED_DiscOnTetrahedra) {
  const double t = 0.25;
  const int finest = getenv("TETS_FINEST") ? atoi(getenv("TETS_FINEST")) : 16;
  for (int n : {8, 12, 16}) {
    if (n > finest) break;
    Problem p = InfiniteBody(n);
    p.ts_type = "cn";
    p.simplex = true;
    Outcome out;
    ASSERT_EQ(Solve(PETSC_COMM_WORLD, p, t, 5, 12, &out), 0);
    PetscPrintf(PETSC_COMM_WORLD, "tets n = %d (%d dofs): centre %.6g (exact %.6g), error %.3e\n", n,
                static_cast<int>(out.dofs), out.rise[0], DiscAxisRise(0.0, t), InfiniteBodyError(p, out, t));
  }
}

// (b): the face above a buried disc, insulated (3D-NOTES.md §4.3: the image doubles the infinite body's rise).
TEST(SurfaceSource3D, BuriedDiscBelowInsulatedFace) {
  const double depth = 0.5, steady = std::hypot(kRadius, depth) - depth;
  std::vector<double> errors;
  for (int n : {8, 16}) {
    Problem p;
    p.nodes = {GradedAxis(1.25, 10.0, 0.6, n), GradedAxis(1.25, 10.0, 0.6, n), GradedAxis(2 * depth, 10.0, 0.5, n)};
    p.sink = [](const double* c) { return c[0] > 1e-9 && c[1] > 1e-9 && c[2] > 1e-9; };  // z = 0: the insulated face
    p.disc_z = depth;
    p.radial = 4 * n;
    p.angular = 6 * n;
    p.probes = {0, 0, 0};
    p.ts_type = "cn";
    double worst = 0.0;
    for (double t : {1.0, 4.0}) {
      Outcome out;
      ASSERT_EQ(Solve(PETSC_COMM_WORLD, p, t, 6, 12, &out), 0);
      const double exact = 2.0 * DiscAxisRise(depth, t);
      worst = std::max(worst, std::abs(out.rise[0] - exact) / exact);
      PetscPrintf(PETSC_COMM_WORLD, "buried disc, n = %d, t = %g: face %.6g, exact %.6g (steady %.6g), error %.3e\n", n,
                  t, out.rise[0], exact, steady, std::abs(out.rise[0] - exact) / exact);
    }
    errors.push_back(worst);
  }
  EXPECT_LT(errors.back(), 1.2e-2);  // measured 0.91 % (n = 16: the face's first layer 0.125 a)
  EXPECT_GT(std::log2(errors.front() / errors.back()), 1.8);
}

// (c): the energy budget closes to rounding (insulated box; then with sinks), and N ranks = serial.
TEST(SurfaceSource3D, EnergyBudgetAndRanks) {
  const double t = 0.25;
  Problem p = InfiniteBody(8);
  p.nodes = {GradedAxis(1.25, 2.5, 0.6, 8), GradedAxis(1.25, 2.5, 0.6, 8), MirroredAxis(GradedAxis(1.0, 2.0, 0.6, 8))};
  for (bool sinks : {false, true}) {
    if (!sinks) p.sink = [](const double*) { return false; };
    else p.sink = InfiniteBody(8).sink;
    Outcome parallel, serial;
    ASSERT_EQ(Solve(PETSC_COMM_WORLD, p, t, 3, 4, &parallel), 0);
    ASSERT_EQ(Solve(PETSC_COMM_SELF, p, t, 3, 4, &serial), 0);
    const double energy = parallel.power * t;
    EXPECT_NEAR(parallel.power, kFlux * M_PI / 4, 1e-13);  // the quarter disc's area, exactly
    EXPECT_NEAR(parallel.load_total, parallel.power, 1e-14 * parallel.power);
    EXPECT_NEAR(parallel.deposited, energy, 1e-13 * energy);
    EXPECT_NEAR(parallel.content + parallel.boundary_loss, parallel.deposited, 1e-12 * energy);
    if (!sinks) EXPECT_EQ(parallel.boundary_loss, 0.0);
    else EXPECT_GT(parallel.boundary_loss, 1e-4 * energy);  // the sinks do take heat: the check means something
    for (std::size_t i = 0; i < serial.rise.size(); ++i)
      EXPECT_NEAR(parallel.rise[i], serial.rise[i], 1e-10 * serial.rise[0]);
    EXPECT_NEAR(parallel.content, serial.content, 1e-12 * energy);
    double ranks = 0.0;
    for (std::size_t i = 0; i < serial.rise.size(); ++i)
      ranks = std::max(ranks, std::abs(parallel.rise[i] - serial.rise[i]) / serial.rise[0]);
    PetscPrintf(PETSC_COMM_WORLD,
                "budget (%s): load - power %.2e, deposited - q A t %.2e, content + loss - deposited %.2e (relative; "
                "loss %.3g of %.3g), ranks vs serial %.2e\n",
                sinks ? "sinks" : "insulated", (parallel.load_total - parallel.power) / parallel.power,
                (parallel.deposited - energy) / energy,
                (parallel.content + parallel.boundary_loss - parallel.deposited) / energy, parallel.boundary_loss,
                energy, ranks);
  }
}

/// Q += q ∫ψ_h dA over the faces of the plane z = 0 within [0, X] × [0, Y] (FaceNodes' weights; owned faces).
PetscErrorCode PlaneFaceLoad(const fe::LagrangeSpace& space, double X, double Y, double q, Vec Q) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  std::vector<bool> ghost;
  std::vector<double> x, weights;
  std::vector<PetscInt> offsets;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscCall(space.NodePositions(&x));
  PetscInt pStart, fStart, fEnd;
  PetscCall(DMPlexGetChart(dm, &pStart, nullptr));
  PetscCall(DMPlexGetHeightStratum(dm, 1, &fStart, &fEnd));
  Vec local;
  PetscScalar* a;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(VecSet(local, 0.0));
  PetscCall(VecGetArray(local, &a));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    if (ghost[f - pStart]) continue;
    double area;
    PetscCall(space.FaceNodes(f, &offsets, &weights, &area));
    bool inside = true;
    for (PetscInt o : offsets)
      inside = inside && std::abs(x[3 * o + 2]) < 1e-12 && x[3 * o] < X + 1e-12 && x[3 * o + 1] < Y + 1e-12;
    if (inside)
      for (std::size_t j = 0; j < offsets.size(); ++j) a[offsets[j]] += q * weights[j];
  }
  PetscCall(VecRestoreArray(local, &a));
  PetscCall(DMLocalToGlobal(dm, local, ADD_VALUES, Q));
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

// (d): the transfer of a uniform density over heat faces is exact (the 2D transfer's property, here by quadrature).
TEST(SurfaceSource3D, UniformDensityOnHeatFacesIsExact) {
  const std::vector<double> xy = GradedAxis(1.25, 4.0, 0.6, 8), z = MirroredAxis(GradedAxis(1.0, 3.0, 0.6, 8));
  const double side = xy[3];  // three faces of the uniform part: a 3 × 3 patch of faces at a corner of the plane
  for (PetscInt degree : {1, 2}) {
    DM dm;
    ASSERT_EQ(GradedBox(PETSC_COMM_WORLD, {xy, xy, z}, false, [](const double*) { return false; }, &dm), 0);
    {
      fe::LagrangeSpace space;
      ASSERT_EQ(space.Setup(dm, degree, 1), 0);
      PetscMPIInt rank;
      MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
      const geometry::Frame<3> frame = geometry::FrameFromNormal({0, 0, 1}, {1, 0, 0});
      const coupling::SurfacePoints patch = rank == 0 ? coupling::Rectangle({side / 2, side / 2, 0}, frame, side / 2,
                                                                          side / 2, 3, 3)
                                                      : coupling::SurfacePoints{};
      coupling::SurfaceHeatTransfer transfer;
      ASSERT_EQ(transfer.Setup(space, patch), 0);
      Vec Q, reference;
      DMCreateGlobalVector(dm, &Q);
      VecDuplicate(Q, &reference);
      VecSet(Q, 0.0);
      VecSet(reference, 0.0);
      ASSERT_EQ(transfer.AddRates(std::vector<double>(patch.size(), 2.5), Q), 0);
      ASSERT_EQ(PlaneFaceLoad(space, side, side, 2.5, reference), 0);
      PetscReal scale, difference;
      VecNorm(reference, NORM_INFINITY, &scale);
      VecAXPY(Q, -1.0, reference);
      VecNorm(Q, NORM_INFINITY, &difference);
      EXPECT_NEAR(transfer.area(), side * side, 1e-14);
      EXPECT_GT(scale, 0.0);
      EXPECT_LT(difference, 1e-14 * scale) << "degree " << degree;
      VecDestroy(&Q);
      VecDestroy(&reference);
    }
    DMDestroy(&dm);
  }
}

}  // namespace
}  // namespace vibrotherm::testing
