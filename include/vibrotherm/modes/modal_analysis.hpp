// Natural modes of the specimen for local defect resonance (LDR):
//
//   K φ = ω² M φ      on the crack-split mesh (the crack faces are free: the
//                     open crack, which is also the contact linearised at
//                     a0 = 0 for laws with N(0) = N'(0) = 0, e.g. Biwa's),
//
// or (-modes_crack contact) with the crack's contact linearised at its initial state
// added to K, as the harmonic start (-wave_start harmonic) does: K_c = the tangent
// stiffness of every contact cell (normal and stuck tangential springs at a0), so a
// pre-closed crack's modes are those its small vibrations resonate at (a kissing
// delamination's layer rides on these springs: its LDR lies above the open one's);
// with the wave solver's own K and lumped M, so the frequencies are those the
// explicit wave solver resonates at. Edges: roller, antisymmetric, fixed and
// the prescribed component of a displacement source are constraints; absorbing
// edges are free (their dashpots damp, they do not constrain). Constraints are
// eliminated exactly: K_r = Pᵀ K P, M_r = Pᵀ M P, with P mapping the free
// directions of every node onto the full displacement.
//
// SLEPc solves it by shift-and-invert around -modes_target_frequency (LU by
// MUMPS), -modes_n eigenpairs; -modes_eps_* and -modes_st_* tune SLEPc.
// The defect participation of a mode is the share of its strain energy in the
// cells whose centroid lies within -modes_defect_radius of a crack.
#pragma once
#include <slepceps.h>

#include <array>
#include <functional>
#include <string>
#include <vector>
#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/mesh/crack_surface.hpp"
#include "vibrotherm/wave/excitation.hpp"
#include "vibrotherm/wave/material.hpp"
#include "vibrotherm/options/petsc/option_spec.hpp"

namespace vibrotherm::modes {

struct ModesOptions {
  PetscInt n = 10;                ///< -modes_n: eigenpairs wanted
  double target_frequency = 0.0;  ///< -modes_target_frequency [Hz] (default: -source_frequency)
  double defect_radius = 0.0;     ///< -modes_defect_radius [m] (default: half the longest crack)
  double memory_limit_gb = 0.0;   ///< -modes_memory_limit [GB] for the factorisation (0: 0.9 x the memory available)
  bool force = false;             ///< -force (the mesh's option, MeshSource): factor even above that
  bool contact = false;           ///< -modes_crack contact: the contact linearised at a0 (else open)
};
/// The -modes_* options, declared (option_spec.hpp).
const std::vector<OptionSpec<ModesOptions>>& ModesOptionSpecs();
PetscErrorCode ReadModesOptions(MPI_Comm comm, double default_frequency, double default_radius, ModesOptions* o, OptionValues* values = nullptr);

struct Mode {
  double frequency;      ///< [Hz]
  double participation;  ///< strain energy near the cracks / total (nan without a crack, or for a rigid motion)
  double error;          ///< relative residual ‖Kφ − ω²Mφ‖ / ‖Kφ‖ (SLEPc)
};

/// Distance from a point (x, y, z; 2D: z = 0) to the nearest crack [m].
using CrackDistance = std::function<double(const std::array<double, 3>&)>;

class ModalAnalysis {
 public:
  ModalAnalysis() = default;
  ModalAnalysis(const ModalAnalysis&) = delete;
  ModalAnalysis& operator=(const ModalAnalysis&) = delete;
  ~ModalAnalysis();
  /// Stiffness entries added to K (global dof rows, columns, values) from the space and lumped mass.
  using ExtraStiffness = std::function<PetscErrorCode(const fe::LagrangeSpace& space, Vec mass,
                                                      std::vector<PetscInt>* rows, std::vector<PetscInt>* cols,
                                                      std::vector<double>* values)>;
  /// Assembles the reduced K (plus `extra`: the linearised contact) and M on the wave mesh. Collective.
  PetscErrorCode Setup(DM wave_dm, PetscInt degree, const wave::ElasticMaterial& material,
                       const wave::Excitation& excitation, const ExtraStiffness& extra = nullptr);
  /// Solves for the modes nearest the target; the distance to the cracks gives each
  /// mode's participation (none: no crack, no participation).
  PetscErrorCode Solve(const ModesOptions& options, const CrackDistance& crack_distance);
  /// modes.csv (rank 0) and the mode shapes in modes.h5 + modes.xmf ("time" = frequency).
  PetscErrorCode Write(const std::string& dir) const;
  const std::vector<Mode>& modes() const { return modes_; }
  PetscInt dofs() const { return reduced_dofs_; }

 private:
  /// K += the extra stiffness (assembled; its new nonzeros allocated). Collective.
  PetscErrorCode AddStiffness(const ExtraStiffness& extra, Vec mass, Mat K) const;
  /// Per local bulk cell (space order): whether its centroid lies within radius of a crack.
  PetscErrorCode CellsNearCracks(const CrackDistance& crack_distance, double radius, std::vector<bool>* near) const;
  /// Share of the strain energy of φ (full displacement) in the cells marked near.
  PetscErrorCode DefectParticipation(Vec phi, const std::vector<bool>& near, double* share) const;
  fe::LagrangeSpace space_;
  wave::ElasticMaterial material_;
  Mat P_ = nullptr, K_ = nullptr, M_ = nullptr;  ///< prolongation, reduced stiffness and mass
  PetscInt reduced_dofs_ = 0;
  std::vector<Mode> modes_;
  std::vector<Vec> shapes_;  ///< full displacement of each mode, max |u| = 1
};

}  // namespace vibrotherm::modes
