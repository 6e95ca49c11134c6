// Requirement: the assembled elastic operators are exact where they must be:
// total lumped mass = ρ·area; rigid-body motions are in the kernel of K; a
// uniform strain stores exactly (λ + 2G) ε² · area (uᵀKu), for degree 1 and 2,
// quads and triangles.
#include <cmath>

#include "mesh_test_support.hpp"
#include "vibrotherm/wave/elastic_operator.hpp"

namespace vibrotherm::testing {
namespace {

class ElasticOperator : public ::testing::TestWithParam<std::tuple<int, const char*>> {};

TEST_P(ElasticOperator, ExactForRigidMotionsUniformStrainAndMass) {
  const auto [degree, cell] = GetParam();
  ScopedSpecimen s(std::string("-specimen_width 0.05 -specimen_height 0.1 -mesh_h 0.01 -mesh_cell ") + cell);
  ASSERT_EQ(s.status, 0);
  fe::LagrangeSpace space;
  ASSERT_EQ(space.Setup(s.specimen.wave, degree, 2), 0);
  wave::ElasticMaterial mat;
  Mat K;
  Vec M;
  ASSERT_EQ(wave::AssembleElasticOperators(space, mat, &K, &M), 0);
  const double area = 0.05 * 0.1;
  PetscReal total;
  VecSum(M, &total);
  EXPECT_NEAR(total, 2 * mat.density * area, 1e-12 * total);  // both components

  std::vector<std::array<double, 2>> x;
  ASSERT_EQ(space.NodeCoordinates(&x), 0);
  Vec u_local, u, Ku;
  DMGetLocalVector(space.dm(), &u_local);
  DMCreateGlobalVector(space.dm(), &u);
  VecDuplicate(u, &Ku);
  auto fill = [&](auto f) {
    PetscScalar* a;
    VecGetArray(u_local, &a);
    for (std::size_t i = 0; i < x.size(); ++i) {
      const auto v = f(x[i][0], x[i][1]);
      a[2 * i] = v[0];
      a[2 * i + 1] = v[1];
    }
    VecRestoreArray(u_local, &a);
    DMLocalToGlobal(space.dm(), u_local, INSERT_VALUES, u);
  };
  const double K_scale = mat.E;
  for (int mode = 0; mode < 3; ++mode) {
    fill([&](double X, double Y) {
      return mode == 0 ? std::array<double, 2>{1, 0} : mode == 1 ? std::array<double, 2>{0, 1}
                                                                 : std::array<double, 2>{-Y, X};
    });
    MatMult(K, u, Ku);
    PetscReal norm;
    VecNorm(Ku, NORM_INFINITY, &norm);
    EXPECT_LT(norm, 1e-12 * K_scale * 0.1) << "rigid mode " << mode;
  }
  const double eps = 1e-4;
  fill([&](double X, double) { return std::array<double, 2>{eps * X, 0.0}; });
  MatMult(K, u, Ku);
  PetscScalar uKu;
  VecDot(u, Ku, &uKu);
  const double exact = (mat.lambda() + 2 * mat.shear_modulus()) * eps * eps * area;
  EXPECT_NEAR(uKu, exact, 1e-10 * exact);
  DMRestoreLocalVector(space.dm(), &u_local);
  VecDestroy(&u);
  VecDestroy(&Ku);
  VecDestroy(&M);
  MatDestroy(&K);
}

INSTANTIATE_TEST_SUITE_P(DegreesAndCells, ElasticOperator,
                         ::testing::Combine(::testing::Values(1, 2), ::testing::Values("quad", "tri")));

}  // namespace
}  // namespace vibrotherm::testing
