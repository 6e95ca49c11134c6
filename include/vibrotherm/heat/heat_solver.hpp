// Heat conduction on the unsplit mesh (PHYSICS.md §2), its own PETSc TS
// (prefix -heat_, implicit BDF by default):
//   ρ c_p Ṫ = ∇·(k ∇T) + q δ_Γ,   T = T0 on sink edges,
// discretised as M Ṫ + K T = Q(t) with consistent mass M and conductivity K
// assembled once. Q is the crack line source: a power per unit crack length
// (W/m per metre of depth, i.e. W/m²) on each crack facet, integrated with the
// face weights ∫φ ds. Sink dofs are algebraic rows T − T0 = 0.
#pragma once

#include <petscts.h>

#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"

namespace vibrotherm::heat {

struct HeatMaterial {
  double density = 2700.0;      ///< shared with the wave material
  double conductivity = 237.0;  ///< -heat_conductivity [W/(m K)]
  double capacity = 900.0;      ///< -heat_capacity c_p [J/(kg K)]
  double T0 = 293.15;           ///< -heat_T0 [K]
  double diffusivity() const { return conductivity / (density * capacity); }
};
PetscErrorCode ReadHeatMaterial(MPI_Comm comm, double density, HeatMaterial* material);

class HeatSolver {
 public:
  HeatSolver() = default;
  HeatSolver(const HeatSolver&) = delete;
  HeatSolver& operator=(const HeatSolver&) = delete;
  ~HeatSolver();

  /// Builds the space (-heat_degree 1|2), M, K, the sink rows and the TS on dm (the unsplit mesh).
  PetscErrorCode Setup(DM dm, const HeatMaterial& material);
  /// Sets the line source: power per unit length [W/m²] for each crack facet,
  /// indexed by its crack_face id (every rank passes the same vector).
  PetscErrorCode SetCrackPower(const std::vector<double>& power_by_facet);
  /// Advances the TS (adaptive) to t_end.
  PetscErrorCode AdvanceTo(double t_end);

  /// Temperature at a point (collective; NaN outside).
  PetscErrorCode TemperatureAt(double x, double y, double* T) const;
  /// Heat content ∫ρ c_p (T − T0) [J/m] (collective).
  PetscErrorCode HeatContent(double* content) const;
  double time() const { return time_; }
  PetscInt steps() const { return steps_; }
  const fe::LagrangeSpace& space() const { return space_; }

 private:
  static PetscErrorCode IFunction(TS ts, PetscReal t, Vec T, Vec Tdot, Vec F, void* ctx);
  static PetscErrorCode IJacobian(TS ts, PetscReal t, Vec T, Vec Tdot, PetscReal shift, Mat J, Mat P, void* ctx);

  DM dm_ = nullptr;
  fe::LagrangeSpace space_;
  HeatMaterial material_;
  Mat M_ = nullptr, K_ = nullptr;
  Vec T_ = nullptr, Q_ = nullptr, work_ = nullptr;
  std::vector<PetscInt> sink_rows_;  ///< global rows held at T0
  /// Per crack facet id: (owned-or-local dof offsets, weights) to build Q.
  struct FacetLoad {
    PetscInt id;
    std::vector<PetscInt> local_offsets;
    std::vector<double> weights;
  };
  std::vector<FacetLoad> facets_;
  TS ts_ = nullptr;
  double time_ = 0.0;
  PetscInt steps_ = 0;
};

}  // namespace vibrotherm::heat
