// Requirement (issue 25, the dimension comes from the DM): the Lagrange space
// and the elastic operators take their dimension from the mesh, and are exact
// where they must be in 2D and 3D (serial meshes), on quads/hexes (non-affine) and on
// triangles/tetrahedra, degrees 1 and 2:
//  - the space: dim() and the cell shape are the DM's, the element's node count follows;
//  - patch test: a linear displacement gives its constant stress at every
//    quadrature point, K u has no interior residual, and uᵀKu = σ:ε · volume;
//  - rigid-body motions (D translations, D(D−1)/2 rotations) are in the null space of K;
//  - the stepping product (BlockKernel) is MatMult's to rounding: its 2×2 loop in 2D, its 3×3
//    loop in 3D, portable and AVX2 paths, all rows or only those with entries;
//  - LTS levels are assigned to every cell and reach every dof;
//  - the lumped mass is positive (Q2 hexes included: Gauss–Lobatto-like row
//    sums; P2 simplices by HRZ, their row sums being ≤ 0 at vertices) and totals ρ·volume.
#include <cmath>
#include <cstdio>

#include "box_mesh_support.hpp"
#include "vibrotherm/wave/block_kernel.hpp"
#include "vibrotherm/wave/elastic_operator.hpp"
#include "vibrotherm/wave/lts_levels.hpp"

namespace vibrotherm::testing {
namespace {

constexpr int kNodes[2][2][3] = {{{0, 4, 9}, {0, 3, 6}}, {{0, 8, 27}, {0, 4, 10}}};  // [dim−2][simplex][degree]

class DimensionFromDm : public ::testing::TestWithParam<BoxCase> {
 protected:
  void SetUp() override {
    ASSERT_EQ(BoxMesh(GetParam(), &dm_), 0);
    ASSERT_EQ(space_.Setup(dm_, GetParam().degree, GetParam().dim), 0);
    ASSERT_EQ(wave::AssembleElasticOperators(space_, material_, &K_, &mass_), 0);
  }
  void TearDown() override {
    VecDestroy(&mass_);
    MatDestroy(&K_);
    DMDestroy(&dm_);
  }
  /// ‖K u‖∞ / (‖K‖∞ ‖u‖∞) for u = f at the nodes, and K u itself in Ku (caller destroys).
  double Apply(const std::function<void(const double*, double*)>& f, Vec* u, Vec* Ku) {
    EXPECT_EQ(NodalField(space_, f, u), 0);
    VecDuplicate(*u, Ku);
    MatMult(K_, *u, *Ku);
    PetscReal norm, K_norm, u_norm;
    VecNorm(*Ku, NORM_INFINITY, &norm);
    VecNorm(*u, NORM_INFINITY, &u_norm);
    MatNorm(K_, NORM_INFINITY, &K_norm);
    return norm / (K_norm * u_norm);
  }
  DM dm_ = nullptr;
  fe::LagrangeSpace space_;
  wave::ElasticMaterial material_;
  Mat K_ = nullptr;
  Vec mass_ = nullptr;
};

TEST_P(DimensionFromDm, SpaceTakesDimensionAndShapeFromTheMesh) {
  const BoxCase c = GetParam();
  EXPECT_EQ(space_.dim(), c.dim);
  EXPECT_EQ(space_.simplex(), c.simplex);
  EXPECT_EQ(space_.nodes_per_cell(), kNodes[c.dim - 2][c.simplex][c.degree]);
  PetscInt bs;
  MatGetBlockSize(K_, &bs);
  EXPECT_EQ(bs, c.dim);
}

TEST_P(DimensionFromDm, LumpedMassPositiveAndTotalIsRhoVolume) {
  const int D = GetParam().dim;
  PetscReal total, smallest;
  VecSum(mass_, &total);
  VecMin(mass_, nullptr, &smallest);
  const double exact = D * material_.density * BoxVolume(D);  // every component carries the mass
  std::printf("  %s: min lumped mass %.6g kg, total/exact − 1 = %.3g\n", BoxCaseName({GetParam(), 0}).c_str(), smallest,
              total / exact - 1);
  EXPECT_GT(smallest, 0.0);
  EXPECT_NEAR(total, exact, 1e-12 * exact);
}

TEST_P(DimensionFromDm, RigidBodyMotionsAreInTheNullSpace) {
  const int D = GetParam().dim;
  // Translations e_k, then rotations in the (i, j) planes: u_i = −x_j, u_j = x_i.
  std::vector<std::function<void(const double*, double*)>> motions;
  for (int k = 0; k < D; ++k)
    motions.push_back([=](const double*, double* u) {
      for (int d = 0; d < D; ++d) u[d] = d == k ? 1.0 : 0.0;
    });
  for (int i = 0; i < D; ++i)
    for (int j = i + 1; j < D; ++j)
      motions.push_back([=](const double* x, double* u) {
        for (int d = 0; d < D; ++d) u[d] = 0.0;
        u[i] = -x[j], u[j] = x[i];
      });
  EXPECT_EQ(motions.size(), static_cast<std::size_t>(D * (D + 1) / 2));
  double worst = 0.0;
  for (std::size_t m = 0; m < motions.size(); ++m) {
    Vec u, Ku;
    const double residual = Apply(motions[m], &u, &Ku);
    worst = std::max(worst, residual);
    EXPECT_LT(residual, 1e-13) << "rigid motion " << m;
    VecDestroy(&u);
    VecDestroy(&Ku);
  }
  std::printf("  %s: max ‖K r‖∞ / (‖K‖∞ ‖r‖∞) over %zu rigid motions = %.3g\n", BoxCaseName({GetParam(), 0}).c_str(),
              motions.size(), worst);
}

/// A displacement gradient with every entry different (stretch, shear and rotation).
double Gradient(int i, int j) { return 1e-4 * (1.0 + i + 0.5 * j + 0.25 * i * j) * (i == j ? 1.0 : -0.7); }

TEST_P(DimensionFromDm, PatchTestLinearDisplacement) {
  const int D = GetParam().dim;
  const double lambda = material_.lambda(), G = material_.shear_modulus();
  double sigma[3][3], energy_density = 0.0, trace = 0.0;
  for (int i = 0; i < D; ++i) trace += Gradient(i, i);
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) {
      sigma[i][j] = (i == j ? lambda * trace : 0.0) + G * (Gradient(i, j) + Gradient(j, i));
      energy_density += sigma[i][j] * 0.5 * (Gradient(i, j) + Gradient(j, i));
    }
  Vec u, Ku;
  Apply(
      [=](const double* x, double* v) {
        for (int i = 0; i < D; ++i) {
          v[i] = 1e-5 * (i + 1);
          for (int j = 0; j < D; ++j) v[i] += Gradient(i, j) * x[j];
        }
      },
      &u, &Ku);
  PetscReal boundary_force;
  VecNorm(Ku, NORM_INFINITY, &boundary_force);
  const double interior = InteriorMax(space_, Ku) / boundary_force;
  PetscScalar uKu;
  VecDot(u, Ku, &uKu);
  const double exact = energy_density * BoxVolume(D);
  // The stress at every quadrature point, from the element gradients of u.
  Vec u_local;
  PetscSection section;
  DMGetLocalVector(dm_, &u_local);
  DMGlobalToLocal(dm_, u, INSERT_VALUES, u_local);
  DMGetLocalSection(dm_, &section);
  fe::CellQuadrature q;
  double stress_error = 0.0;
  for (PetscInt c : space_.cells()) {
    space_.Evaluate(c, &q);
    PetscScalar* cu = nullptr;
    DMPlexVecGetClosure(dm_, section, u_local, c, nullptr, &cu);
    for (int p = 0; p < q.points; ++p) {
      double grad[3][3] = {}, tr = 0.0;
      for (int b = 0; b < q.nodes; ++b)
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) grad[i][j] += PetscRealPart(cu[D * b + i]) * q.grad[(p * q.nodes + b) * D + j];
      for (int i = 0; i < D; ++i) tr += grad[i][i];
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          const double s = (i == j ? lambda * tr : 0.0) + G * (grad[i][j] + grad[j][i]);
          stress_error = std::max(stress_error, std::abs(s - sigma[i][j]) / std::abs(sigma[0][0]));
        }
    }
    DMPlexVecRestoreClosure(dm_, section, u_local, c, nullptr, &cu);
  }
  DMRestoreLocalVector(dm_, &u_local);
  std::printf(
      "  %s: patch test: stress error %.3g, interior residual %.3g (of the boundary force), "
      "uKu/exact − 1 = %.3g\n",
      BoxCaseName({GetParam(), 0}).c_str(), stress_error, interior, PetscRealPart(uKu) / exact - 1);
  EXPECT_LT(stress_error, 1e-10);
  EXPECT_LT(interior, 1e-10);
  EXPECT_NEAR(PetscRealPart(uKu), exact, 1e-10 * exact);
  VecDestroy(&u);
  VecDestroy(&Ku);
}

TEST_P(DimensionFromDm, BlockKernelAgreesWithMatMult) {
  const int D = GetParam().dim;
  Vec u, Ku, blocked;
  Apply(
      [=](const double* x, double* v) {
        for (int i = 0; i < D; ++i) v[i] = std::sin(3.0 * x[0] + i) * std::cos(2.0 * x[D - 1]);
      },
      &u, &Ku);
  VecDuplicate(Ku, &blocked);
  PetscReal scale;
  MatNorm(K_, NORM_INFINITY, &scale);  // rounding of a row's sum: ‖K‖∞ ‖u‖∞ (‖u‖∞ ≤ 1)
  for (bool compress : {false, true})
    for (bool wide : {false, true}) {
      wave::BlockKernel kernel;
      ASSERT_EQ(kernel.Setup(K_, wide, compress), 0);
      VecSet(blocked, 0.0);
      ASSERT_EQ(kernel.Apply(u, blocked), 0);
      PetscReal difference;
      VecAXPY(blocked, -1.0, Ku);
      VecNorm(blocked, NORM_INFINITY, &difference);
      EXPECT_LT(difference, 1e-14 * scale) << "compress " << compress << ", wide " << kernel.wide();  // its own order
    }
  VecDestroy(&blocked);
  VecDestroy(&u);
  VecDestroy(&Ku);
}

TEST_P(DimensionFromDm, LtsLevelsReachEveryDof) {
  wave::LtsOptions options;
  options.on = true;
  wave::LtsLevels levels;
  ASSERT_EQ(wave::AssignCellLevels(space_, material_, options, &levels), 0);
  ASSERT_EQ(levels.cell_level.size(), space_.cells().size());
  std::vector<PetscInt> finest;
  std::vector<std::vector<char>> touched;
  ASSERT_EQ(wave::DofLevels(space_, levels, &finest, &touched), 0);
  PetscInt owned;
  VecGetLocalSize(mass_, &owned);
  ASSERT_EQ(finest.size(), static_cast<std::size_t>(owned));
  for (PetscInt level : finest) EXPECT_TRUE(level >= 0 && level < levels.levels);
  // Halving a cell doubles its frequency in any dimension (K_e/M_e ∝ 1/h²):
  // gradients ×2, measure ÷2^D.
  fe::CellQuadrature q;
  ASSERT_EQ(space_.Evaluate(space_.cells()[0], &q), 0);
  const bool hrz = space_.simplex() && space_.degree() == 2;
  const double omega = wave::CellAngularFrequency(q, material_, hrz);
  for (double& g : q.grad) g *= 2.0;
  for (double& w : q.weight) w /= std::pow(2.0, GetParam().dim);
  EXPECT_NEAR(wave::CellAngularFrequency(q, material_, hrz), 2.0 * omega, 1e-9 * omega);
  std::printf("  %s: %" PetscInt_FMT " LTS level(s), ω of the first cell %.4g rad/s\n",
              BoxCaseName({GetParam(), 0}).c_str(), levels.levels, omega);
}

INSTANTIATE_TEST_SUITE_P(BoxMeshes, DimensionFromDm, ::testing::ValuesIn(AllBoxCases()), BoxCaseName);

}  // namespace
}  // namespace vibrotherm::testing
