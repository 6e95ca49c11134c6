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

#include <functional>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/util/point_exchange.hpp"

namespace vibrotherm::coupling {

/// The value at a quadrature point of ψ_h times this, for wave dof (node a, component k):
/// kernel(φ_a, ∂φ_a/∂x_k). Integrated over the heat mesh's cells (their points located in the wave mesh:
/// each sent only to the ranks whose wave cells' bounding box holds it, util/point_exchange.hpp; what
/// this rank's exchange moved in `counts` when given). Collective.
using WaveToHeatKernel = std::function<double(double phi, double dphi_dxk)>;
PetscErrorCode AssembleWaveToHeat(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat,
                                  const WaveToHeatKernel& kernel, Mat* transfer,
                                  util::ExchangeCounts* counts = nullptr);

/// B with beta_T0 = T0 β [Pa]. Collective over both meshes.
PetscErrorCode AssembleThermoelasticTransfer(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat,
                                             double beta_T0, Mat* transfer);

/// The damping heat's transfer D (heat dofs × wave dofs): D_hj = ∫ψ_h φ_a / Σ_h ∫ψ_h φ_a for dof j of
/// node a, so that a wave dof's energy E_j arrives whole as the load D E (material damping heat). Collective.
PetscErrorCode AssembleDampingTransfer(const fe::LagrangeSpace& wave, const fe::LagrangeSpace& heat, Mat* transfer);

}  // namespace vibrotherm::coupling
