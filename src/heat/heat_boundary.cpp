#include "vibrotherm/heat/heat_boundary.hpp"

#include <petscdmplex.h>
#include <petscsf.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::heat {
namespace {

PetscErrorCode ParseKind(MPI_Comm comm, const char* option, const std::string& value, ThermalEdge* kind) {
  PetscFunctionBeginUser;
  static const std::map<std::string, ThermalEdge> kinds = {
      {"sink", ThermalEdge::Sink}, {"insulated", ThermalEdge::Insulated}, {"convective", ThermalEdge::Convective}};
  auto it = kinds.find(value);
  PetscCheck(it != kinds.end(), comm, PETSC_ERR_USER_INPUT, "%s: unknown value '%s' (sink, insulated, convective)",
             option, value.c_str());
  *kind = it->second;
  PetscFunctionReturn(0);
}

/// Points that exist on more than one rank (leaves and roots with leaves of the point SF).
/// The option of side s: 0..3 by mesh::Side, 4 front (z = depth), 5 back (z = 0): the side label's values.
std::string SideOption(int s) {
  static const char* kDepthSides[2] = {"front", "back"};
  return std::string("-heat_bc_") + (s < 4 ? mesh::to_string(static_cast<mesh::Side>(s)) : kDepthSides[s - 4]);
}

PetscErrorCode SharedPoints(DM dm, std::vector<bool>* shared) {
  PetscFunctionBeginUser;
  PetscInt pStart, pEnd, nroots, nleaves;
  const PetscInt* leaves;
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  shared->assign(pEnd - pStart, false);
  PetscSF sf;
  PetscCall(DMGetPointSF(dm, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, &nleaves, &leaves, nullptr));
  if (nroots < 0) PetscFunctionReturn(0);  // serial: no graph
  for (PetscInt i = 0; i < nleaves; ++i) (*shared)[(leaves ? leaves[i] : i) - pStart] = true;
  const PetscInt* degree;
  PetscCall(PetscSFComputeDegreeBegin(sf, &degree));
  PetscCall(PetscSFComputeDegreeEnd(sf, &degree));
  for (PetscInt p = 0; p < nroots; ++p)
    if (degree[p] > 0) (*shared)[p] = true;
  PetscFunctionReturn(0);
}

/// The owned rows of sink and convective dofs from the per-rank marks (summed over the ranks that share a dof).
PetscErrorCode CollectEdgeRows(DM dm, Vec sink_local, Vec h_local, HeatBoundary* b) {
  PetscFunctionBeginUser;
  Vec sink_global, h_global;
  PetscCall(DMGetGlobalVector(dm, &sink_global));
  PetscCall(DMGetGlobalVector(dm, &h_global));
  PetscCall(VecSet(sink_global, 0.0));
  PetscCall(VecSet(h_global, 0.0));
  PetscCall(DMLocalToGlobal(dm, sink_local, ADD_VALUES, sink_global));
  PetscCall(DMLocalToGlobal(dm, h_local, ADD_VALUES, h_global));
  PetscInt rstart, n;
  PetscCall(VecGetOwnershipRange(sink_global, &rstart, nullptr));
  PetscCall(VecGetLocalSize(sink_global, &n));
  const PetscScalar *sg, *hg;
  PetscCall(VecGetArrayRead(sink_global, &sg));
  PetscCall(VecGetArrayRead(h_global, &hg));
  for (PetscInt i = 0; i < n; ++i) {
    if (PetscRealPart(sg[i]) > 0) b->sink_rows.push_back(rstart + i);
    else if (PetscRealPart(hg[i]) > 0) {  // a corner between a sink and a convective edge is held
      b->convective_rows.push_back(rstart + i);
      b->convective_h.push_back(PetscRealPart(hg[i]));
    }
  }
  PetscCall(VecRestoreArrayRead(sink_global, &sg));
  PetscCall(VecRestoreArrayRead(h_global, &hg));
  for (Vec* v : {&sink_global, &h_global}) PetscCall(DMRestoreGlobalVector(dm, v));
  PetscFunctionReturn(0);
}

}  // namespace

const std::vector<OptionSpec<HeatBoundaryOptions>>& HeatBoundaryOptionSpecs() {
  using O = HeatBoundaryOptions;
  using contact::Range;
  static const std::vector<OptionSpec<O>> specs = [] {
    const std::vector<std::string> kinds = {"sink", "insulated", "convective"};
    std::vector<OptionSpec<O>> list = {TextChoiceOption<O>(
        "-heat_bc", [](O* o) { return &o->all; }, kinds, "Every outer edge (default: sink edges)")};
    for (int s = 0; s < 6; ++s)
      list.push_back(TextChoiceOption<O>(
          SideOption(s), [s](O* o) { return &o->side[s]; }, kinds,
          s < 4 ? "One side of a generated specimen" : "One face of a 3D box (front: z = depth, back: z = 0)"));
    list.push_back(RealOption("-heat_h", &O::h, Range::at_least(0.0), "W/(m^2 K)", "Convective film coefficient"));
    list.push_back(RealOption("-heat_T_ext", &O::T_ext, Range::positive(), "K",
                              "Ambient temperature of convective edges (default: -heat_T0)"));
    return list;
  }();
  return specs;
}

PetscErrorCode ReadHeatBoundaryOptions(MPI_Comm comm, double T0, HeatBoundaryOptions* o, OptionValues* values) {
  PetscFunctionBeginUser;
  o->T_ext = T0;
  PetscCall(ReadOptionSpecs(comm, "Thermal edges", HeatBoundaryOptionSpecs(), o, values));
  PetscFunctionReturn(0);
}

PetscErrorCode BuildHeatBoundary(const fe::LagrangeSpace& space, const HeatBoundaryOptions& o, HeatBoundary* b) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  *b = HeatBoundary{};
  b->T_ext = o.T_ext;
  DMLabel side, sink;
  PetscCall(DMGetLabel(dm, mesh::labels::side, &side));
  PetscCall(DMGetLabel(dm, mesh::labels::sink, &sink));
  std::vector<bool> ghost, shared;
  PetscCall(mesh::GhostPoints(dm, &ghost));
  PetscCall(SharedPoints(dm, &shared));
  PetscInt chart0, fStart, fEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(mesh::FacetRange(dm, &fStart, &fEnd));
  // Marks go through local vectors and an ADD to the global one: a vertex shared
  // by two ranks gets the contribution of an outer face only one of them holds.
  Vec sink_local, h_local;
  PetscCall(DMGetLocalVector(dm, &sink_local));
  PetscCall(DMGetLocalVector(dm, &h_local));
  PetscCall(VecSet(sink_local, 0.0));
  PetscCall(VecSet(h_local, 0.0));
  PetscScalar *sink_mark, *hw;
  PetscCall(VecGetArray(sink_local, &sink_mark));
  PetscCall(VecGetArray(h_local, &hw));
  PetscInt counts[3] = {0, 0, 0};
  // outer_faces (DistanceToOuterEdges) are edges of a planar mesh; a 3D mesh's faces are not kept.
  const bool planar = space.dim() == 2;
  b->dimension = space.dim();
  mesh::VertexCoordinates x;
  if (planar) PetscCall(x.Setup(dm));
  for (PetscInt f = fStart; f < fEnd; ++f) {
    // Outer: one cell, and not a face the partition cut (those have their other cell elsewhere).
    PetscInt support;
    PetscCall(DMPlexGetSupportSize(dm, f, &support));
    if (support != 1 || shared[f - chart0]) continue;
    if (planar) {
      const PetscInt* cone;
      PetscCall(DMPlexGetCone(dm, f, &cone));
      b->outer_faces.push_back({x(cone[0])[0], x(cone[0])[1], x(cone[1])[0], x(cone[1])[1]});
    }
    ThermalEdge kind = ThermalEdge::Insulated;
    PetscInt s = -1, is_sink = -1;
    if (side) PetscCall(DMLabelGetValue(side, f, &s));
    if (sink) PetscCall(DMLabelGetValue(sink, f, &is_sink));
    if (s >= 0 && s < 6 && !o.side[s].empty()) PetscCall(ParseKind(comm, "-heat_bc_<side>", o.side[s], &kind));
    else if (!o.all.empty()) PetscCall(ParseKind(comm, "-heat_bc", o.all, &kind));
    else kind = is_sink == 1 ? ThermalEdge::Sink : ThermalEdge::Insulated;
    ++counts[static_cast<int>(kind)];
    if (kind == ThermalEdge::Insulated) continue;
    std::vector<PetscInt> offsets;
    std::vector<double> weights;
    double length;
    PetscCall(space.FaceNodes(f, &offsets, &weights, &length));
    for (std::size_t j = 0; j < offsets.size(); ++j) {
      if (kind == ThermalEdge::Sink) sink_mark[offsets[j]] += 1.0;
      else hw[offsets[j]] += o.h * weights[j];
    }
  }
  PetscCall(VecRestoreArray(sink_local, &sink_mark));
  PetscCall(VecRestoreArray(h_local, &hw));
  PetscCall(CollectEdgeRows(dm, sink_local, h_local, b));
  for (Vec* v : {&sink_local, &h_local}) PetscCall(DMRestoreLocalVector(dm, v));
  PetscInt global_counts[3];
  PetscCallMPI(MPI_Allreduce(counts, global_counts, 3, MPIU_INT, MPI_SUM, comm));
  b->sink_faces = global_counts[0];
  b->insulated_faces = global_counts[1];
  b->convective_faces = global_counts[2];
  PetscFunctionReturn(0);
}

PetscErrorCode DistanceToOuterEdges(MPI_Comm comm, const HeatBoundary& b, double x, double y, double* distance) {
  PetscFunctionBeginUser;
  PetscCheck(b.dimension == 2, comm, PETSC_ERR_SUP, "the distance to the outer edges is planar; this heat mesh is %dD",
             b.dimension);
  double mine = INFINITY;
  for (const auto& f : b.outer_faces) {
    const double dx = f[2] - f[0], dy = f[3] - f[1], l2 = dx * dx + dy * dy;
    const double s = l2 > 0 ? std::clamp(((x - f[0]) * dx + (y - f[1]) * dy) / l2, 0.0, 1.0) : 0.0;
    mine = std::min(mine, std::hypot(x - f[0] - s * dx, y - f[1] - s * dy));
  }
  PetscCallMPI(MPI_Allreduce(&mine, distance, 1, MPI_DOUBLE, MPI_MIN, comm));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::heat
