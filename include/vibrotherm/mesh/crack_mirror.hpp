// A mesh that is mirror-symmetric across each crack of a generated 2D specimen (issue 41;
// docs/METHODS.md "The mesh at a crack").
//
// Why: the two faces of a crack in a homogeneous body are mirror images, and so are the
// bodies' elastic responses near it: a pair of tangential tractions ±T on the faces opens
// no gap, a pair of normal tractions ±N slides nothing. A mesh that is not mirror-symmetric
// across the crack breaks this at the scale of its elements, and Coulomb friction (T = μN
// while sliding) closes a loop opening → N → T → slip → opening that the continuum does
// not have: a crack-face mode near the mesh's highest frequencies grows by friction, slowly
// (about 1.5 % a period in the paper scene), and deepens the claps: the friction per period
// rises (docs/MEASUREMENTS.md "What drifts in the paper scene").
//
// The plan (plain geometry, no gmsh): around each crack a rectangle of half-width `width`
// on either side of its line, from e0 to e1 along it. The mesher meshes the upper half
// (along +n, n the crack's tangent turned +90°) and copies it, reflected, onto the lower
// half (gmsh's periodic meshes with a reflection), so each element there has its mirror
// image across the crack. An end inside the specimen is passed by `width`; an end on an
// outer edge perpendicular to the crack is the band's end; an end on an inclined edge
// stops the band short of it where the band still fits (the last stretch of the crack
// there is meshed as before: its geometry is not symmetric either). A band that does not
// fit in the specimen or reaches half-way to another crack is narrowed, down to 2
// elements; a crack that has none then is said (`why`).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "vibrotherm/mesh/mesh_data.hpp"
#include "vibrotherm/mesh/scene_geometry.hpp"

namespace vibrotherm::mesh {

struct CrackMirror {
  using P = std::array<double, 2>;
  int crack = -1;        ///< index in SpecimenGeometry::cracks
  P p0{}, p1{};          ///< the crack's ends
  P e0{}, e1{};          ///< the band's ends on the crack's line (before p0 / after p1 past a tip)
  P normal{};            ///< n: the crack's tangent (p0 → p1) turned +90°
  double width = 0.0;    ///< half-width: from the line to the band's far sides [m]
  /// The far corners on the +n side ({at e0, at e1}), and on the −n side.
  std::array<P, 2> upper() const;
  std::array<P, 2> lower() const;
  /// The band's outline, counter-clockwise.
  std::vector<P> outline() const;
  /// p reflected across the crack's line.
  P reflect(const P& p) const;
};

struct CrackMirrorPlan {
  std::vector<CrackMirror> bands;  ///< the cracks that have one
  std::vector<std::string> why;    ///< for each crack without one: "crack 2: ..."
};

/// Default half-width: the distance over which the mesh grades from -mesh_h_crack to
/// -mesh_h, at least 4 elements of -mesh_h_crack.
double DefaultMirrorWidth(const SpecimenGeometry& g);

/// The bands of half-width `width` (0: none) around the cracks of g.
CrackMirrorPlan PlanCrackMirror(const SpecimenGeometry& g, double width);

/// Replaces the cells on the band's lower side (centroid inside it) by those of its upper
/// side reflected across the crack's line: the same vertices on the line, the lower
/// outline's vertices where the reflected upper outline's fall (the mesher made them
/// so: throws std::runtime_error if one is missing), new ones inside; the lower side's
/// own inner vertices dropped. Every cell then has its mirror image across the crack.
void MirrorBandCells(const CrackMirror& band, MeshData* mesh);

}  // namespace vibrotherm::mesh
