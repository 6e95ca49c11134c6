// Requirement (issue 25, item 4): the boundary terms with D = 3 components a node:
//  - a dashpot's 3×3 block: the kick solves m a = m a₀ − C (v + h/2 a), the
//    implicit force is −C v, the account h v̄ᵀ C v̄;
//  - two constrained directions on one node: the acceleration and the reset
//    state lose both components, the third is untouched.
#include <gtest/gtest.h>
#include <petscvec.h>

#include <array>
#include <cmath>

#include "vibrotherm/wave/boundary_terms.hpp"

namespace vibrotherm::wave {
namespace {

constexpr double kMass = 2.5e-3;

std::vector<std::unique_ptr<BoundaryTerm>> Terms(const WaveBoundary& boundary, Vec* mass) {
  EXPECT_EQ(VecCreateSeq(PETSC_COMM_SELF, 3, mass), 0);
  EXPECT_EQ(VecSet(*mass, kMass), 0);
  std::vector<std::unique_ptr<BoundaryTerm>> terms;
  EXPECT_EQ(CreateBoundaryTerms(boundary, *mass, false, &terms), 0);
  return terms;
}

TEST(BoundaryTerms3d, DashpotBlockKickForceAndAccount) {
  WaveBoundary boundary;
  boundary.dim = boundary.dashpots.dim = 3;
  const std::array<double, 6> upper = {4.0e3, -1.0e3, 0.5e3, 5.0e3, 0.7e3, 3.0e3};  // xx xy xz yy yz zz
  boundary.dashpots.Add(0, upper.data());
  const double C[3][3] = {{4.0e3, -1.0e3, 0.5e3}, {-1.0e3, 5.0e3, 0.7e3}, {0.5e3, 0.7e3, 3.0e3}};
  Vec mass;
  auto terms = Terms(boundary, &mass);
  const PetscScalar masses[3] = {kMass, kMass, kMass}, v[3] = {0.2, -0.7, 0.4}, a0[3] = {40.0, -15.0, 7.0};
  const auto Cx = [&](int i, const double* x) { return C[i][0] * x[0] + C[i][1] * x[1] + C[i][2] * x[2]; };
  for (const double h : {0.0, 1e-4}) {
    ForceState s;
    s.mass = masses;
    s.velocity = v;
    s.kick_dt = h;
    PetscScalar acc[3] = {a0[0], a0[1], a0[2]};
    for (auto& term : terms) term->Accelerate(s, acc);
    double mean[3];
    for (int i = 0; i < 3; ++i) mean[i] = v[i] + 0.5 * h * acc[i];
    for (int i = 0; i < 3; ++i) {
      const double rhs = kMass * a0[i] - Cx(i, mean);
      EXPECT_NEAR(kMass * acc[i], rhs, 1e-12 * std::abs(kMass * a0[i]) + 1e-12 * std::abs(rhs)) << "h = " << h;
    }
  }
  PetscScalar f[3] = {0.0, 0.0, 0.0};
  ForceState s;
  s.velocity = v;
  for (auto& term : terms) term->AddForce(s, f);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i], -Cx(i, v), 1e-12 * std::abs(Cx(i, v)));
  StepState step;
  const PetscScalar zero[3] = {0.0, 0.0, 0.0};
  step.h = 2e-8;
  step.u = zero;
  step.v = zero;
  for (auto& term : terms) term->Resume(step);
  step.v = v;
  BoundaryEnergy e;
  for (auto& term : terms) term->Account(step, &e);
  const double half[3] = {0.5 * v[0], 0.5 * v[1], 0.5 * v[2]};
  const double expected = step.h * (half[0] * Cx(0, half) + half[1] * Cx(1, half) + half[2] * Cx(2, half));
  EXPECT_NEAR(e.radiated, expected, 1e-12 * expected);
  VecDestroy(&mass);
}

TEST(BoundaryTerms3d, TwoConstraintsOnANodeRemoveBothComponents) {
  WaveBoundary boundary;
  boundary.dim = boundary.dashpots.dim = 3;
  const double s = std::sqrt(0.5);
  const double d1[3] = {s, 0.0, s}, d2[3] = {-s, 0.0, s}, free[3] = {0.0, 1.0, 0.0};
  boundary.constraints.push_back({0, {d1[0], d1[1], d1[2]}, false});
  boundary.constraints.push_back({0, {d2[0], d2[1], d2[2]}, false});
  Vec mass;
  auto terms = Terms(boundary, &mass);
  const auto dot = [](const PetscScalar* a, const double* d) { return a[0] * d[0] + a[1] * d[1] + a[2] * d[2]; };
  const PetscScalar masses[3] = {kMass, kMass, kMass}, v[3] = {0.0, 0.0, 0.0};
  ForceState state;
  state.mass = masses;
  state.velocity = v;
  PetscScalar acc[3] = {10.0, -4.0, 3.0};
  for (auto& term : terms) term->Accelerate(state, acc);
  EXPECT_NEAR(dot(acc, d1), 0.0, 1e-14);
  EXPECT_NEAR(dot(acc, d2), 0.0, 1e-14);
  EXPECT_DOUBLE_EQ(dot(acc, free), -4.0);
  PetscScalar U[3] = {1e-8, 2e-8, -3e-8}, V[3] = {1e-3, -2e-3, 5e-4};
  for (auto& term : terms) term->Impose(SignalValues{}, U, V);
  EXPECT_NEAR(dot(U, d1), 0.0, 1e-22);
  EXPECT_NEAR(dot(V, d2), 0.0, 1e-17);
  EXPECT_DOUBLE_EQ(U[1], 2e-8);
  EXPECT_DOUBLE_EQ(V[1], -2e-3);
  VecDestroy(&mass);
}

}  // namespace
}  // namespace vibrotherm::wave
