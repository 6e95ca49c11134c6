// Requirement: each boundary term does what its equation says, node by node,
// without a mesh: a dashpot's kick solves (m I + h/2 C) a = m a₀ − C v, a
// constraint makes the prescribed component follow g, ġ, g̈ and leaves the free
// one alone, and the energy each term accounts is the closed-form work of a
// step (h v̄ᵀ C v̄ radiated, the support force times Δg, g(t_mid) f·Δu).
#include <gtest/gtest.h>
#include <petscvec.h>

#include <array>
#include <cmath>

#include "vibrotherm/wave/boundary_terms.hpp"

namespace vibrotherm::wave {
namespace {

constexpr double kMass = 2.5;

/// A serial lumped mass of `nodes` nodes (2 dofs each).
Vec MassVector(PetscInt nodes) {
  Vec m;
  EXPECT_EQ(VecCreateSeq(PETSC_COMM_SELF, 2 * nodes, &m), 0);
  EXPECT_EQ(VecSet(m, kMass), 0);
  return m;
}

/// The terms of `boundary` (one node unless said), with every kind present.
std::vector<std::unique_ptr<BoundaryTerm>> Terms(const WaveBoundary& boundary, Vec mass, bool displacement) {
  std::vector<std::unique_ptr<BoundaryTerm>> terms;
  EXPECT_EQ(CreateBoundaryTerms(boundary, mass, displacement, &terms), 0);
  return terms;
}

TEST(BoundaryTerms, DashpotKickSolvesTheTrapezoidalBalance) {
  Vec mass = MassVector(1);
  WaveBoundary boundary;
  boundary.dashpots.Add(0, std::array<double, 3>{3.0e3, -1.0e3, 5.0e3}.data());
  auto terms = Terms(boundary, mass, false);
  const double C[2][2] = {{3.0e3, -1.0e3}, {-1.0e3, 5.0e3}}, v[2] = {0.2, -0.7}, a0[2] = {40.0, -15.0};
  const PetscScalar masses[2] = {kMass, kMass};
  for (const double h : {0.0, 1e-4}) {
    ForceState s;
    s.mass = masses;
    s.velocity = v;
    s.kick_dt = h;
    PetscScalar acc[2] = {a0[0], a0[1]};
    for (auto& term : terms) term->Accelerate(s, acc);
    for (int i = 0; i < 2; ++i) {  // m a = m a₀ − C (v + h/2 a)
      const double rhs = kMass * a0[i] - (C[i][0] * (v[0] + 0.5 * h * acc[0]) + C[i][1] * (v[1] + 0.5 * h * acc[1]));
      EXPECT_NEAR(kMass * acc[i], rhs, 1e-12 * std::abs(rhs)) << "h = " << h << ", component " << i;
    }
  }
  PetscScalar f[2] = {0.0, 0.0};
  ForceState s;
  s.velocity = v;
  for (auto& term : terms) term->AddForce(s, f);
  EXPECT_DOUBLE_EQ(f[0], -(C[0][0] * v[0] + C[0][1] * v[1]));
  EXPECT_DOUBLE_EQ(f[1], -(C[1][0] * v[0] + C[1][1] * v[1]));
  VecDestroy(&mass);
}

TEST(BoundaryTerms, ConstraintFollowsTheSourceAlongItsDirectionOnly) {
  Vec mass = MassVector(1);
  WaveBoundary boundary;
  const double d[2] = {std::cos(0.3), std::sin(0.3)};
  boundary.constraints.push_back({0, {d[0], d[1]}, true});
  auto terms = Terms(boundary, mass, true);
  const PetscScalar masses[2] = {kMass, kMass}, v[2] = {0.0, 0.0};
  ForceState s;
  s.mass = masses;
  s.velocity = v;
  s.signal = {1e-7, 2e-2, -3e4};
  PetscScalar acc[2] = {10.0, -4.0};
  const double free_before = -acc[0] * d[1] + acc[1] * d[0];
  for (auto& term : terms) term->Accelerate(s, acc);
  EXPECT_NEAR(acc[0] * d[0] + acc[1] * d[1], s.signal.ddg, 1e-12 * std::abs(s.signal.ddg));
  EXPECT_NEAR(-acc[0] * d[1] + acc[1] * d[0], free_before, 1e-12);
  PetscScalar U[2] = {5e-8, 1e-8}, V[2] = {1e-3, -2e-3};
  const double u_free = -U[0] * d[1] + U[1] * d[0], v_free = -V[0] * d[1] + V[1] * d[0];
  for (auto& term : terms) term->Impose(s.signal, U, V);
  EXPECT_NEAR(U[0] * d[0] + U[1] * d[1], s.signal.g, 1e-20);
  EXPECT_NEAR(V[0] * d[0] + V[1] * d[1], s.signal.dg, 1e-15);
  EXPECT_NEAR(-U[0] * d[1] + U[1] * d[0], u_free, 1e-20);
  EXPECT_NEAR(-V[0] * d[1] + V[1] * d[0], v_free, 1e-15);
  // The kick's support force along d is m (g̈ − a₀·d); it works over Δg.
  StepState step;
  step.start.g = 0.0;
  step.end.g = s.signal.g;
  step.reactions_from_kick = true;
  BoundaryEnergy e;
  for (auto& term : terms) term->Account(step, &e);
  const double a0_along = 10.0 * d[0] - 4.0 * d[1];
  EXPECT_NEAR(e.work_source, kMass * (s.signal.ddg - a0_along) * s.signal.g, 1e-12 * std::abs(e.work_source));
  VecDestroy(&mass);
}

TEST(BoundaryTerms, EnergyOfAStepIsItsClosedFormWork) {
  Vec mass = MassVector(2);
  WaveBoundary boundary;
  boundary.dashpots.Add(1, std::array<double, 3>{4.0e3, 0.5e3, 2.0e3}.data());
  EXPECT_EQ(VecCreateSeq(PETSC_COMM_SELF, 4, &boundary.traction_shape), 0);
  EXPECT_EQ(VecSet(boundary.traction_shape, 0.0), 0);
  EXPECT_EQ(VecSetValue(boundary.traction_shape, 1, 1e-3, INSERT_VALUES), 0);  // node 0, y
  auto terms = Terms(boundary, mass, false);
  // A step in which node 1 moves at the constant velocity (vx, vy) and node 0 by Δu_y.
  const double h = 2e-8, vx = 0.3, vy = -0.1, du = 4e-9;
  StepState step;
  step.h = h;
  step.middle.g = 7e5;
  const PetscScalar u0[4] = {0, 0, 0, 0}, v0[4] = {0, 0, vx, vy};
  step.u = u0;
  step.v = v0;
  BoundaryEnergy first;  // the first step starts from rest: the terms remember the state
  for (auto& term : terms) term->Account(step, &first);
  const PetscScalar u1[4] = {0, du, 0, 0};
  step.u = u1;
  BoundaryEnergy e;
  for (auto& term : terms) term->Account(step, &e);
  EXPECT_NEAR(e.radiated, h * (4.0e3 * vx * vx + 2 * 0.5e3 * vx * vy + 2.0e3 * vy * vy), 1e-15);
  EXPECT_NEAR(e.work_source, 7e5 * 1e-3 * du, 1e-18);
  // The traction's acceleration is g f / m on its dofs only.
  ForceState s;
  s.signal.g = 7e5;
  PetscScalar acc[4] = {0, 0, 0, 0};
  const PetscScalar masses[4] = {kMass, kMass, kMass, kMass}, v[4] = {0, 0, 0, 0};
  s.mass = masses;
  s.velocity = v;
  for (auto& term : terms) term->Accelerate(s, acc);
  EXPECT_DOUBLE_EQ(acc[1], 7e5 * 1e-3 / kMass);
  EXPECT_EQ(acc[0], 0.0);
  EXPECT_EQ(acc[2], 0.0);
  VecDestroy(&mass);
}

}  // namespace
}  // namespace vibrotherm::wave
