// A crack law: per contact cell, half displacements (a, b) → tractions (N, T),
// with history committed once per accepted time step (PHYSICS.md §3). b and T
// are tangential vectors: one component in 2D, two in 3D (§3.5).
//
// This is the contract between the contact library and the interface module:
// trial() is a pure function of the committed state (called at every RHS
// evaluation and stage), commit() advances the history and returns the energy
// dissipated in the step. Signs: N compressive positive; T has the sign of the
// elastic tangential displacement; the interface absorbs 2(N ȧ + T·ḃ).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

#include "vibrotherm/contact/contact_parameter_list.hpp"
#include "vibrotherm/contact/memory_diagram.hpp"
#include "vibrotherm/contact/tangential.hpp"

namespace vibrotherm::contact {

/// Tangent stiffnesses dN/da and dT_k/db_k (half-displacement units, the same
/// for every tangential component) for the stable time-step bound.
struct CellStiffness {
  double normal = 0.0, tangential = 0.0;
};

class CrackLaw {
 public:
  virtual ~CrackLaw() = default;
  virtual std::string name() const = 0;

  /// Allocates `cells` cells, each in its virgin state at (a[i], b[i]). The
  /// b[i] have the problem's tangential components (1 in 2D, 2 in 3D); every
  /// later b has as many. InputError naming -crack_law if the law has no rule
  /// for that many.
  virtual void initialize(std::size_t cells, const double* a, const Tangential* b) = 0;
  virtual std::size_t cells() const = 0;

  /// Tractions at (a, b) from the committed state; T has b's components.
  virtual Traction trial(std::size_t cell, double a, const Tangential& b) const = 0;
  virtual StepResult commit(std::size_t cell, double a, const Tangential& b) = 0;

  /// Stored interface energy of the committed state [J/m²].
  virtual double stored_energy(std::size_t cell) const = 0;
  /// Accumulated full-slip offset b0 of the committed state.
  virtual Tangential slip_offset(std::size_t cell) const = 0;
  virtual CellStiffness stiffness(std::size_t cell, double a) const = 0;

  /// False when the law can never dissipate (open, linear, clapping, μ = 0):
  /// the simulator then never creates the heat solver.
  virtual bool can_dissipate() const = 0;
  /// False for a law that never transmits any traction (open).
  virtual bool has_contact() const = 0;
  /// The bound |T| ≤ friction_bound() · N the law keeps, |T| the Euclidean length (μ; +∞ for
  /// laws without friction limit).
  virtual double friction_bound() const = 0;

  /// The committed state of a cell as numbers (checkpoints), and back bit for
  /// bit; restore_state throws std::runtime_error on a state of the wrong shape.
  virtual std::vector<double> save_state(std::size_t cell) const = 0;
  virtual void restore_state(std::size_t cell, const double* values, std::size_t n) = 0;
};

/// save_state / restore_state of a law whose cell state is some numbers and some
/// tangential vectors: the numbers, then each vector's components (restore_cell_state
/// takes the component counts from the vectors it fills).
std::vector<double> save_cell_state(std::initializer_list<double> numbers, std::initializer_list<Tangential> vectors);
void restore_cell_state(const double* values, std::size_t n, std::initializer_list<double*> numbers,
                        std::initializer_list<Tangential*> vectors);

using CrackLawFactory = std::unique_ptr<CrackLaw> (*)(const ContactParameters&);

struct CrackLawEntry {
  const char* name;
  const char* help;
  CrackLawFactory create;
  const ContactParameterList& (*parameters)();  ///< the options this law reads besides the common ones
};

/// All registered crack laws. Adding one: a new file with its factory and its
/// parameter list, and one line in crack_law_registry.cpp.
const std::vector<CrackLawEntry>& crack_laws();

/// Validates params and creates the law named by params.crack_law.
std::unique_ptr<CrackLaw> create_crack_law(const ContactParameters& params);

std::unique_ptr<CrackLaw> create_open_law(const ContactParameters&);
std::unique_ptr<CrackLaw> create_linear_slip_law(const ContactParameters&);
std::unique_ptr<CrackLaw> create_clapping_law(const ContactParameters&);
std::unique_ptr<CrackLaw> create_coulomb_law(const ContactParameters&);
std::unique_ptr<CrackLaw> create_mmd_law(const ContactParameters&);

const ContactParameterList& linear_slip_law_parameters();
const ContactParameterList& coulomb_law_parameters();
const ContactParameterList& mmd_law_parameters();

}  // namespace vibrotherm::contact
