// Names of the DMLabels the mesh module sets, shared by every module that reads them.
//
//   crack       crack faces (both faces after the split): crack index + 1
//   crack_face  crack faces: global crack facet id 0..n-1, numbered crack by
//               crack along each crack; identifies a facet of the split (wave)
//               mesh with the facet of the unsplit (heat) mesh
//   crack_tip   vertices: 1 on crack ends inside the body (never duplicated)
//   crack_plus  split mesh: 1 on the face of each cohesive cell on the + side (the
//               bulk cell the crack normal points into: 3D the oriented normal,
//               geometry/frame.hpp; 2D the tangent along the crack's chord turned
//               by +90°, geometry/crack_chord.hpp)
//   side        outer faces of a generated specimen: Side (0 bottom .. 3 left)
//   sink        outer faces held at T0 by the heat solver: 1
//   absorbing, free, roller, fixed, source: outer faces of that mechanical kind: 1
#pragma once

namespace vibrotherm::mesh::labels {
inline constexpr const char* crack = "crack";
inline constexpr const char* crack_face = "crack_face";
inline constexpr const char* crack_tip = "crack_tip";
inline constexpr const char* crack_plus = "crack_plus";
inline constexpr const char* side = "side";
inline constexpr const char* sink = "sink";
}  // namespace vibrotherm::mesh::labels
