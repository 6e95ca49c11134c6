// Heat conduction on the unsplit mesh (PHYSICS.md §2), its own PETSc TS
// (prefix -heat_ while coupled, -heat_free_ once the waves are gone; Crank-Nicolson with adaptive steps by default):
//   ρ c_p Ṫ = ∇·(k ∇T) + q δ_Γ,   T = T0 on sink edges, h (T − T_ext) out of convective ones,
// discretised for the rise θ = T − T0 (so the TS tolerances measure the rise,
// not 293 K) as M θ̇ + (K + H) θ = Q(t) + G with consistent mass M,
// conductivity K, lumped convective film H, G = H (T_ext − T0), all assembled
// once. Sink dofs are algebraic rows θ = 0; their columns are zeroed too, which
// keeps the Jacobian symmetric positive definite (CG + BoomerAMG by default).
//
// Sources: a power per unit length on each crack facet (SetCrackPower, for
// prescribed scenes) and point sources [W per metre of depth] at fixed points
// (SetSourcePowers: the contact cells of the crack interface). Both are
// assembled with the heat basis, so the injected power is exactly their sum.
//
// Accounting per accepted step n (h = t_n − t_{n−1}): deposited += h·1ᵀQ_n;
// boundary loss += h·1ᵀ(H θ_n − G) − Σ_sink r_i with r = M Δθ + h((K+H)θ_n − Q_n − G),
// the flux leaving through sink and convective edges (exact for backward Euler).
#pragma once

#include <petscts.h>

#include <functional>
#include <map>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/fe/point_location.hpp"
#include "vibrotherm/heat/heat_boundary.hpp"

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

  /// Builds the space (-heat_degree 1|2), M, K, the edges (-heat_bc...) and the TS on dm (the unsplit mesh).
  PetscErrorCode Setup(DM dm, const HeatMaterial& material);
  /// Sets the line source: power per unit length [W/m²] for each crack facet,
  /// indexed by its crack_face id (every rank passes the same vector).
  PetscErrorCode SetCrackPower(const std::vector<double>& power_by_facet);
  /// Fixes the point sources (x, y pairs, the same on every rank). Collective.
  PetscErrorCode SetSourcePoints(const std::vector<double>& xy);
  /// Sets the power [W/m] of every point source (the same vector on every rank).
  PetscErrorCode SetSourcePowers(const std::vector<double>& power);
  /// Fixes the probe points (x, y pairs). Collective.
  PetscErrorCode SetProbePoints(const std::vector<double>& xy);
  /// Temperatures [K] at the probe points, on every rank. Collective.
  PetscErrorCode ProbeTemperatures(std::vector<double>* T) const;
  /// Switches to the TS of free diffusion (prefix -heat_free_; Crank-Nicolson by
  /// default, whose balance closes exactly). -heat_free_ts_type bdf takes 10×
  /// fewer steps on meshes much finer than the diffusion length (measured on the
  /// Carslaw-Jaeger case) but closes the balance only to ~1 %.
  PetscErrorCode UseFreeIntegrator();
  /// Advances the TS (adaptive) to exactly t_end.
  PetscErrorCode AdvanceTo(double t_end);
  /// Advances to t_end in one step (coupling intervals: the source jumps at
  /// every interval, so error control there would only chase the jumps).
  PetscErrorCode AdvanceInOneStep(double t_end);
  /// Called after every accepted step (recording while the heat TS runs alone).
  std::function<PetscErrorCode(const HeatSolver&)> on_step;

  /// Temperature at a point (collective; NaN outside).
  PetscErrorCode TemperatureAt(double x, double y, double* T) const;
  /// Heat content ∫ρ c_p (T − T0) [J/m] (collective).
  PetscErrorCode HeatContent(double* content) const;
  /// Energy injected by the sources so far [J/m].
  double deposited() const { return deposited_; }
  /// Energy that left through sink and convective edges so far [J/m].
  double boundary_loss() const { return boundary_loss_; }
  /// Temperature (not the rise) as a new global vector of the heat DM.
  PetscErrorCode Temperature(Vec* T) const;
  double time() const { return time_; }
  PetscInt steps() const { return steps_; }
  PetscInt dofs() const { return global_dofs_; }
  const fe::LagrangeSpace& space() const { return space_; }
  const HeatBoundary& boundary() const { return boundary_; }
  const HeatMaterial& material() const { return material_; }

 private:
  static PetscErrorCode IFunction(TS ts, PetscReal t, Vec theta, Vec theta_dot, Vec F, void* ctx);
  static PetscErrorCode IJacobian(TS ts, PetscReal t, Vec theta, Vec theta_dot, PetscReal shift, Mat J, Mat P,
                                  void* ctx);
  static PetscErrorCode PostStep(TS ts);
  PetscErrorCode Account(double h);
  PetscErrorCode ScaleTolerance();
  PetscErrorCode SetLoad(Vec local_load);  ///< Q from a local vector (ADD to global), and 1ᵀQ

  DM dm_ = nullptr;
  fe::LagrangeSpace space_;
  HeatMaterial material_;
  HeatBoundary boundary_;
  Mat M_ = nullptr, K_ = nullptr;  ///< K includes the convective film H
  Vec theta_ = nullptr, theta_prev_ = nullptr, Q_ = nullptr, G_ = nullptr, H_ = nullptr, work_ = nullptr;
  Vec residual_ = nullptr, mix_ = nullptr;  ///< Account's work vectors (every step)
  double load_total_ = 0.0, film_total_ = 0.0;  ///< 1ᵀQ, 1ᵀG
  /// Per crack facet id: (local dof offsets, weights) to build Q.
  struct FacetLoad {
    PetscInt id;
    std::vector<PetscInt> local_offsets;
    std::vector<double> weights;
  };
  std::vector<FacetLoad> facets_;
  std::vector<fe::LocatedPoint> sources_, probes_;
  PetscErrorCode CreateTS(const char* prefix, TSType type, TS* ts);
  TS coupled_ts_ = nullptr, free_ts_ = nullptr;  ///< prefixes -heat_ and -heat_free_
  TS ts_ = nullptr;                             ///< the one in use
  double time_ = 0.0, deposited_ = 0.0, boundary_loss_ = 0.0;
  std::map<Mat, double> last_shift_;  ///< shift of the Jacobian each matrix holds
  double peak_rise_ = 0.0;  ///< largest rise seen [K] (sets the absolute tolerance)
  PetscInt steps_ = 0, global_dofs_ = 0;
  PetscLogEvent source_event_ = 0;
};

}  // namespace vibrotherm::heat
