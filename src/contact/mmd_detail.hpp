// Internals shared by the memory-diagram update and its dissipation integral.
#pragma once

#include <cstddef>

#include "vibrotherm/contact/memory_diagram.hpp"

namespace vibrotherm::contact::detail {

using Breakpoint = MemoryDiagram::Breakpoint;

/// The diagram after a step, described relative to the old one: old points
/// [0, keep) stay, then `count` new points follow.
struct Tail {
  ContactState state = ContactState::Loss;
  int s = 0;               ///< slip direction of the active wedge edge (0: none)
  std::size_t keep = 0;    ///< old breakpoints kept unchanged
  double q = 0.0;          ///< left end of the slipped zone among springs α < min(a1, a2)
  int count = 0;           ///< new points
  double alpha[3] = {0, 0, 0}, f[3] = {0, 0, 0};
  double N = 0.0, T = 0.0; ///< tractions of the new diagram
  NormalLawValue apex;     ///< law at a2
  NormalLawValue at_q;     ///< law at q (valid when q is a new point or has_q_value)
  bool has_q_value = false;
};

/// Clips the old diagram pts[0..n) (α_{n-1} = a1, f_{n-1} = b̃1) to the wedge of
/// apex (a2, bt2), appending the newly contacting part when a2 > a1.
Tail build_tail(const Breakpoint* pts, std::size_t n, const NormalLaw& law, const MmdConfig& cfg, double a2,
                double bt2);

/// Friction work (J/m²) of the spring bed along the straight path from the old
/// diagram's apex (a1, b̃1) to (a2, bt2), a2 >= 0, all b̃ relative to the same b0.
/// q_final: left end of the slipped zone among springs below min(a1, a2).
/// The law values of `tail` at a2 and q are reused (no pow() twice).
double path_dissipation(const Breakpoint* pts, std::size_t n, const NormalLaw& law, const MmdConfig& cfg,
                        double a2, double bt2, const Tail& tail);

}  // namespace vibrotherm::contact::detail
