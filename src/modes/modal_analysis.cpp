#include "vibrotherm/modes/modal_analysis.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>

#include "vibrotherm/store/atomic_file.hpp"
#include "vibrotherm/io/field_output.hpp"
#include "vibrotherm/mesh/plex/plex_access.hpp"
#include "vibrotherm/options/petsc/option_choice.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/util/heartbeat.hpp"
#include "vibrotherm/wave/elastic_operator.hpp"
#include "vibrotherm/wave/factor_memory.hpp"
#include "vibrotherm/wave/wave_boundary.hpp"

namespace vibrotherm::modes {

const std::vector<OptionSpec<ModesOptions>>& ModesOptionSpecs() {
  using O = ModesOptions;
  using contact::Range;
  static const std::vector<OptionSpec<O>> specs = {
      IntOption("-modes_n", &O::n, Range::at_least(1), "Number of modes"),
      RealOption("-modes_target_frequency", &O::target_frequency, Range::positive(), "Hz",
                 "Modes nearest this frequency (a free specimen's rigid motions sit at 0)"),
      RealOption("-modes_defect_radius", &O::defect_radius, Range::at_least(0.0), "m",
                 "Distance from the crack counted as the defect"),
      RealOption("-modes_memory_limit", &O::memory_limit_gb, Range::at_least(0.0), "GB",
                 "Memory the factorisation may take (0: 0.9 x available)"),
      ChoiceOption("-modes_crack", &O::contact, {"open", "contact"},
                   "The crack in the modes: open (faces free) or contact (linearised at -crack_a0, as the harmonic "
                   "start)"),
  };
  return specs;
}

PetscErrorCode ReadModesOptions(MPI_Comm comm, double default_frequency, double default_radius, ModesOptions* o,
                                OptionValues* values) {
  PetscFunctionBeginUser;
  o->target_frequency = default_frequency;
  o->defect_radius = default_radius;
  PetscCall(ReadOptionSpecs(comm, "Natural modes (-modes)", ModesOptionSpecs(), o, values));
  PetscFunctionReturn(0);
}

PetscErrorCode ModalAnalysis::AddStiffness(const ExtraStiffness& extra, Vec mass, Mat K) const {
  PetscFunctionBeginUser;
  std::vector<PetscInt> rows, cols;
  std::vector<double> values;
  PetscCall(extra(space_, mass, &rows, &cols, &values));
  PetscCall(MatSetOption(K, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  for (std::size_t k = 0; k < rows.size(); ++k) PetscCall(MatSetValue(K, rows[k], cols[k], values[k], ADD_VALUES));
  PetscCall(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

ModalAnalysis::~ModalAnalysis() {
  for (Mat* m : {&P_, &K_, &M_}) (void)MatDestroy(m);
  for (Vec& v : shapes_) (void)VecDestroy(&v);
}

namespace {

using Direction = std::array<double, 3>;

/// v minus its components along the orthonormal basis; true if what is left is not
/// (nearly) zero, then normalised.
bool Orthonormalise(const std::vector<Direction>& basis, Direction* v) {
  for (const Direction& b : basis) {
    const double dot = b[0] * (*v)[0] + b[1] * (*v)[1] + b[2] * (*v)[2];
    for (int i = 0; i < 3; ++i) (*v)[i] -= dot * b[i];
  }
  const double norm = std::sqrt((*v)[0] * (*v)[0] + (*v)[1] * (*v)[1] + (*v)[2] * (*v)[2]);
  if (norm < 1e-8) return false;
  if (std::abs(norm - 1.0) > 1e-14)  // a unit vector stays as it is, bit for bit
    for (double& x : *v) x /= norm;
  return true;
}

/// Free directions of every owned node: the orthonormal complement, in D dimensions, of
/// the span of its constraint directions (D − independent constraints of them). A
/// direction orthogonal to one constraint keeps the 2D rule's (−d_y, d_x).
std::vector<std::vector<Direction>> FreeDirections(int D, PetscInt nodes,
                                                   const std::vector<wave::Constraint>& constraints) {
  std::vector<std::vector<Direction>> constrained(nodes), free(nodes);
  for (const wave::Constraint& c : constraints) {
    Direction d{c.d[0], c.d[1], D == 3 ? c.d[2] : 0.0};
    if (Orthonormalise(constrained[c.node], &d)) constrained[c.node].push_back(d);
  }
  for (PetscInt i = 0; i < nodes; ++i) {
    std::vector<Direction> span = constrained[i];
    std::vector<Direction> candidates;
    if (D == 2 && span.size() == 1) candidates.push_back({-span[0][1], span[0][0], 0.0});
    for (int axis = 0; axis < D; ++axis) candidates.push_back({axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0,
                                                                axis == 2 ? 1.0 : 0.0});
    for (Direction v : candidates)
      if (static_cast<int>(span.size()) < D && Orthonormalise(span, &v)) {
        span.push_back(v);
        free[i].push_back(v);
      }
  }
  return free;
}

}  // namespace

PetscErrorCode ModalAnalysis::Setup(DM wave_dm, PetscInt degree, const wave::ElasticMaterial& material,
                                    const wave::Excitation& excitation, const ExtraStiffness& extra) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)wave_dm);
  material_ = material;
  PetscInt dim;
  PetscCall(DMGetDimension(wave_dm, &dim));
  PetscCall(space_.Setup(wave_dm, degree, dim));
  Mat K;
  Vec mass;
  PetscCall(wave::AssembleElasticOperators(space_, material, &K, &mass));
  wave::WaveBoundary boundary;
  PetscCall(wave::BuildWaveBoundary(space_, material, excitation, &boundary));

  // P: one row per full dof, one column per free direction of its node.
  PetscInt n_full, row_start;
  PetscCall(VecGetLocalSize(mass, &n_full));
  PetscCall(VecGetOwnershipRange(mass, &row_start, nullptr));
  const PetscInt D = space_.dim();
  const auto free = FreeDirections(static_cast<int>(D), n_full / D, boundary.constraints);
  PetscInt n_reduced = 0, col_start = 0;
  for (const auto& f : free) n_reduced += static_cast<PetscInt>(f.size());
  PetscCallMPI(MPI_Exscan(&n_reduced, &col_start, 1, MPIU_INT, MPI_SUM, comm));
  PetscCallMPI(MPI_Allreduce(&n_reduced, &reduced_dofs_, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(MatCreateAIJ(comm, n_full, n_reduced, PETSC_DETERMINE, PETSC_DETERMINE, D, nullptr, D, nullptr, &P_));
  PetscInt col = col_start;
  for (std::size_t node = 0; node < free.size(); ++node)
    for (const auto& t : free[node]) {
      for (PetscInt i = 0; i < D; ++i)
        if (t[i] != 0.0) PetscCall(MatSetValue(P_, row_start + D * node + i, col, t[i], INSERT_VALUES));
      ++col;
    }
  PetscCall(MatAssemblyBegin(P_, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(P_, MAT_FINAL_ASSEMBLY));

  // K_r = Pᵀ K P (K as AIJ: PtAP of a block matrix with a scalar P is not offered); M_r likewise.
  Mat K_aij, M_full;
  PetscCall(MatConvert(K, MATAIJ, MAT_INITIAL_MATRIX, &K_aij));
  if (extra) PetscCall(AddStiffness(extra, mass, K_aij));
  PetscCall(MatPtAP(K_aij, P_, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &K_));
  PetscCall(MatCreateAIJ(comm, n_full, n_full, PETSC_DETERMINE, PETSC_DETERMINE, 1, nullptr, 0, nullptr, &M_full));
  PetscCall(MatDiagonalSet(M_full, mass, INSERT_VALUES));
  PetscCall(MatPtAP(M_full, P_, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &M_));
  for (Mat* m : {&K, &K_aij, &M_full}) PetscCall(MatDestroy(m));
  PetscCall(VecDestroy(&mass));
  PetscFunctionReturn(0);
}

PetscErrorCode ModalAnalysis::CellsNearCracks(const CrackDistance& crack_distance, double radius,
                                              std::vector<bool>* near) const {
  PetscFunctionBeginUser;
  near->clear();
  if (space_.dim() == 2) {
    mesh::VertexCoordinates x;
    PetscCall(x.Setup(space_.dm()));
    for (PetscInt c : space_.cells()) {
      std::array<double, 2> centre;
      PetscCall(mesh::CellCentroid(space_.dm(), x, c, &centre));
      near->push_back(crack_distance({centre[0], centre[1], 0.0}) <= radius);
    }
  } else {
    mesh::VertexPositions<3> x;
    PetscCall(x.Setup(space_.dm()));
    for (PetscInt c : space_.cells()) {
      geometry::Point<3> centre;
      PetscCall(mesh::CellCentroid(space_.dm(), x, c, &centre));
      near->push_back(crack_distance({centre[0], centre[1], centre[2]}) <= radius);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode ModalAnalysis::DefectParticipation(Vec phi, const std::vector<bool>& near, double* share) const {
  PetscFunctionBeginUser;
  DM dm = space_.dm();
  Vec local;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscCall(DMGlobalToLocal(dm, phi, INSERT_VALUES, local));
  PetscSection section;
  PetscCall(DMGetLocalSection(dm, &section));
  const int n = space_.dim() * space_.nodes_per_cell();
  std::vector<double> Ke(n * n);
  fe::CellQuadrature q;
  double energy[2] = {0.0, 0.0};  // near the cracks, everywhere
  for (std::size_t k = 0; k < space_.cells().size(); ++k) {
    const PetscInt c = space_.cells()[k];
    PetscCall(space_.Evaluate(c, &q));
    wave::ElementStiffness(q, material_.lambda(), material_.shear_modulus(), Ke.data());
    PetscScalar* u = nullptr;
    PetscCall(DMPlexVecGetClosure(dm, section, local, c, nullptr, &u));
    double e = 0.0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) e += 0.5 * u[i] * Ke[i * n + j] * u[j];
    PetscCall(DMPlexVecRestoreClosure(dm, section, local, c, nullptr, &u));
    energy[0] += near[k] ? e : 0.0;
    energy[1] += e;
  }
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, energy, 2, MPI_DOUBLE, MPI_SUM, PetscObjectComm((PetscObject)dm)));
  *share = energy[0] / energy[1];
  PetscFunctionReturn(0);
}

namespace {

/// SLEPc's generalized eigensolver about the target frequency: shift-invert, MUMPS factoring
/// K − σM (its memory checked first), -modes_ options applied. Collective.
PetscErrorCode CreateShiftInvertSolver(Mat K, Mat M, const ModesOptions& options, EPS* eps) {
  PetscFunctionBeginUser;
  ST st;
  KSP ksp;
  PC pc;
  PetscCall(EPSCreate(PetscObjectComm((PetscObject)K), eps));
  PetscCall(EPSSetOptionsPrefix(*eps, "modes_"));
  PetscCall(EPSSetOperators(*eps, K, M));
  PetscCall(EPSSetProblemType(*eps, EPS_GHEP));
  PetscCall(EPSSetDimensions(*eps, options.n, PETSC_DEFAULT, PETSC_DEFAULT));
  const double omega_target = 2.0 * M_PI * options.target_frequency;
  PetscCall(EPSSetTarget(*eps, omega_target * omega_target));
  PetscCall(EPSSetWhichEigenpairs(*eps, EPS_TARGET_MAGNITUDE));
  PetscCall(EPSSetTolerances(*eps, 1e-10, PETSC_DEFAULT));
  PetscCall(EPSGetST(*eps, &st));
  PetscCall(STSetType(st, STSINVERT));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCLU));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCall(EPSSetFromOptions(*eps));
  const char* factor_prefix;
  PetscCall(KSPGetOptionsPrefix(ksp, &factor_prefix));
  PetscCall(wave::CheckFactorMemory(K, factor_prefix,
                                    {"Modes", "-modes_memory_limit", options.memory_limit_gb, options.force}));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode ModalAnalysis::Solve(const ModesOptions& options, const CrackDistance& crack_distance) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)K_);
  PetscLogEvent solve_event;
  PetscCall(PetscLogEventRegister("ModesSolve", EPS_CLASSID, &solve_event));
  EPS eps;
  PetscCall(CreateShiftInvertSolver(K_, M_, options, &eps));
  PetscCall(PetscPrintf(comm, "Modes: shift-invert about %g Hz (MUMPS factors the stiffness), %" PetscInt_FMT
                              " modes sought\n", options.target_frequency, options.n));
  PetscCall(PetscLogEventBegin(solve_event, 0, 0, 0, 0));
  {
    const Heartbeat beat(comm, "Modes: solving");  // MUMPS and SLEPc say nothing for minutes on a 3D box
    PetscCall(EPSSolve(eps));
  }
  PetscCall(PetscLogEventEnd(solve_event, 0, 0, 0, 0));
  PetscInt converged;
  PetscCall(EPSGetConverged(eps, &converged));
  PetscCheck(converged > 0, comm, PETSC_ERR_NOT_CONVERGED,
             "-modes: SLEPc found no mode near %g Hz (try -modes_eps_max_it or another -modes_target_frequency)",
             options.target_frequency);
  std::vector<bool> near;
  if (crack_distance) PetscCall(CellsNearCracks(crack_distance, options.defect_radius, &near));
  Vec reduced, full;
  PetscCall(MatCreateVecs(K_, &reduced, nullptr));
  PetscCall(MatCreateVecs(P_, nullptr, &full));
  struct Found {
    Mode mode;
    Vec shape;
  };
  std::vector<Found> found;
  for (PetscInt i = 0; i < std::min(converged, options.n); ++i) {
    PetscScalar lambda;
    PetscReal error;
    PetscCall(EPSGetEigenpair(eps, i, &lambda, nullptr, reduced, nullptr));
    PetscCall(EPSComputeError(eps, i, EPS_ERROR_RELATIVE, &error));
    Vec shape;
    PetscCall(VecDuplicate(full, &shape));
    PetscCall(MatMult(P_, reduced, shape));
    PetscReal peak;
    PetscCall(VecNorm(shape, NORM_INFINITY, &peak));
    PetscCall(VecScale(shape, 1.0 / peak));
    Mode mode{std::sqrt(std::max(PetscRealPart(lambda), 0.0)) / (2.0 * M_PI), NAN, error};
    // A rigid motion (a free specimen's zero mode) strains nothing: no participation.
    const bool rigid = mode.frequency < 1e-3 * options.target_frequency;
    if (!rigid && crack_distance) PetscCall(DefectParticipation(shape, near, &mode.participation));
    found.push_back({mode, shape});
  }
  std::sort(found.begin(), found.end(),
            [](const Found& a, const Found& b) { return a.mode.frequency < b.mode.frequency; });
  for (const Found& f : found) {
    modes_.push_back(f.mode);
    shapes_.push_back(f.shape);
  }
  PetscCall(VecDestroy(&reduced));
  PetscCall(VecDestroy(&full));
  PetscCall(EPSDestroy(&eps));
  PetscFunctionReturn(0);
}

PetscErrorCode ModalAnalysis::Write(const std::string& dir) const {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)K_);
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    VibrothermCallCpp(PETSC_COMM_SELF, {
      store::AtomicFile file(dir + "/modes.csv");
      auto& out = file.stream();
      out << "mode,frequency,participation,error\n" << std::setprecision(10);
      for (std::size_t k = 0; k < modes_.size(); ++k)
        out << k << ',' << modes_[k].frequency << ',' << modes_[k].participation << ',' << modes_[k].error << '\n';
      file.commit();
    });
  }
  io::FieldFile shapes;
  PetscCall(shapes.Open(comm, dir + "/modes.h5", io::XdmfLayout::kSingleSeries, "frequency"));
  PetscCall(shapes.AddMesh("wave", space_));
  // Shapes are scaled to a peak |u| component of 1: no units.
  for (std::size_t k = 0; k < shapes_.size(); ++k)
    PetscCall(shapes.WriteField("wave", "mode", "1", shapes_[k], static_cast<int>(k), modes_[k].frequency));
  PetscCall(shapes.Finish());
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::modes
