// Heat conduction on the heat mesh (PHYSICS.md §2), its own PETSc TS: prefix
// -heat_ while coupled (backward Euler, fixed steps, direct solver), -heat_free_
// once the waves are gone (Crank-Nicolson on the step ladder, step_ladder.hpp):
//   ρ c_p Ṫ = ∇·(k ∇T) + q δ_Γ,   T = T0 on sink edges, h (T − T_ext) out of convective ones,
// discretised for the rise θ = T − T0 (so the TS tolerances measure the rise,
// not 293 K) as M θ̇ + (K + H) θ = Q(t) + G with row-sum lumped mass M
// (-heat_lumped_mass 0: consistent), conductivity K, lumped convective film H,
// G = H (T_ext − T0), all assembled
// once. Sink dofs are algebraic rows θ = 0; their columns are zeroed too, which
// keeps the Jacobian symmetric positive definite.
//
// Sources: a load vector Q (SetSourceLoad), assembled by its owner: the friction heat
// (coupling/exchange), or a uniform power per unit crack area on each crack for
// prescribed scenes (crack_power.hpp). Integrated with the heat basis, the injected
// power is exactly 1ᵀQ. Probes read θ from outside (heat_probes.hpp).
//
// Accounting per accepted step n (h = t_n − t_{n−1}): deposited += h·1ᵀQ_n;
// boundary loss += h·1ᵀ(H θ_n − G) − Σ_sink r_i with r = M Δθ + h((K+H)θ_n − Q_n − G),
// the flux leaving through sink and convective edges (exact for backward Euler).
#pragma once

#include <petscts.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/heat/heat_boundary.hpp"
#include "vibrotherm/heat/rung_solvers.hpp"
#include "vibrotherm/store/checkpoint.hpp"
#include "vibrotherm/mesh/plex/point_origin.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::heat {

struct HeatMaterial {
  double density = 2700.0;      ///< shared with the wave material
  double conductivity = 237.0;  ///< -heat_conductivity [W/(m K)]
  double capacity = 900.0;      ///< -heat_capacity c_p [J/(kg K)]
  double T0 = 293.15;           ///< -heat_T0 [K]
  double expansion = 23e-6;     ///< -material_expansion: linear thermal expansion α_L [1/K] (thermoelastic heating)
  double diffusivity() const { return conductivity / (density * capacity); }
};
/// -heat_conductivity, -heat_capacity, -heat_T0, -material_expansion, declared (option_spec.hpp).
const std::vector<OptionSpec<HeatMaterial>>& HeatMaterialOptionSpecs();
PetscErrorCode ReadHeatMaterial(MPI_Comm comm, double density, HeatMaterial* material, OptionValues* values = nullptr);

/// Everything the heat solver is built from (read once with the scene).
struct HeatOptions {
  HeatMaterial material;
  PetscInt degree = 1;   ///< -heat_degree 1|2
  bool lumped = true;    ///< -heat_lumped_mass: row sums (no ringing at the crack, see README)
  HeatBoundaryOptions boundary;
  /// The coupled steps' length [s] (the coupling's heat step; 0: not known). It picks
  /// their linear solver (ConfigurePc).
  double coupled_step = 0.0;
};
/// -heat_degree, -heat_lumped_mass, declared (option_spec.hpp).
const std::vector<OptionSpec<HeatOptions>>& HeatDiscretisationOptionSpecs();
/// -heat_* (material, degree, mass, edges). Collective.
PetscErrorCode ReadHeatOptions(MPI_Comm comm, double density, HeatOptions* options, OptionValues* values = nullptr);

/// The heat balance of HeatSolver::Accounts: deposited = boundary_loss + content, to the
/// integrator's accuracy (exactly for backward Euler and Crank–Nicolson).
struct HeatAccounts {
  double deposited = 0.0, boundary_loss = 0.0, content = 0.0;
};

class HeatSolver {
 public:
  HeatSolver() = default;
  HeatSolver(const HeatSolver&) = delete;
  HeatSolver& operator=(const HeatSolver&) = delete;
  ~HeatSolver();

  /// Builds the space, M, K, the edges and the TS on dm (the heat mesh).
  PetscErrorCode Setup(DM dm, const HeatOptions& options);
  /// Sets the load Q [W/m per dof], a global vector of the heat DM. Collective.
  PetscErrorCode SetSourceLoad(Vec load);
  /// A second rise field stepped with θ's own steps (the same linear system, its own load Q_p,
  /// no film source G): by linearity, the share of θ that Q_p causes (the camera's defect
  /// signal is the friction heat's share, heat_component.hpp). Zero until loaded; SetPartialLoad
  /// before each step, like SetSourceLoad. Needs a theta-family integrator (backward Euler,
  /// Crank–Nicolson): a step of another type is refused, naming -heat_free_ts_type. Collective.
  PetscErrorCode EnablePartialRise();
  PetscErrorCode SetPartialLoad(Vec load);
  /// The partial rise (null unless enabled): a global vector of the heat DM (read only).
  Vec partial_rise() const { return partial_; }
  /// What a load does to a functional φᵀθ under the coupled integrator
  /// (step_responses.cpp): lengths = h_n, h_{n−1}, ... of the last steps, newest
  /// first; w[k] such that a load Q applied in step n − k adds w[k]ᵀQ to φᵀθ at
  /// the end of step n, k = 0 .. lengths.size() − 1. supported = false (w empty)
  /// when the coupled TS is not of the theta family. Collective.
  PetscErrorCode StepResponses(Vec phi, const std::vector<double>& lengths, std::vector<Vec>* w, bool* supported);
  /// Switches to the TS of free diffusion (prefix -heat_free_; Crank-Nicolson by
  /// default, whose balance closes exactly, on the step ladder from the last
  /// coupled step). With -heat_free_ts_adapt_type basic (error control),
  /// -heat_free_ts_type bdf took 10× fewer steps on meshes much finer than the
  /// diffusion length (Carslaw-Jaeger case) but closes the balance only to ~1 %.
  PetscErrorCode UseFreeIntegrator();
  /// Back to the coupled phase's TS at the current time (after a periodic continuation's free steps).
  PetscErrorCode UseCoupledIntegrator();
  /// Advances with the free integrator (its own step schedule) to exactly t_end.
  PetscErrorCode AdvanceTo(double t_end);
  /// Advances to t_end in `steps` equal steps (coupling intervals: the source
  /// jumps at every interval, so error control there would only chase the jumps).
  PetscErrorCode AdvanceInSteps(double t_end, PetscInt steps);
  /// Called after every accepted step (recording while the heat TS runs alone).
  std::function<PetscErrorCode(const HeatSolver&)> on_step;
  /// Ends the running AdvanceTo after the current step (the run was interrupted).
  void RequestStop() { stop_requested_ = true; }

  /// Whether convective edges to an ambient T_ext ≠ T0 heat or cool the specimen (a source G ≠ 0).
  bool film_source() const { return film_total_ != 0.0; }
  /// The heat balance so far [J/m in 2D, J in 3D]: what the sources injected, what left through
  /// sink and convective edges, and the heat content ∫ρ c_p (T − T0). Collective.
  PetscErrorCode Accounts(HeatAccounts* accounts) const;
  /// The rise θ = T − T0: the solver's own global vector of the heat DM (read only).
  Vec rise() const { return theta_; }
  /// 1 / (row sums of M) [K m/J per dof], 0 on sink rows (held at T0): the
  /// adiabatic rise of a load deposited at once is its load times this. New global vector.
  PetscErrorCode LumpedCapacityInverse(Vec* inverse) const;
  double time() const { return time_; }
  PetscInt steps() const { return steps_; }
  /// Linear solvers set up so far by the free TS's steps (one per step length: rung_solvers.hpp).
  PetscInt free_solver_setups() const { return rungs_.count(free_ts_) ? rungs_.at(free_ts_)->setups() : 0; }
  PetscInt dofs() const { return global_dofs_; }
  /// That ratio for the coupled step (HeatOptions::coupled_step; < 0 when not given).
  double coupled_stiffness_ratio() const { return coupled_stiffness_ratio_; }
  /// Up to this ratio an iterative solve uses CG with Jacobi (ConfigurePc).
  static constexpr double kJacobiStiffnessRatio = 10.0;
  const fe::LagrangeSpace& space() const { return space_; }
  const HeatBoundary& boundary() const { return boundary_; }
  const HeatMaterial& material() const { return material_; }
  /// The coupled phase's state (θ keyed by dof origin; time, steps, accounts,
  /// the Jacobian's shift) into a checkpoint, and back (heat_solver_state.cpp).
  PetscErrorCode Save(store::Checkpoint& checkpoint, const mesh::PointOrigin& origin) const;
  PetscErrorCode Restore(const store::Checkpoint& checkpoint, const mesh::PointOrigin& origin);

 private:
  static PetscErrorCode IFunction(TS ts, PetscReal t, Vec theta, Vec theta_dot, Vec F, void* ctx);
  static PetscErrorCode IJacobian(TS ts, PetscReal t, Vec theta, Vec theta_dot, PetscReal shift, Mat J, Mat P,
                                  void* ctx);
  static PetscErrorCode PostStep(TS ts);
  /// J = K + shift M with the sink rows; the shift J holds is remembered (IJacobian keeps it).
  static PetscErrorCode AssembleJacobian(HeatSolver* self, PetscReal shift, Mat J);
  /// J = K + shift M with the sink rows (identity rows and columns). Collective.
  PetscErrorCode FillJacobian(double shift, Mat J) const;
  PetscErrorCode Account(double h);
  /// The partial rise through the step just taken (partial_rise.cpp).
  PetscErrorCode AdvancePartial();
  /// w of a theta-family TS (1: backward Euler, 1/2: Crank-Nicolson); family = false (w = 1) for others.
  static PetscErrorCode ThetaWeight(TS ts, bool* family, double* w);
  // Setup's parts: M and K (lumped M: row sums), the convective film into K, H, G.
  PetscErrorCode AssembleMassAndConductivity(bool lumped);
  PetscErrorCode AddConvectiveFilm();
  PetscErrorCode ScaleTolerance();
  /// A solver of J = K + M/(w dt) (sinks as the TS's), set up once per step length dt.
  PetscErrorCode ResponseSolver(double dt, double w, KSP* ksp);

  DM dm_ = nullptr;
  fe::LagrangeSpace space_;
  HeatMaterial material_;
  HeatBoundary boundary_;
  Mat M_ = nullptr, K_ = nullptr;  ///< K includes the convective film H
  Vec theta_ = nullptr, theta_prev_ = nullptr, Q_ = nullptr, G_ = nullptr, H_ = nullptr, work_ = nullptr;
  Vec residual_ = nullptr, mix_ = nullptr;  ///< Account's work vectors (every step)
  Vec partial_ = nullptr, partial_load_ = nullptr, partial_step_ = nullptr;  ///< EnablePartialRise
  double load_total_ = 0.0, film_total_ = 0.0;  ///< 1ᵀQ, 1ᵀG
  PetscErrorCode CreateTS(const char* prefix, TSType type, TSAdaptType adapt_type, TS* ts);
  /// Whether the free (adaptive) TS is the one in use.
  bool free_integrator() const { return ts_ == free_ts_ && free_ts_ != nullptr; }
  /// max_i K_ii / (shift M_ii): how far K + shift·M is from its mass (a step dt of
  /// backward Euler: shift = 1/dt). Collective.
  PetscErrorCode StiffnessToMassRatio(double shift, double* ratio) const;
  // The linear solvers (heat_linear_solver.cpp): per shift of K + shift·M, Cholesky when the
  // mesh is small (direct_solve) and the user names no other PC, else CG with Jacobi when the
  // mass dominates every row (StiffnessToMassRatio ≤ kJacobiStiffnessRatio), else CG with BoomerAMG.
  /// Whether a solver under this prefix iterates (CG) or applies a factor once (PREONLY).
  PetscErrorCode Iterative(const char* prefix, bool* iterative) const;
  /// The KSP's type and tolerance (CG to kRelativeTolerance, or PREONLY).
  PetscErrorCode ConfigureKsp(KSP ksp) const;
  /// ksp's PC for J = K + shift·M under `prefix` (the user's -<prefix>pc_* read after).
  PetscErrorCode ConfigurePc(KSP ksp, const char* prefix, double shift) const;
  /// Reads the rungs' options now (3D: BoomerAMG's defaults first), before any step makes a rung.
  PetscErrorCode ReadSolverOptions(const char* prefix) const;
  /// A TS's KSP: ConfigureKsp, and a PC applying the solver of the step's rung (rungs_[ts]).
  PetscErrorCode ConfigureStepSolver(TS ts, KSP ksp);
  /// CG's relative tolerance on a step's update (the TS solves for the change from the
  /// last state): 1e-8 (it was 1e-12, only so that 2 ranks matched serial to 1e-10).
  static constexpr double kRelativeTolerance = 1e-8;
  double coupled_stiffness_ratio_ = -1.0;  ///< of the coupled step (< 0: not known)
  static constexpr PetscInt kDirectSolveDofs = 50000;   ///< above: CG + AMG even for fixed steps
  static constexpr PetscInt kDirectSolveDofs3D = 5000;  ///< the same on a 3D mesh (more fill)
  bool direct_solve() const { return global_dofs_ <= (space_.dim() == 3 ? kDirectSolveDofs3D : kDirectSolveDofs); }
  TS coupled_ts_ = nullptr, free_ts_ = nullptr;  ///< prefixes -heat_ and -heat_free_
  TS ts_ = nullptr;                             ///< the one in use
  double time_ = 0.0, deposited_ = 0.0, boundary_loss_ = 0.0;
  double last_step_ = 0.0;  ///< the last accepted step (the free ladder's first rung)
  std::map<Mat, double> last_shift_;  ///< shift of the Jacobian each matrix holds
  double peak_rise_ = 0.0;  ///< largest rise seen [K] (sets the absolute tolerance)
  PetscInt steps_ = 0, global_dofs_ = 0;
  bool stop_requested_ = false;
  /// Each TS's solvers by step length (rung_solvers.hpp).
  std::map<TS, std::unique_ptr<RungSolvers>> rungs_;
  /// The rungs' kept shifts in a checkpoint and back (heat_solver_state.cpp).
  static std::string RungsName(TS ts);
  PetscErrorCode SaveRungs(store::Checkpoint& checkpoint) const;
  PetscErrorCode RestoreRungs(const store::Checkpoint& checkpoint);
  /// StepResponses' own solvers (the TS's are not disturbed), by shift.
  RungSolvers responses_;
};

}  // namespace vibrotherm::heat
