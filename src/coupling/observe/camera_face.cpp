#include "vibrotherm/coupling/observe/camera_face.hpp"

#include <algorithm>
#include <map>

namespace vibrotherm::coupling {
namespace {

struct FaceAxes {
  int u, v, normal;
  bool upper;  ///< the face at the normal axis' maximum
};

const std::map<std::string, FaceAxes>& Faces() {
  static const std::map<std::string, FaceAxes> faces = {
      {"front", {0, 1, 2, true}}, {"back", {0, 1, 2, false}},  {"top", {0, 2, 1, true}},
      {"bottom", {0, 2, 1, false}}, {"right", {2, 1, 0, true}}, {"left", {2, 1, 0, false}}};
  return faces;
}

}  // namespace

bool IsCameraFace(const std::string& name) { return Faces().count(name) > 0; }

PetscErrorCode CameraFace::Setup(DM dm, const std::string& face) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)dm);
  PetscInt dim;
  PetscCall(DMGetCoordinateDim(dm, &dim));
  dim_ = static_cast<int>(dim);
  PetscReal lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  PetscCall(DMGetBoundingBox(dm, lo, hi));
  if (dim_ == 2) {
    PetscCheck(face.empty(), comm, PETSC_ERR_USER_INPUT,
               "-camera_face %s: a 2D (plane strain) specimen is filmed in its own plane, no face to choose",
               face.c_str());
    name_ = "";
    bounds_ = {lo[0], lo[1], hi[0], hi[1]};
    PetscFunctionReturn(0);
  }
  name_ = face.empty() ? "front" : face;
  const auto it = Faces().find(name_);
  PetscCheck(it != Faces().end(), comm, PETSC_ERR_USER_INPUT,
             "-camera_face %s: unknown face (front, back, top, bottom, left, right)", name_.c_str());
  const FaceAxes& a = it->second;
  u_axis_ = a.u, v_axis_ = a.v, normal_axis_ = a.normal;
  const double hair = 1e-9 * std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  plane_ = a.upper ? hi[a.normal] - hair : lo[a.normal] + hair;
  bounds_ = {lo[a.u], lo[a.v], hi[a.u], hi[a.v]};
  PetscFunctionReturn(0);
}

std::array<double, 3> CameraFace::Point(double u, double v) const {
  std::array<double, 3> p = {0, 0, 0};
  p[u_axis_] = u;
  p[v_axis_] = v;
  if (dim_ == 3) p[normal_axis_] = plane_;
  return p;
}

}  // namespace vibrotherm::coupling
