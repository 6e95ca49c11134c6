// The face an IR camera films, as the plane of its pixel grid: in 2D (plane strain)
// the specimen's own x–y plane (the temperature is uniform through the depth); in 3D
// one face of the box (-camera_face front|back|top|bottom|left|right), with two
// in-plane axes (u, v) that -camera_window and camera.h5's grid use:
//   front (z = max) and back (z = min): u = x, v = y;
//   top (y = max) and bottom (y = min): u = x, v = z;
//   right (x = max) and left (x = min): u = z, v = y.
// A point (u, v) of the face maps to the body point on that face, moved inward by a
// hair (1e-9 of the box) so that the cell that holds it is found despite rounding.
#pragma once

#include <petscdm.h>

#include <array>
#include <string>

namespace vibrotherm::coupling {

/// Whether name is one of the six faces (front, back, top, bottom, left, right).
bool IsCameraFace(const std::string& name);

class CameraFace {
 public:
  /// face: "" in 2D; in 3D one of the six names ("" = front). InputError-like PETSc error naming
  /// -camera_face for a face in 2D or an unknown name. Collective.
  PetscErrorCode Setup(DM dm, const std::string& face);
  int dim() const { return dim_; }
  /// The face's extent in (u, v): lower u, lower v, upper u, upper v [m].
  std::array<double, 4> bounds() const { return bounds_; }
  /// The body point at (u, v) (dim coordinates used).
  std::array<double, 3> Point(double u, double v) const;
  const std::string& name() const { return name_; }

 private:
  int dim_ = 2;
  int u_axis_ = 0, v_axis_ = 1, normal_axis_ = 2;
  double plane_ = 0.0;  ///< the normal coordinate of the sample points (inside the body by a hair)
  std::array<double, 4> bounds_ = {0, 0, 0, 0};
  std::string name_;
};

}  // namespace vibrotherm::coupling
