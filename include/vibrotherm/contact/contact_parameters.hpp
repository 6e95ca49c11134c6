// Parameters of a crack law, with the option names users type.
//
// Plain data (no PETSc): the simulator and vibrotherm-contact fill it from the
// -contact_* / -crack_law options; validate() rejects bad values with a message
// that names the option.
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
  std::string crack_law = "mmd";    ///< -crack_law open|linear|clapping|coulomb|mmd
  double mu = 1.0;                  ///< -contact_mu   friction coefficient (>= 0)
  double nu = 0.33;                 ///< -contact_nu   Poisson ratio (-1, 0.5)
  std::string normal_law = "biwa";  ///< -contact_normal_law power|biwa|linear|table
  /// -contact_normal_C: power: C in N = C a^p; biwa: C_B in K = C_B N^m.
  /// Negative means "law default" (power 1e18 Pa/m^1.5, biwa 1e11 Pa^0.5/m).
  double normal_C = -1.0;
  double normal_p = 1.5;            ///< -contact_normal_p (power), >= 1
  double normal_m = 0.5;            ///< -contact_normal_m (biwa), in (0, 1)
  double normal_k = 1e14;           ///< -contact_normal_k (linear law / linear crack law) [Pa/m]
  std::string normal_table;         ///< -contact_normal_table FILE (a,N CSV)
  double a0 = 0.0;                  ///< -contact_a0 initial approach added to a [m]
  double tangential_k = 1e14;       ///< -contact_tangential_k (linear, coulomb) [Pa/m]
  double mmd_rel_tol = 1e-9;        ///< -contact_mmd_tol: shortest kept segment / a
  int mmd_max_breakpoints = 1024;   ///< -contact_mmd_max_breakpoints: hard memory bound

  /// Mindlin's compliance ratio θ = (2 − ν) / (2 (1 − ν)).
  double theta() const { return (2.0 - nu) / (2.0 * (1.0 - nu)); }

  /// Throws InputError naming the first invalid option.
  void validate() const;
};

}  // namespace vibrotherm::contact
