// Friction energy → heat load: the one home of that transfer. Built once per run
// as a parallel sparse matrix T (heat dofs × contact cells), so every exchange is
// one MatMult (PETSc moves the values between the two partitions). In both
// dimensions T = Ψ Φ: the quadrature of the crack's faces (crack_face_quadrature.hpp;
// 2D faces cut at the heat mesh's crack vertices, so the integrals are exact)
// through the surface transfer of its points (surface_transfer.hpp). A 2D crack
// line also keeps its wave elements (ξ along it) for the crack-heat record and
// the near-field temperatures.
#pragma once

#include <petscmat.h>

#include <array>
#include <vector>

#include "vibrotherm/coupling/exchange/crack_face_quadrature.hpp"
#include "vibrotherm/coupling/exchange/line_transfer.hpp"
#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/interface/crack_interface.hpp"
#include "vibrotherm/mesh/crack_surface.hpp"

namespace vibrotherm::coupling {

class FrictionHeat {
 public:
  FrictionHeat() = default;
  FrictionHeat(const FrictionHeat&) = delete;
  FrictionHeat& operator=(const FrictionHeat&) = delete;
  ~FrictionHeat();

  /// Locates the quadrature points of the contact cells' faces (on wave_space's split
  /// mesh) in heat_space's mesh: face_subdivisions parts along each direction of a
  /// face, 2D faces cut further at the vertices of heat_cracks' lines (3D: none;
  /// wave_cracks' lines give the 2D record's elements).
  /// Collective over both meshes' communicator.
  PetscErrorCode Setup(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                       const mesh::CrackSurface& wave_cracks, const fe::LagrangeSpace& heat_space,
                       const mesh::CrackSurface& heat_cracks, int face_subdivisions);
  /// Q += heat load [W/m per heat dof] of the friction energy each cell dissipated
  /// since the last call (cumulative W [J/m²] per owned cell), spread over `interval`.
  PetscErrorCode AddLoad(const std::vector<double>& dissipated_per_area, double interval, Vec Q);
  /// Q += heat load of the friction power q_c [W/m²] per owned cell, exchanging nothing.
  PetscErrorCode AddRates(const std::vector<double>& rates, Vec Q);
  /// Line density q_c [W/m²] of the owned cells in the last Load.
  const std::vector<double>& density() const { return density_; }
  /// The cells' dissipated energies at the last exchange (restarts: the interface's restored ones).
  void set_previous(const std::vector<double>& dissipated_per_area) { previous_ = dissipated_per_area; }
  const std::vector<double>& previous() const { return previous_; }
  /// The wave-side crack elements (node = global contact-cell index), the same on every rank.
  const std::vector<CrackElement>& wave_elements() const { return wave_elements_; }
  /// Vertices of the wave mesh's cracks: (crack, ξ, x, y) per vertex, the same on every rank.
  const std::vector<std::array<double, 4>>& crack_vertices() const { return crack_vertices_; }
  /// x, y, z [m] and weight (tributary length [m] in 2D, area [m²] in 3D) of each owned cell.
  const std::vector<double>& cell_places() const { return cell_places_; }
  /// Global index of this rank's first contact cell.
  PetscInt first_cell() const { return first_cell_; }
  /// Tᵀw per owned contact cell [m]: what a unit density at each cell adds to wᵀQ
  /// (w: a global vector of the heat DM). Collective.
  PetscErrorCode CellResponse(Vec w, std::vector<double>* per_cell) const;

 private:
  PetscErrorCode BuildWaveElements(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                                   const mesh::CrackSurface& wave_cracks);
  /// T = Ψ Φ of the crack faces' quadrature, checked to conserve every cell's weight.
  PetscErrorCode SetupTransfer(const interface::CrackInterface& crack, const fe::LagrangeSpace& wave_space,
                               const fe::LagrangeSpace& heat_space, const CrackFaceSplit& split);

  std::vector<CrackElement> wave_elements_;
  std::vector<std::array<double, 4>> crack_vertices_;
  Mat transfer_ = nullptr;  ///< T: heat dofs × contact cells
  Vec rate_ = nullptr;      ///< q per contact cell (owned layout of the interface)
  std::vector<double> previous_, density_, cell_places_;
  PetscInt first_cell_ = 0;
};

}  // namespace vibrotherm::coupling
