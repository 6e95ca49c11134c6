// Parameters of the crack laws and normal laws, with the option names users type.
//
// Plain data (no PETSc). Each law declares its own options (name, help, unit,
// default, allowed values) next to its factory; contact_parameters() lists
// them all, and the simulator and vibrotherm-contact both read that list.
// A default-constructed ContactParameters holds the declared defaults.
#pragma once

#include <stdexcept>
#include <string>

namespace vibrotherm::contact {

/// Thrown for invalid user input; what() names the option or file.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ContactParameters {
  ContactParameters();  ///< every field at its declared default

  // Common to all laws (contact_parameters.cpp).
  std::string crack_law;   ///< -crack_law open|linear|clapping|coulomb|mmd
  std::string normal_law;  ///< -contact_normal_law power|biwa|linear|table
  double mu;               ///< -contact_mu friction coefficient (coulomb, mmd)
  double a0;               ///< -contact_a0 initial approach added to a [m]

  // Normal laws (normal_law_<name>.cpp).
  double power_C, power_p;  ///< -contact_power_C, -contact_power_p: N = C a^p
  double biwa_C, biwa_m;    ///< -contact_biwa_C, -contact_biwa_m: K = C_B N^m
  double linear_k;          ///< -contact_linear_k: N = k a
  std::string table_file;   ///< -contact_table_file: CSV of a,N

  // Crack laws (crack_law_<name>.cpp).
  double linear_kn, linear_kt;  ///< -crack_linear_kn, -crack_linear_kt (Schoenberg)
  double coulomb_kt;            ///< -crack_coulomb_kt: tangential stiffness while stuck
  double nu;                    ///< -material_nu: the material's Poisson ratio (mmd: Mindlin's θ)
  double mmd_rel_tol;           ///< -crack_mmd_tol: shortest kept segment / a
  int mmd_max_breakpoints;      ///< -crack_mmd_max_breakpoints: hard memory bound
  int mmd_levels;               ///< -crack_mmd_levels: spring-bed levels per cell (3D)

  /// Mindlin's compliance ratio θ = (2 − ν) / (2 (1 − ν)).
  double theta() const { return (2.0 - nu) / (2.0 * (1.0 - nu)); }

  /// Throws InputError naming the first field outside its declared range.
  void validate() const;
};

}  // namespace vibrotherm::contact
