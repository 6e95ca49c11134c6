// The thermoelastic transfer matrix (heat dofs × wave dofs), PHYSICS.md §2:
//   B_hj = −T0 β ∫ ψ_h ∇·φ_j dx,   β = (3λ + 2G) α_L,
// integrated over the heat mesh's cells, their quadrature points located in the
// wave mesh (fe/cell_locator). Both directions of the coupling use it:
//   waves → heat  Q = B u̇            (thermoelastic_source.hpp: one_way and two_way)
//   heat → waves  f = −(1/T0) Bᵀ θ    (thermal_stress.hpp: two_way), its adjoint,
// so that the power the thermal stress takes from the waves, (1/T0) θᵀ B u̇, is
// the entropy-weighted heating: the discrete energy budget closes by construction.
#pragma once

#include <petscmat.h>

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::coupling {

/// B with beta_T0 = T0 β [Pa]. Collective over both meshes.
PetscErrorCode AssembleThermoelasticTransfer(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat,
                                             double beta_T0, Mat* transfer);

}  // namespace vibrotherm::coupling
