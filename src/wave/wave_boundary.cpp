#include "vibrotherm/wave/wave_boundary.hpp"

#include <cmath>

#include "vibrotherm/mesh/plex_access.hpp"

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

}  // namespace

PetscErrorCode BuildWaveBoundary(const fe::LagrangeSpace& space, const ElasticMaterial& material,
                                 const Excitation& excitation, WaveBoundary* bc) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  mesh::VertexCoordinates x;
  PetscCall(x.Setup(dm));
  // Local accumulators, 2 dofs per node like the solution: one pair of vectors per kind.
  enum { Absorbing, Source, Roller, Antisymmetric, Fixed, Kinds };
  const char* names[Kinds] = {"absorbing", "source", "roller", "antisymmetric", "fixed"};
  Vec xx[Kinds], yy[Kinds], xy[Kinds], sum[Kinds];
  for (int k = 0; k < Kinds; ++k) {
    for (Vec* v : {&xx[k], &yy[k], &xy[k], &sum[k]}) {
      PetscCall(DMCreateLocalVector(dm, v));
      PetscCall(VecSet(*v, 0.0));
    }
  }
  const double rho = material.density, cp = material.cp(), cs = material.cs();
  std::vector<PetscInt> offsets;
  std::vector<double> weights;
  double lengths[Kinds] = {0, 0, 0, 0, 0};
  for (int k = 0; k < Kinds; ++k) {
    DMLabel label;
    PetscCall(DMGetLabel(dm, names[k], &label));
    if (!label) continue;
    IS faces;
    PetscCall(DMLabelGetStratumIS(label, 1, &faces));
    if (!faces) continue;
    PetscInt nf;
    const PetscInt* f;
    PetscCall(ISGetLocalSize(faces, &nf));
    PetscCall(ISGetIndices(faces, &f));
    PetscScalar *axx, *ayy, *axy, *asum;
    PetscCall(VecGetArray(xx[k], &axx));
    PetscCall(VecGetArray(yy[k], &ayy));
    PetscCall(VecGetArray(xy[k], &axy));
    PetscCall(VecGetArray(sum[k], &asum));
    for (PetscInt i = 0; i < nf; ++i) {
      PetscInt depth;
      PetscCall(DMPlexGetPointDepth(dm, f[i], &depth));
      if (depth != 1) continue;
      double n[2], s[2], L;
      PetscCall(FaceFrame(dm, x, f[i], n, s));
      PetscCall(space.FaceNodes(f[i], &offsets, &weights, &L));
      lengths[k] += L;
      // The direction each kind acts along.
      // The direction each kind acts along: the source's chosen component, the
      // tangent for an antisymmetry plane, the normal otherwise.
      const bool tangential = (k == Source && excitation.component == SourceComponent::Tangential) || k == Antisymmetric;
      const double* d = tangential ? s : n;
      for (std::size_t j = 0; j < offsets.size(); ++j) {
        const PetscInt o = offsets[j];
        const double w = weights[j];
        if (k == Absorbing) {  // ρ (c_p n nᵀ + c_s s sᵀ)
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
    PetscCall(VecRestoreArray(xx[k], &axx));
    PetscCall(VecRestoreArray(yy[k], &ayy));
    PetscCall(VecRestoreArray(xy[k], &axy));
    PetscCall(VecRestoreArray(sum[k], &asum));
    PetscCall(ISRestoreIndices(faces, &f));
    PetscCall(ISDestroy(&faces));
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, lengths, Kinds, MPI_DOUBLE, MPI_SUM, comm));
  bc->absorbing_length = lengths[Absorbing];
  bc->source_length = lengths[Source];

  // Sum over ranks onto owned nodes.
  Vec gxx[Kinds], gyy[Kinds], gxy[Kinds], gsum[Kinds];
  for (int k = 0; k < Kinds; ++k) {
    Vec* local[4] = {&xx[k], &yy[k], &xy[k], &sum[k]};
    Vec* global[4] = {&gxx[k], &gyy[k], &gxy[k], &gsum[k]};
    for (int j = 0; j < 4; ++j) {
      PetscCall(DMCreateGlobalVector(dm, global[j]));
      PetscCall(VecSet(*global[j], 0.0));
      PetscCall(DMLocalToGlobal(dm, *local[j], ADD_VALUES, *global[j]));
      PetscCall(VecDestroy(local[j]));
    }
  }
  PetscInt nlocal;
  PetscCall(VecGetLocalSize(gxx[0], &nlocal));
  const PetscScalar *A[Kinds][4];
  for (int k = 0; k < Kinds; ++k) {
    PetscCall(VecGetArrayRead(gxx[k], &A[k][0]));
    PetscCall(VecGetArrayRead(gyy[k], &A[k][1]));
    PetscCall(VecGetArrayRead(gxy[k], &A[k][2]));
    PetscCall(VecGetArrayRead(gsum[k], &A[k][3]));
  }
  bc->constraints.clear();
  bc->dashpots.clear();
  const bool displacement = excitation.type == SourceType::Displacement;
  for (PetscInt node = 0; node < nlocal / 2; ++node) {
    const PetscInt i = 2 * node;
    auto block = [&](int k, double* bxx, double* byy, double* bxy) {
      *bxx = A[k][0][i];  // all three sums are accumulated at the node's x dof
      *byy = A[k][1][i];
      *bxy = A[k][2][i];
    };
    double bxx, byy, bxy;
    block(Absorbing, &bxx, &byy, &bxy);
    if (bxx + byy > 0.0) bc->dashpots.push_back({node, bxx, bxy, byy});
    block(Fixed, &bxx, &byy, &bxy);
    if (bxx + byy > 0.0) {
      bc->constraints.push_back({node, {1.0, 0.0}, false});
      bc->constraints.push_back({node, {0.0, 1.0}, false});
      continue;
    }
    // Principal direction of Σ w d dᵀ, signed like Σ w d (consistent along an edge).
    auto principal = [&](int k, double dir[2]) {
      block(k, &bxx, &byy, &bxy);
      if (!(bxx + byy > 0.0)) return false;
      const double theta = 0.5 * std::atan2(2.0 * bxy, bxx - byy);
      dir[0] = std::cos(theta);
      dir[1] = std::sin(theta);
      if (dir[0] * A[k][3][i] + dir[1] * A[k][3][i + 1] < 0.0) dir[0] = -dir[0], dir[1] = -dir[1];
      return true;
    };
    double d[2];
    if (displacement && principal(Source, d)) bc->constraints.push_back({node, {d[0], d[1]}, true});
    if (principal(Roller, d)) bc->constraints.push_back({node, {d[0], d[1]}, false});
    if (principal(Antisymmetric, d)) bc->constraints.push_back({node, {d[0], d[1]}, false});
  }
  PetscCall(PetscInfo(nullptr, "wave boundary: %zu dashpots, %zu constraints\n", bc->dashpots.size(), bc->constraints.size()));
  for (int k = 0; k < Kinds; ++k) {
    PetscCall(VecRestoreArrayRead(gxx[k], &A[k][0]));
    PetscCall(VecRestoreArrayRead(gyy[k], &A[k][1]));
    PetscCall(VecRestoreArrayRead(gxy[k], &A[k][2]));
    PetscCall(VecRestoreArrayRead(gsum[k], &A[k][3]));
  }
  // A prescribed component cannot absorb (its dashpot would only exchange energy
  // with the support): keep each dashpot on the free directions of its node,
  // C ← P C P with P = I − d dᵀ for every constrained direction d.
  std::vector<std::vector<const Constraint*>> constrained(nlocal / 2);
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
  if (!displacement) {
    bc->traction_shape = gsum[Source];
    gsum[Source] = nullptr;
  }
  for (int k = 0; k < Kinds; ++k)
    for (Vec* v : {&gxx[k], &gyy[k], &gxy[k], &gsum[k]}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::wave
