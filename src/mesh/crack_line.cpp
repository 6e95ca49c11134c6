#include "vibrotherm/mesh/crack_line.hpp"

#include <petscdmplex.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "vibrotherm/mesh/plex/labels.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"

namespace vibrotherm::mesh {

PetscErrorCode CrackLine::Setup(DM dm, PetscInt crack) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  DMLabel crack_label, ids;
  PetscCall(DMGetLabel(dm, labels::crack, &crack_label));
  PetscCall(DMGetLabel(dm, labels::crack_face, &ids));
  std::vector<bool> ghost;
  PetscCall(GhostPoints(dm, &ghost));
  VertexCoordinates x;
  PetscCall(x.Setup(dm));
  PetscInt chart0, fStart, fEnd;
  PetscCall(DMPlexGetChart(dm, &chart0, nullptr));
  PetscCall(FacetRange(dm, &fStart, &fEnd));
  // Per owned facet of this crack: id, x0, y0, x1, y1. On a split mesh both
  // faces carry the id; they have the same coordinates, so duplicates are harmless.
  std::vector<double> mine;
  for (PetscInt f = fStart; f < fEnd && crack_label && ids; ++f) {
    PetscInt c, id;
    PetscCall(DMLabelGetValue(crack_label, f, &c));
    PetscCall(DMLabelGetValue(ids, f, &id));
    if (c != crack + 1 || id < 0 || ghost[f - chart0]) continue;
    const PetscInt* cone;
    PetscCall(DMPlexGetCone(dm, f, &cone));
    const auto a = x(cone[0]), b = x(cone[1]);
    mine.insert(mine.end(), {static_cast<double>(id), a[0], a[1], b[0], b[1]});
  }
  PetscMPIInt size, count = static_cast<PetscMPIInt>(mine.size());
  PetscCallMPI(MPI_Comm_size(comm, &size));
  std::vector<PetscMPIInt> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  std::vector<double> all(displs[size - 1] + counts[size - 1]);
  PetscCallMPI(MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, comm));
  std::map<long, std::array<double, 4>> facets;  // ordered by id
  for (std::size_t k = 0; k + 5 <= all.size(); k += 5)
    facets[std::lround(all[k])] = {all[k + 1], all[k + 2], all[k + 3], all[k + 4]};
  points_.clear();
  arc_.clear();
  ids_.clear();
  length_ = 0.0;
  for (const auto& [id, f] : facets) {
    std::array<double, 2> a{f[0], f[1]}, b{f[2], f[3]};
    if (points_.empty()) {
      // Orient the first facet so that its second vertex touches the next facet.
      auto next = std::next(facets.find(id));
      if (next != facets.end()) {
        const auto& g = next->second;
        auto d = [](const std::array<double, 2>& p, double qx, double qy) { return std::hypot(p[0] - qx, p[1] - qy); };
        if (std::min(d(a, g[0], g[1]), d(a, g[2], g[3])) < std::min(d(b, g[0], g[1]), d(b, g[2], g[3])))
          std::swap(a, b);
      }
      points_.push_back(a);
      arc_.push_back(0.0);
    }
    const auto& last = points_.back();
    const std::array<double, 2> far =
        std::hypot(a[0] - last[0], a[1] - last[1]) < std::hypot(b[0] - last[0], b[1] - last[1]) ? b : a;
    ids_.push_back(static_cast<PetscInt>(id));
    length_ += std::hypot(far[0] - last[0], far[1] - last[1]);
    points_.push_back(far);
    arc_.push_back(length_);
  }
  PetscFunctionReturn(0);
}

std::array<double, 2> CrackLine::At(double xi) const {
  if (points_.empty()) return {NAN, NAN};
  const double s = std::min(1.0, std::max(0.0, xi)) * length_;
  std::size_t k = std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin();
  if (k == 0) return points_.front();
  if (k >= points_.size()) return points_.back();
  const double w = (s - arc_[k - 1]) / std::max(arc_[k] - arc_[k - 1], 1e-300);
  return {points_[k - 1][0] + w * (points_[k][0] - points_[k - 1][0]),
          points_[k - 1][1] + w * (points_[k][1] - points_[k - 1][1])};
}

double CrackLine::XiOf(double x, double y) const {
  double best = INFINITY, xi = 0.0;
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const auto &p = points_[i], &q = points_[i + 1];
    const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
    const double s = len2 > 0.0 ? std::clamp(((x - p[0]) * dx + (y - p[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    const double d = std::hypot(x - p[0] - s * dx, y - p[1] - s * dy);
    if (d < best) best = d, xi = (arc_[i] + s * (arc_[i + 1] - arc_[i])) / length_;
  }
  return std::clamp(xi, 0.0, 1.0);
}

double CrackLine::Distance(double x, double y) const {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const auto &p = points_[i], &q = points_[i + 1];
    const double dx = q[0] - p[0], dy = q[1] - p[1], len2 = dx * dx + dy * dy;
    const double s = len2 > 0.0 ? std::clamp(((x - p[0]) * dx + (y - p[1]) * dy) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(x - p[0] - s * dx, y - p[1] - s * dy));
  }
  return best;
}

}  // namespace vibrotherm::mesh
