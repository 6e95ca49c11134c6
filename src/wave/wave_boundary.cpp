#include "vibrotherm/wave/wave_boundary.hpp"

#include <array>
#include <cmath>
#include <type_traits>

#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::wave {
namespace {

/// Outward unit normal and tangent (s = n rotated clockwise, so +x on a top edge) of a boundary face.
PetscErrorCode FaceFrame(DM dm, const mesh::VertexCoordinates& x, PetscInt face, double n[2], double s[2]) {
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
  std::array<double, 2> centroid;
  PetscCall(mesh::CellCentroid(dm, x, support[0], &centroid));
  if ((0.5 * (a[0] + b[0]) - centroid[0]) * n[0] + (0.5 * (a[1] + b[1]) - centroid[1]) * n[1] < 0) n[0] = -n[0], n[1] = -n[1];
  s[0] = n[1];
  s[1] = -n[0];
  PetscFunctionReturn(0);
}

// The kinds of edge are mesh::EdgeKind (one list: the options, the labels, these sums).
using mesh::EdgeKind;
constexpr int kKinds = static_cast<int>(std::tuple_size<std::remove_reference_t<decltype(mesh::all_edge_kinds())>>::value);
constexpr int Index(EdgeKind kind) { return static_cast<int>(kind); }

/// Per kind of edge, per node (at its x dof): Σ w B with B = ρ (c_p n nᵀ + c_s s sᵀ)
/// for absorbing edges and d dᵀ otherwise (xx, yy, xy), and Σ w d (sum, 2 dofs).
struct EdgeSums {
  Vec xx = nullptr, yy = nullptr, xy = nullptr, sum = nullptr;
  Vec* all[4] = {&xx, &yy, &xy, &sum};
  EdgeSums() = default;
  EdgeSums(const EdgeSums&) = delete;
  EdgeSums& operator=(const EdgeSums&) = delete;
  ~EdgeSums() {
    for (Vec* v : all) (void)VecDestroy(v);
  }
};

/// The sums of one kind's labelled faces into local vectors; *length: the faces' total length.
PetscErrorCode AccumulateKind(const fe::LagrangeSpace& space, const mesh::VertexCoordinates& x,
                              const ElasticMaterial& material, const Excitation& excitation, EdgeKind kind, EdgeSums* local,
                              double* length) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  for (Vec* v : local->all) {
    PetscCall(DMCreateLocalVector(dm, v));
    PetscCall(VecSet(*v, 0.0));
  }
  *length = 0.0;
  DMLabel label;
  IS faces = nullptr;
  PetscCall(DMGetLabel(dm, mesh::to_string(kind), &label));
  if (label) PetscCall(DMLabelGetStratumIS(label, 1, &faces));
  if (!faces) PetscFunctionReturn(0);
  const double rho = material.density, cp = material.cp(), cs = material.cs();
  // The direction each kind acts along: the source's chosen component, the
  // tangent for an antisymmetry plane, the normal otherwise.
  const bool tangential =
      (kind == EdgeKind::Source && excitation.component == SourceComponent::Tangential) ||
      kind == EdgeKind::Antisymmetric;
  std::vector<PetscInt> offsets;
  std::vector<double> weights;
  PetscInt nf;
  const PetscInt* f;
  PetscScalar *axx, *ayy, *axy, *asum;
  PetscCall(ISGetLocalSize(faces, &nf));
  PetscCall(ISGetIndices(faces, &f));
  PetscCall(VecGetArray(local->xx, &axx));
  PetscCall(VecGetArray(local->yy, &ayy));
  PetscCall(VecGetArray(local->xy, &axy));
  PetscCall(VecGetArray(local->sum, &asum));
  for (PetscInt i = 0; i < nf; ++i) {
    bool facet;
    PetscCall(mesh::IsFacet(dm, f[i], &facet));
    if (!facet) continue;
    double n[2], s[2], L;
    PetscCall(FaceFrame(dm, x, f[i], n, s));
    PetscCall(space.FaceNodes(f[i], &offsets, &weights, &L));
    *length += L;
    const double* d = tangential ? s : n;
    for (std::size_t j = 0; j < offsets.size(); ++j) {
      const PetscInt o = offsets[j];
      const double w = weights[j];
      if (kind == EdgeKind::Absorbing) {  // ρ (c_p n nᵀ + c_s s sᵀ)
        axx[o] += w * rho * (cp * n[0] * n[0] + cs * s[0] * s[0]);
        ayy[o] += w * rho * (cp * n[1] * n[1] + cs * s[1] * s[1]);
        axy[o] += w * rho * (cp * n[0] * n[1] + cs * s[0] * s[1]);
      } else {
        axx[o] += w * d[0] * d[0];
        ayy[o] += w * d[1] * d[1];
        axy[o] += w * d[0] * d[1];
      }
      asum[o] += w * d[0];
      asum[o + 1] += w * d[1];
    }
  }
  PetscCall(VecRestoreArray(local->xx, &axx));
  PetscCall(VecRestoreArray(local->yy, &ayy));
  PetscCall(VecRestoreArray(local->xy, &axy));
  PetscCall(VecRestoreArray(local->sum, &asum));
  PetscCall(ISRestoreIndices(faces, &f));
  PetscCall(ISDestroy(&faces));
  PetscFunctionReturn(0);
}

/// Every kind's sums over all ranks, on the owned nodes (global vectors).
PetscErrorCode SumEdgeKinds(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                            const Excitation& excitation, EdgeSums global[kKinds], double lengths[kKinds]) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm));
  for (EdgeKind kind : mesh::all_edge_kinds()) {
    const int k = Index(kind);
    EdgeSums local;
    PetscCall(AccumulateKind(space, x, material, excitation, kind, &local, &lengths[k]));
    for (int j = 0; j < 4; ++j) {
      PetscCall(DMCreateGlobalVector(dm, global[k].all[j]));
      PetscCall(VecSet(*global[k].all[j], 0.0));
      PetscCall(DMLocalToGlobal(dm, *local.all[j], ADD_VALUES, *global[k].all[j]));
    }
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, lengths, kKinds, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  PetscFunctionReturn(0);
}

/// Read access to the sums of every kind: A[kind][0..3] = xx, yy, xy, sum.
struct EdgeSumArrays {
  const PetscScalar* A[kKinds][4];
};

/// The dashpot and the constraints of each owned node from the summed edges.
void NodeConditions(const EdgeSumArrays& e, PetscInt nodes, bool displacement, WaveBoundary* bc) {
  for (PetscInt node = 0; node < nodes; ++node) {
    const PetscInt i = 2 * node;  // all three block sums are accumulated at the node's x dof
    const auto block = [&](int k, double b[3]) {
      for (int j = 0; j < 3; ++j) b[j] = e.A[k][j][i];
      return b[0] + b[1] > 0.0;
    };
    double b[3];
    if (block(Index(EdgeKind::Absorbing), b)) bc->dashpots.push_back({node, b[0], b[2], b[1]});
    if (block(Index(EdgeKind::Fixed), b)) {
      bc->constraints.push_back({node, {1.0, 0.0}, false});
      bc->constraints.push_back({node, {0.0, 1.0}, false});
      continue;
    }
    // Principal direction of Σ w d dᵀ, signed like Σ w d (consistent along an edge).
    const auto principal = [&](int k, double dir[2]) {
      if (!block(k, b)) return false;
      const double theta = 0.5 * std::atan2(2.0 * b[2], b[0] - b[1]);
      dir[0] = std::cos(theta);
      dir[1] = std::sin(theta);
      if (dir[0] * e.A[k][3][i] + dir[1] * e.A[k][3][i + 1] < 0.0) dir[0] = -dir[0], dir[1] = -dir[1];
      return true;
    };
    double d[2];
    if (displacement && principal(Index(EdgeKind::Source), d)) bc->constraints.push_back({node, {d[0], d[1]}, true});
    if (principal(Index(EdgeKind::Roller), d)) bc->constraints.push_back({node, {d[0], d[1]}, false});
    if (principal(Index(EdgeKind::Antisymmetric), d)) bc->constraints.push_back({node, {d[0], d[1]}, false});
  }
}

/// A prescribed component cannot absorb (its dashpot would only exchange energy
/// with the support): keep each dashpot on the free directions of its node,
/// C ← P C P with P = I − d dᵀ for every constrained direction d.
void KeepDashpotsOnFreeDirections(PetscInt nodes, WaveBoundary* bc) {
  std::vector<std::vector<const Constraint*>> constrained(nodes);
  for (const Constraint& c : bc->constraints) constrained[c.node].push_back(&c);
  std::vector<Dashpot> kept;
  for (Dashpot d : bc->dashpots) {
    for (const Constraint* c : constrained[d.node]) {
      const double P[2][2] = {{1 - c->d[0] * c->d[0], -c->d[0] * c->d[1]}, {-c->d[0] * c->d[1], 1 - c->d[1] * c->d[1]}};
      const double C[2][2] = {{d.xx, d.xy}, {d.xy, d.yy}};
      double PC[2][2], PCP[2][2];
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) PC[i][j] = P[i][0] * C[0][j] + P[i][1] * C[1][j];
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) PCP[i][j] = PC[i][0] * P[0][j] + PC[i][1] * P[1][j];
      d.xx = PCP[0][0];
      d.xy = PCP[0][1];
      d.yy = PCP[1][1];
    }
    if (d.xx + d.yy > 1e-12 * (std::abs(d.xx) + std::abs(d.yy) + 1e-300)) kept.push_back(d);
  }
  bc->dashpots.swap(kept);
}

}  // namespace

PetscErrorCode BuildWaveBoundary(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                 const Excitation& excitation, WaveBoundary* bc) {
  PetscFunctionBeginUser;
  // Edges, 2×2 blocks and one constrained direction a node: a 3D face needs D×D
  // blocks and up to two constrained directions (issue 25).
  PetscCheck(space.dim() == 2, PetscObjectComm((PetscObject)space.dm()), PETSC_ERR_SUP,
             "wave boundary: 2D meshes only (this one is %dD)", space.dim());
  EdgeSums sums[kKinds];
  double lengths[kKinds];
  PetscCall(SumEdgeKinds(space, material, excitation, sums, lengths));
  bc->absorbing_length = lengths[Index(EdgeKind::Absorbing)];
  bc->source_length = lengths[Index(EdgeKind::Source)];
  PetscInt nlocal;
  PetscCall(VecGetLocalSize(sums[0].xx, &nlocal));
  EdgeSumArrays arrays;
  for (int k = 0; k < kKinds; ++k)
    for (int j = 0; j < 4; ++j) PetscCall(VecGetArrayRead(*sums[k].all[j], &arrays.A[k][j]));
  bc->constraints.clear();
  bc->dashpots.clear();
  const bool displacement = excitation.type == SourceType::Displacement;
  NodeConditions(arrays, nlocal / 2, displacement, bc);
  for (int k = 0; k < kKinds; ++k)
    for (int j = 0; j < 4; ++j) PetscCall(VecRestoreArrayRead(*sums[k].all[j], &arrays.A[k][j]));
  KeepDashpotsOnFreeDirections(nlocal / 2, bc);
  PetscCall(PetscInfo(nullptr, "wave boundary: %zu dashpots, %zu constraints\n", bc->dashpots.size(),
                      bc->constraints.size()));
  if (!displacement) {  // the traction load's shape ∫φ d ds
    bc->traction_shape = sums[Index(EdgeKind::Source)].sum;
    sums[Index(EdgeKind::Source)].sum = nullptr;
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
