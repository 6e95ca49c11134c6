#include "vibrotherm/wave/wave_boundary.hpp"

#include <array>
#include <cmath>
#include <type_traits>

#include "vibrotherm/geometry/frame.hpp"
#include "vibrotherm/geometry/symmetric_eigen.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::wave {
namespace {

/// Outward unit normal and tangent (s = n rotated clockwise, so +x on a top edge) of a boundary face.
PetscErrorCode FaceFrame(DM dm, const mesh::VertexPositions<2>& x, PetscInt face, double n[2], double s[2]) {
  PetscFunctionBeginUser;
  const PetscInt* cone;
  const PetscInt* support;
  PetscCall(DMPlexGetCone(dm, face, &cone));
  PetscCall(DMPlexGetSupport(dm, face, &support));
  const auto a = x(cone[0]), b = x(cone[1]);
  const double L = std::hypot(b[0] - a[0], b[1] - a[1]);
  n[0] = (b[1] - a[1]) / L;
  n[1] = -(b[0] - a[0]) / L;
  // Orient away from the cell's centroid.
  geometry::Vec2 centroid;
  PetscCall(mesh::CellCentroid(dm, x, support[0], &centroid));
  if ((0.5 * (a[0] + b[0]) - centroid[0]) * n[0] + (0.5 * (a[1] + b[1]) - centroid[1]) * n[1] < 0) n[0] = -n[0], n[1] = -n[1];
  s[0] = n[1];
  s[1] = -n[0];
  PetscFunctionReturn(0);
}

/// Outward unit normal of a 3D boundary face: the cross product of its
/// diagonals (of two edges for a triangle), away from the cell's centroid.
PetscErrorCode FaceNormal(DM dm, const mesh::VertexPositions<3>& x, PetscInt face, geometry::Vec3* n) {
  PetscFunctionBeginUser;
  using geometry::Sub;
  std::vector<PetscInt> corners, edges;
  PetscCall(mesh::FaceCycle(dm, face, &corners, &edges));
  std::vector<geometry::Vec3> c;
  geometry::Vec3 centre{};
  for (PetscInt v : corners) {
    c.push_back(x(v));
    centre = geometry::Add(centre, geometry::Scale(1.0 / corners.size(), c.back()));
  }
  const bool triangle = c.size() == 3;
  *n = geometry::Normalized(geometry::Cross(triangle ? Sub(c[1], c[0]) : Sub(c[2], c[0]),
                                            triangle ? Sub(c[2], c[0]) : Sub(c[3], c[1])));
  const PetscInt* support;
  PetscCall(DMPlexGetSupport(dm, face, &support));
  geometry::Vec3 centroid;
  PetscCall(mesh::CellCentroid(dm, x, support[0], &centroid));
  if (geometry::Dot(Sub(centre, centroid), *n) < 0) *n = geometry::Scale(-1.0, *n);
  PetscFunctionReturn(0);
}

// The kinds of edge are mesh::EdgeKind (one list: the options, the labels, these sums).
using mesh::EdgeKind;
constexpr int kKinds = static_cast<int>(std::tuple_size<std::remove_reference_t<decltype(mesh::all_edge_kinds())>>::value);
constexpr int Index(EdgeKind kind) { return static_cast<int>(kind); }

/// Per kind of face, per node (at its D dofs): the symmetric block Σ w B with
/// B = ρ (c_p n nᵀ + c_s (I − n nᵀ)) for absorbing faces and the projector on
/// the constrained directions otherwise — diag: its diagonal; off: xy (2D);
/// xy, xz, yz (3D) — and Σ w d (sum).
struct EdgeSums {
  Vec diag = nullptr, off = nullptr, sum = nullptr;
  Vec* all[3] = {&diag, &off, &sum};
  EdgeSums() = default;
  EdgeSums(const EdgeSums&) = delete;
  EdgeSums& operator=(const EdgeSums&) = delete;
  ~EdgeSums() {
    for (Vec* v : all) (void)VecDestroy(v);
  }
};

/// What a face of one kind adds to its nodes.
struct KindRule {
  EdgeKind kind;
  double rho, cp, cs;
  bool tangential;  ///< acts along the tangent(s): an antisymmetry plane, a tangential source
  bool load;        ///< a traction source: Σ w d is the load's shape ∫φ d dA
};

/// Write access to one kind's local sums.
struct SumArrays {
  PetscScalar *diag, *off, *sum;
};

/// 2D: w B at the node with x dof o, the arithmetic of the 2D code as it has always been.
void AddEdgeNode(const KindRule& r, const double n[2], const double s[2], double w, PetscInt o, SumArrays a) {
  const double* d = r.tangential ? s : n;
  if (r.kind == EdgeKind::Absorbing) {  // ρ (c_p n nᵀ + c_s s sᵀ)
    a.diag[o] += w * r.rho * (r.cp * n[0] * n[0] + r.cs * s[0] * s[0]);
    a.diag[o + 1] += w * r.rho * (r.cp * n[1] * n[1] + r.cs * s[1] * s[1]);
    a.off[o] += w * r.rho * (r.cp * n[0] * n[1] + r.cs * s[0] * s[1]);
  } else {
    a.diag[o] += w * d[0] * d[0];
    a.diag[o + 1] += w * d[1] * d[1];
    a.off[o] += w * d[0] * d[1];
  }
  a.sum[o] += w * d[0];
  a.sum[o + 1] += w * d[1];
}

/// The direction a tangential source drives on a 3D face of normal n: x projected
/// onto the face (shear along x on the top and bottom faces), z on a face normal to x.
geometry::Vec3 SourceTangent(const geometry::Vec3& n) {
  const geometry::Vec3 axis = std::abs(n[0]) > geometry::kNearlyNormal ? geometry::Vec3{0.0, 0.0, 1.0}
                                                                       : geometry::Vec3{1.0, 0.0, 0.0};
  return geometry::Normalized(geometry::Sub(axis, geometry::Scale(geometry::Dot(axis, n), n)));
}

/// 3D: w B at the node with x dof o, B = n nᵀ (normal), I − n nᵀ (tangential), e eᵀ
/// (a tangential source along e = SourceTangent(n)) or the dashpot, and w_sum n (w_sum e).
void AddFaceNode(const KindRule& r, const geometry::Vec3& n, double w, double w_sum, PetscInt o, SumArrays a) {
  constexpr int kRow[3] = {0, 0, 1}, kCol[3] = {1, 2, 2};  // xy, xz, yz
  const bool along_tangent = r.kind == EdgeKind::Source && r.tangential;
  const geometry::Vec3 d = along_tangent ? SourceTangent(n) : n;
  const auto entry = [&](int i, int j) {
    const double normal = n[i] * n[j], tangential = (i == j ? 1.0 : 0.0) - normal;
    if (r.kind == EdgeKind::Absorbing) return r.rho * (r.cp * normal + r.cs * tangential);
    if (along_tangent) return d[i] * d[j];
    return r.tangential ? tangential : normal;
  };
  for (int i = 0; i < 3; ++i) {
    a.diag[o + i] += w * entry(i, i);
    a.off[o + i] += w * entry(kRow[i], kCol[i]);
    a.sum[o + i] += w_sum * d[i];
  }
}

/// The sums of one kind's labelled faces into local vectors; *measure: the faces' total length (area).
template <std::size_t D>
PetscErrorCode AccumulateKind(const fe::LagrangeSpace& space, const mesh::VertexPositions<D>& x, const KindRule& rule,
                              EdgeSums* local, double* measure) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  for (Vec* v : local->all) {
    PetscCall(DMCreateLocalVector(dm, v));
    PetscCall(VecSet(*v, 0.0));
  }
  *measure = 0.0;
  DMLabel label;
  IS faces = nullptr;
  PetscCall(DMGetLabel(dm, mesh::to_string(rule.kind), &label));
  if (label) PetscCall(DMLabelGetStratumIS(label, 1, &faces));
  if (!faces) PetscFunctionReturn(0);
  std::vector<PetscInt> offsets;
  std::vector<double> weights;
  PetscInt nf;
  const PetscInt* f;
  SumArrays a;
  PetscCall(ISGetLocalSize(faces, &nf));
  PetscCall(ISGetIndices(faces, &f));
  PetscCall(VecGetArray(local->diag, &a.diag));
  PetscCall(VecGetArray(local->off, &a.off));
  PetscCall(VecGetArray(local->sum, &a.sum));
  for (PetscInt i = 0; i < nf; ++i) {
    bool facet;
    PetscCall(mesh::IsFacet(dm, f[i], &facet));
    if (!facet) continue;
    double size;
    PetscCall(space.FaceNodes(f[i], &offsets, &weights, &size));
    *measure += size;
    if constexpr (D == 2) {
      double n[2], s[2];
      PetscCall(FaceFrame(dm, x, f[i], n, s));
      for (std::size_t j = 0; j < offsets.size(); ++j) AddEdgeNode(rule, n, s, weights[j], offsets[j], a);
    } else {
      geometry::Vec3 n;
      PetscCall(FaceNormal(dm, x, f[i], &n));
      // A constraint's directions (and their signs) weigh each face by its area,
      // not ∫φ: the vertex functions of a P2 triangle integrate to zero.
      const bool dashpot = rule.kind == EdgeKind::Absorbing;
      for (std::size_t j = 0; j < offsets.size(); ++j)
        AddFaceNode(rule, n, dashpot ? weights[j] : size, dashpot || rule.load ? weights[j] : size, offsets[j], a);
    }
  }
  PetscCall(VecRestoreArray(local->diag, &a.diag));
  PetscCall(VecRestoreArray(local->off, &a.off));
  PetscCall(VecRestoreArray(local->sum, &a.sum));
  PetscCall(ISRestoreIndices(faces, &f));
  PetscCall(ISDestroy(&faces));
  PetscFunctionReturn(0);
}

/// Every kind's sums over all ranks, on the owned nodes (global vectors).
template <std::size_t D>
PetscErrorCode SumEdgeKinds(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                            const Excitation& excitation, EdgeSums global[kKinds], double measures[kKinds]) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  mesh::VertexPositions<D> x;
  PetscCall(x.Setup(dm));
  for (EdgeKind kind : mesh::all_edge_kinds()) {
    const int k = Index(kind);
    // The direction each kind acts along: the source's chosen component, the
    // tangent for an antisymmetry plane, the normal otherwise.
    const bool tangential =
        (kind == EdgeKind::Source && excitation.component == SourceComponent::Tangential) ||
        kind == EdgeKind::Antisymmetric;
    const bool load = kind == EdgeKind::Source && excitation.type == SourceType::Traction;
    const KindRule rule{kind, material.density, material.cp(), material.cs(), tangential, load};
    EdgeSums local;
    PetscCall(AccumulateKind<D>(space, x, rule, &local, &measures[k]));
    for (int j = 0; j < 3; ++j) {
      PetscCall(DMCreateGlobalVector(dm, global[k].all[j]));
      PetscCall(VecSet(*global[k].all[j], 0.0));
      PetscCall(DMLocalToGlobal(dm, *local.all[j], ADD_VALUES, *global[k].all[j]));
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, measures, kKinds, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

/// Read access to the sums of every kind: A[kind][0..2] = diag, off, sum.
struct EdgeSumArrays {
  const PetscScalar* A[kKinds][3];
  int dim;
  /// The packed upper triangle (dashpot_blocks.hpp) of kind k's block at node; whether it is nonzero.
  bool Block(int k, PetscInt node, double* upper) const {
    const PetscScalar *d = A[k][0] + dim * node, *o = A[k][1] + dim * node;
    if (dim == 2) {
      upper[0] = d[0], upper[1] = o[0], upper[2] = d[1];
      return d[0] + d[1] > 0.0;
    }
    upper[0] = d[0], upper[1] = o[0], upper[2] = o[1], upper[3] = d[1], upper[4] = o[2], upper[5] = d[2];
    return d[0] + d[1] + d[2] > 0.0;
  }
  const PetscScalar* Sum(int k, PetscInt node) const { return A[k][2] + dim * node; }
};

/// The constrained directions of kind k at a 2D node: the principal direction
/// of Σ w d dᵀ, signed like Σ w d (consistent along an edge).
int PlanarDirections(const EdgeSumArrays& e, int k, PetscInt node, double dir[][3]) {
  double b[3];  // xx, xy, yy
  if (!e.Block(k, node, b)) return 0;
  const double theta = 0.5 * std::atan2(2.0 * b[1], b[0] - b[2]);
  const PetscScalar* sum = e.Sum(k, node);
  dir[0][0] = std::cos(theta);
  dir[0][1] = std::sin(theta);
  dir[0][2] = 0.0;
  if (dir[0][0] * sum[0] + dir[0][1] * sum[1] < 0.0) dir[0][0] = -dir[0][0], dir[0][1] = -dir[0][1];
  return 1;
}

/// Below this fraction of the largest eigenvalue of Σ A n nᵀ a direction is
/// not constrained: faces meeting at less than ~4° count as one plane.
constexpr double kDistinctDirection = 1e-3;

/// The constrained directions of kind k at a 3D node: the eigenvectors of the
/// summed projectors with eigenvalues well above zero (one on a face, two on
/// the edge where two faces meet, three at a corner), signed like Σ A n.
int SpatialDirections(const EdgeSumArrays& e, int k, PetscInt node, double dir[][3]) {
  double u[6];
  if (!e.Block(k, node, u)) return 0;
  const geometry::SymmetricEigen3 eig =
      geometry::EigenSymmetric3({geometry::Vec3{u[0], u[1], u[2]}, {u[1], u[3], u[4]}, {u[2], u[4], u[5]}});
  const PetscScalar* sum = e.Sum(k, node);
  const geometry::Vec3 signed_by{sum[0], sum[1], sum[2]};
  int count = 0;
  for (int m = 0; m < 3; ++m) {
    if (!(eig.value[m] > kDistinctDirection * eig.value[0])) break;
    const double sign = geometry::Dot(eig.vector[m], signed_by) < 0.0 ? -1.0 : 1.0;
    for (int c = 0; c < 3; ++c) dir[count][c] = sign * eig.vector[m][c];
    ++count;
  }
  return count;
}

/// The dashpot and the constraints of each owned node from the summed faces.
void NodeConditions(const EdgeSumArrays& e, PetscInt nodes, bool displacement, WaveBoundary* bc) {
  const int D = e.dim;
  const auto directions = D == 2 ? PlanarDirections : SpatialDirections;
  for (PetscInt node = 0; node < nodes; ++node) {
    double upper[6], dir[3][3];
    if (e.Block(Index(EdgeKind::Absorbing), node, upper)) bc->dashpots.Add(node, upper);
    if (e.Block(Index(EdgeKind::Fixed), node, upper)) {
      for (int c = 0; c < D; ++c) {
        Constraint fixed{node, {0.0, 0.0, 0.0}, false};
        fixed.d[c] = 1.0;
        bc->constraints.push_back(fixed);
      }
      continue;
    }
    const auto add = [&](EdgeKind kind, bool source) {
      const int count = directions(e, Index(kind), node, dir);
      for (int m = 0; m < count; ++m) bc->constraints.push_back({node, {dir[m][0], dir[m][1], dir[m][2]}, source});
    };
    if (displacement) add(EdgeKind::Source, true);
    add(EdgeKind::Roller, false);
    add(EdgeKind::Antisymmetric, false);
  }
}

/// A prescribed component cannot absorb (its dashpot would only exchange energy
/// with the support): keep each dashpot on the free directions of its node,
/// C ← P C P with P = I − d dᵀ for every constrained direction d.
void KeepDashpotsOnFreeDirections(PetscInt nodes, WaveBoundary* bc) {
  const int D = bc->dim;
  std::vector<std::vector<const Constraint*>> constrained(nodes);
  for (const Constraint& c : bc->constraints) constrained[c.node].push_back(&c);
  DashpotBlocks kept;
  kept.dim = D;
  for (std::size_t k = 0; k < bc->dashpots.size(); ++k) {
    double C[3][3], P[3][3], PC[3][3];
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) C[i][j] = bc->dashpots.at(k, i, j);
    for (const Constraint* c : constrained[bc->dashpots.nodes[k]]) {
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) P[i][j] = i == j ? 1 - c->d[i] * c->d[i] : -c->d[i] * c->d[j];
      // Each product summed in index order (the 2D code's bits).
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          PC[i][j] = P[i][0] * C[0][j];
          for (int m = 1; m < D; ++m) PC[i][j] += P[i][m] * C[m][j];
        }
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          C[i][j] = PC[i][0] * P[0][j];
          for (int m = 1; m < D; ++m) C[i][j] += PC[i][m] * P[m][j];
        }
    }
    double upper[6], trace = C[0][0], size = std::abs(C[0][0]);
    for (int i = 1; i < D; ++i) trace += C[i][i], size += std::abs(C[i][i]);
    for (int i = 0; i < D; ++i)
      for (int j = i; j < D; ++j) upper[UpperIndex(i, j, D)] = C[i][j];
    if (trace > 1e-12 * (size + 1e-300)) kept.Add(bc->dashpots.nodes[k], upper);
  }
  bc->dashpots = std::move(kept);
}

}  // namespace

PetscErrorCode BuildWaveBoundary(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                 const Excitation& excitation, WaveBoundary* bc) {
  PetscFunctionBeginUser;
  const int D = space.dim();
  EdgeSums sums[kKinds];
  double measures[kKinds];
  if (D == 2)
    PetscCall(SumEdgeKinds<2>(space, material, excitation, sums, measures));
  else
    PetscCall(SumEdgeKinds<3>(space, material, excitation, sums, measures));
  bc->dim = D;
  bc->absorbing_length = measures[Index(EdgeKind::Absorbing)];
  bc->source_length = measures[Index(EdgeKind::Source)];
  PetscInt nlocal;
  PetscCall(VecGetLocalSize(sums[0].diag, &nlocal));
  EdgeSumArrays arrays;
  arrays.dim = D;
  for (int k = 0; k < kKinds; ++k)
    for (int j = 0; j < 3; ++j) PetscCall(VecGetArrayRead(*sums[k].all[j], &arrays.A[k][j]));
  bc->constraints.clear();
  bc->dashpots.clear();
  bc->dashpots.dim = D;
  const bool displacement = excitation.type == SourceType::Displacement;
  NodeConditions(arrays, nlocal / D, displacement, bc);
  for (int k = 0; k < kKinds; ++k)
    for (int j = 0; j < 3; ++j) PetscCall(VecRestoreArrayRead(*sums[k].all[j], &arrays.A[k][j]));
  KeepDashpotsOnFreeDirections(nlocal / D, bc);
  PetscCall(PetscInfo(nullptr, "wave boundary: %zu dashpots, %zu constraints\n", bc->dashpots.size(),
                      bc->constraints.size()));
  if (!displacement) {  // the traction load's shape ∫φ d ds
    bc->traction_shape = sums[Index(EdgeKind::Source)].sum;
    sums[Index(EdgeKind::Source)].sum = nullptr;
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
