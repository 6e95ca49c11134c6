// Requirement (issue 25, item 4): the wave boundary on a 3D mesh, hexahedra
// (Q1, Q2) and tetrahedra (P1, P2), serial:
//  - face weights: on every boundary face Σ w = its area and Σ w f(x_i) = ∫ f dA
//    for a linear f; the faces' areas total the box's surface;
//  - dashpots: a symmetric positive definite D×D block per node with trace
//    W ρ (c_p + 2 c_s) (W: the node's summed face weights); on a face with
//    normal e_z alone, W ρ diag(c_s, c_s, c_p);
//  - constraints: a roller face constrains its normal (e_z on z faces); a node on
//    the edge where two roller faces meet gets two directions (their normals);
//    an antisymmetry face the two tangents; a fixed face all three;
//  - a normal source on a face: the displacement prescribes the outward normal
//    component of every node on it, the traction's load shape is W n; a
//    tangential one drives x (z on a face normal to x);
//  - a plane wave's flux into an absorbing face: a uniform velocity V normal to
//    it radiates ρ c_p V² per area, along it ρ c_s V² (the dashpots' account).
#include <array>
#include <cmath>
#include <functional>
#include <map>

#include "box_mesh_support.hpp"
#include "vibrotherm/geometry/symmetric_eigen.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"
#include "vibrotherm/wave/boundary_terms.hpp"
#include "vibrotherm/wave/wave_boundary.hpp"

namespace vibrotherm::testing {
namespace {

/// A boundary face of the box: which plane it lies on (axis, at the upper end or not).
struct BoxFace {
  PetscInt point;
  int axis;
  bool upper;
};

std::vector<BoxCase> SpatialCases() {
  std::vector<BoxCase> cases;
  for (const BoxCase& c : AllBoxCases())
    if (c.dim == 3) cases.push_back(c);
  return cases;
}

class WaveBoundary3d : public ::testing::TestWithParam<BoxCase> {
 protected:
  void SetUp() override {
    ASSERT_EQ(BoxMesh(GetParam(), &dm_), 0);
    ASSERT_EQ(space_.Setup(dm_, GetParam().degree, 3), 0);
    ASSERT_EQ(space_.NodePositions(&x_), 0);
    PetscInt fStart, fEnd;
    DMPlexGetHeightStratum(dm_, 1, &fStart, &fEnd);
    for (PetscInt f = fStart; f < fEnd; ++f) {
      PetscInt support;
      DMPlexGetSupportSize(dm_, f, &support);
      if (support != 1) continue;
      std::vector<PetscInt> offsets;
      std::vector<double> w;
      double area;
      ASSERT_EQ(space_.FaceNodes(f, &offsets, &w, &area), 0);
      double centre[3] = {0, 0, 0};
      for (PetscInt o : offsets)
        for (int d = 0; d < 3; ++d) centre[d] += Node(o)[d] / offsets.size();
      for (int axis = 0; axis < 3; ++axis)
        for (bool upper : {false, true})
          if (std::abs(centre[axis] - (upper ? kBoxUpper[axis] : 0.0)) < 1e-12) faces_.push_back({f, axis, upper});
    }
  }
  void TearDown() override { DMDestroy(&dm_); }
  const double* Node(PetscInt offset) const { return &x_[offset]; }  // 3 components: offset / 3 * 3
  /// Labels the faces `on` with kind and builds the boundary.
  void Build(mesh::EdgeKind kind, const std::function<bool(const BoxFace&)>& on) {
    DMCreateLabel(dm_, mesh::to_string(kind));
    DMLabel label;
    DMGetLabel(dm_, mesh::to_string(kind), &label);
    for (const BoxFace& f : faces_)
      if (on(f)) DMLabelSetValue(label, f.point, 1);
    ASSERT_EQ(wave::BuildWaveBoundary(space_, material_, excitation_, &boundary_), 0);
  }
  /// Σ w of every node over the faces `on`, by owned node.
  std::map<PetscInt, double> NodeWeights(const std::function<bool(const BoxFace&)>& on) const {
    std::map<PetscInt, double> W;
    std::vector<PetscInt> offsets;
    std::vector<double> w;
    double area;
    for (const BoxFace& f : faces_) {
      if (!on(f) || space_.FaceNodes(f.point, &offsets, &w, &area)) continue;
      for (std::size_t j = 0; j < offsets.size(); ++j) W[offsets[j] / 3] += w[j];
    }
    return W;
  }
  /// The constrained directions of each node.
  std::map<PetscInt, std::vector<geometry::Vec3>> Directions() const {
    std::map<PetscInt, std::vector<geometry::Vec3>> dirs;
    for (const wave::Constraint& c : boundary_.constraints) dirs[c.node].push_back({c.d[0], c.d[1], c.d[2]});
    return dirs;
  }
  /// Whether node lies on the box's plane x_axis = 0.
  bool OnLowerPlane(PetscInt node, int axis) const { return std::abs(x_[3 * node + axis]) < 1e-12; }
  DM dm_ = nullptr;
  fe::LagrangeSpace space_;
  std::vector<double> x_;
  std::vector<BoxFace> faces_;
  wave::ElasticMaterial material_;
  wave::Excitation excitation_;
  wave::WaveBoundary boundary_;
};

TEST_P(WaveBoundary3d, FaceWeightsIntegrateLinearFunctionsExactly) {
  const auto f = [](const double* x) { return 1.0 + 2.0 * x[0] - x[1] + 3.0 * x[2]; };
  double total = 0.0;
  std::vector<PetscInt> offsets;
  std::vector<double> w;
  for (const BoxFace& face : faces_) {
    double area;
    ASSERT_EQ(space_.FaceNodes(face.point, &offsets, &w, &area), 0);
    double sum = 0.0, integral = 0.0, centre[3] = {0, 0, 0};
    std::vector<PetscInt> corners, edges;
    ASSERT_EQ(mesh::FaceCycle(dm_, face.point, &corners, &edges), 0);
    for (std::size_t j = 0; j < offsets.size(); ++j) {
      sum += w[j];
      integral += w[j] * f(Node(offsets[j]));
    }
    for (std::size_t j = 0; j < corners.size(); ++j)  // the corners' mean: the centroid of a rectangle or triangle
      for (int d = 0; d < 3; ++d) centre[d] += Node(offsets[j])[d] / corners.size();
    EXPECT_NEAR(sum, area, 1e-14);
    EXPECT_NEAR(integral, f(centre) * area, 1e-13);
    total += area;
  }
  const double a = kBoxUpper[0], b = kBoxUpper[1], c = kBoxUpper[2];
  EXPECT_NEAR(total, 2.0 * (a * b + b * c + c * a), 1e-13);
}

TEST_P(WaveBoundary3d, DashpotBlocksAreSymmetricPositiveWithTheirTrace) {
  const auto all = [](const BoxFace&) { return true; };
  Build(mesh::EdgeKind::Absorbing, all);
  const auto W = NodeWeights(all);
  const double rho = material_.density, cp = material_.cp(), cs = material_.cs();
  ASSERT_EQ(boundary_.dashpots.dim, 3);
  ASSERT_GT(boundary_.dashpots.size(), 0u);
  for (std::size_t k = 0; k < boundary_.dashpots.size(); ++k) {
    std::array<geometry::Vec3, 3> C;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) C[i][j] = boundary_.dashpots.at(k, i, j);
    const double expected = W.at(boundary_.dashpots.nodes[k]) * rho * (cp + 2.0 * cs);
    EXPECT_NEAR(C[0][0] + C[1][1] + C[2][2], expected, 1e-12 * expected);
    EXPECT_GT(geometry::EigenSymmetric3(C).value[2], 0.0) << "node " << boundary_.dashpots.nodes[k];
  }
}

TEST_P(WaveBoundary3d, DashpotOnAFaceNormalToZIsDiagonal) {
  const auto bottom = [](const BoxFace& f) { return f.axis == 2 && !f.upper; };
  Build(mesh::EdgeKind::Absorbing, bottom);
  const auto W = NodeWeights(bottom);
  const double rho = material_.density, diag[3] = {material_.cs(), material_.cs(), material_.cp()};
  std::size_t weighted = 0;
  for (const auto& [node, w] : W) weighted += w != 0.0;
  ASSERT_EQ(boundary_.dashpots.size(), weighted);
  for (std::size_t k = 0; k < boundary_.dashpots.size(); ++k) {
    const double w = W.at(boundary_.dashpots.nodes[k]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(boundary_.dashpots.at(k, i, j), i == j ? w * rho * diag[i] : 0.0, 1e-12 * w * rho * diag[2]);
  }
}

TEST_P(WaveBoundary3d, RollerOnZFacesConstrainsEz) {
  Build(mesh::EdgeKind::Roller, [](const BoxFace& f) { return f.axis == 2; });
  const auto dirs = Directions();
  EXPECT_EQ(dirs.size(), NodeWeights([](const BoxFace& f) { return f.axis == 2; }).size());
  for (const auto& [node, d] : dirs) {
    ASSERT_EQ(d.size(), 1u) << "node " << node;
    EXPECT_NEAR(std::abs(d[0][2]), 1.0, 1e-14);
  }
}

TEST_P(WaveBoundary3d, TwoRollerFacesGiveTwoDirectionsOnTheirEdge) {
  Build(mesh::EdgeKind::Roller, [](const BoxFace& f) { return !f.upper && (f.axis == 0 || f.axis == 2); });
  std::size_t on_edge = 0;
  for (const auto& [node, d] : Directions()) {
    const bool edge = OnLowerPlane(node, 0) && OnLowerPlane(node, 2);
    ASSERT_EQ(d.size(), edge ? 2u : 1u) << "node " << node;
    if (!edge) continue;
    ++on_edge;
    // The normals e_x and e_z, orthonormal: each constraint removes its own component.
    EXPECT_NEAR(std::abs(d[0][0]) + std::abs(d[1][0]), 1.0, 1e-14);
    EXPECT_NEAR(std::abs(d[0][2]) + std::abs(d[1][2]), 1.0, 1e-14);
    EXPECT_NEAR(geometry::Dot(d[0], d[1]), 0.0, 1e-14);
    EXPECT_NEAR(d[0][1], 0.0, 1e-14);
    EXPECT_NEAR(d[1][1], 0.0, 1e-14);
  }
  EXPECT_EQ(on_edge, GetParam().degree == 1 ? 3u : 5u);  // the edge along y: 2 cells, 3 vertices (+ 2 middle nodes)
}

TEST_P(WaveBoundary3d, AntisymmetricFaceConstrainsItsTwoTangents) {
  Build(mesh::EdgeKind::Antisymmetric, [](const BoxFace& f) { return f.axis == 2 && f.upper; });
  for (const auto& [node, d] : Directions()) {
    ASSERT_EQ(d.size(), 2u) << "node " << node;
    EXPECT_NEAR(d[0][2], 0.0, 1e-14);
    EXPECT_NEAR(d[1][2], 0.0, 1e-14);
    EXPECT_NEAR(geometry::Dot(d[0], d[1]), 0.0, 1e-14);
  }
}

TEST_P(WaveBoundary3d, FixedFaceConstrainsAllThreeComponents) {
  Build(mesh::EdgeKind::Fixed, [](const BoxFace& f) { return f.axis == 1 && !f.upper; });
  const auto dirs = Directions();
  EXPECT_EQ(dirs.size(), NodeWeights([](const BoxFace& f) { return f.axis == 1 && !f.upper; }).size());
  for (const auto& [node, d] : dirs) {
    ASSERT_EQ(d.size(), 3u) << "node " << node;
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(d[k][k], 1.0);
  }
}

TEST_P(WaveBoundary3d, NormalDisplacementSourcePrescribesTheOutwardNormal) {
  excitation_.component = wave::SourceComponent::Normal;
  const auto top = [](const BoxFace& f) { return f.axis == 2 && f.upper; };
  Build(mesh::EdgeKind::Source, top);
  const auto dirs = Directions();
  EXPECT_EQ(dirs.size(), NodeWeights(top).size());
  for (const wave::Constraint& c : boundary_.constraints) {
    EXPECT_TRUE(c.source);
    EXPECT_DOUBLE_EQ(c.d[2], 1.0) << "node " << c.node;
  }
}

TEST_P(WaveBoundary3d, NormalTractionSourceLoadsWn) {
  excitation_.type = wave::SourceType::Traction;
  excitation_.component = wave::SourceComponent::Normal;
  const auto top = [](const BoxFace& f) { return f.axis == 2 && f.upper; };
  Build(mesh::EdgeKind::Source, top);
  ASSERT_NE(boundary_.traction_shape, nullptr);
  EXPECT_TRUE(boundary_.constraints.empty());
  const auto W = NodeWeights(top);
  const PetscScalar* shape;
  PetscInt n;
  VecGetLocalSize(boundary_.traction_shape, &n);
  VecGetArrayRead(boundary_.traction_shape, &shape);
  for (PetscInt node = 0; node < n / 3; ++node) {
    const auto it = W.find(node);
    const double w = it == W.end() ? 0.0 : it->second;
    EXPECT_NEAR(shape[3 * node], 0.0, 1e-15);
    EXPECT_NEAR(shape[3 * node + 1], 0.0, 1e-15);
    EXPECT_NEAR(shape[3 * node + 2], w, 1e-15);
  }
  VecRestoreArrayRead(boundary_.traction_shape, &shape);
}

TEST_P(WaveBoundary3d, TangentialSourceDrivesXOnTopAndZOnXFaces) {
  excitation_.component = wave::SourceComponent::Tangential;
  const auto top = [](const BoxFace& f) { return f.axis == 2 && f.upper; };
  Build(mesh::EdgeKind::Source, top);
  EXPECT_EQ(Directions().size(), NodeWeights(top).size());
  for (const wave::Constraint& c : boundary_.constraints) {  // one direction a node: x
    EXPECT_TRUE(c.source);
    EXPECT_NEAR(std::abs(c.d[0]), 1.0, 1e-14) << "node " << c.node;
  }
  DMRemoveLabel(dm_, mesh::to_string(mesh::EdgeKind::Source), nullptr);
  const auto side = [](const BoxFace& f) { return f.axis == 0 && !f.upper; };
  Build(mesh::EdgeKind::Source, side);
  for (const wave::Constraint& c : boundary_.constraints)
    EXPECT_NEAR(std::abs(c.d[2]), 1.0, 1e-14) << "node " << c.node;
}

TEST_P(WaveBoundary3d, AbsorbingFaceRadiatesThePlaneWaveFlux) {
  Build(mesh::EdgeKind::Absorbing, [](const BoxFace& f) { return f.axis == 2 && !f.upper; });
  Vec mass;
  DMCreateGlobalVector(dm_, &mass);
  VecSet(mass, 1.0);
  std::vector<std::unique_ptr<wave::BoundaryTerm>> terms;
  ASSERT_EQ(wave::CreateBoundaryTerms(boundary_, mass, false, &terms), 0);
  PetscInt n;
  VecGetLocalSize(mass, &n);
  const double V = 0.3, h = 1e-7, area = kBoxUpper[0] * kBoxUpper[1];
  const double impedance[3] = {material_.density * material_.cs(), material_.density * material_.cs(),
                               material_.density * material_.cp()};
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<PetscScalar> u(n, 0.0), v(n, 0.0);
    for (PetscInt i = axis; i < n; i += 3) v[i] = V;
    wave::StepState step;
    step.h = h;
    step.u = u.data();
    step.v = v.data();
    wave::BoundaryEnergy e;
    for (auto& term : terms) {
      term->Resume(step);
      term->Account(step, &e);
    }
    const double expected = h * impedance[axis] * V * V * area;
    EXPECT_NEAR(e.radiated, expected, 1e-12 * expected) << "velocity along axis " << axis;
  }
  VecDestroy(&mass);
}

INSTANTIATE_TEST_SUITE_P(Boxes, WaveBoundary3d, ::testing::ValuesIn(SpatialCases()), BoxCaseName);

}  // namespace
}  // namespace vibrotherm::testing
