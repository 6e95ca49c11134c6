// The wave state a periodic continuation saves where it suspends the waves
// (-periodic_save_state FILE: a period boundary of a steady state), and the warm
// start that begins another run of the scene in it (-wave_start state
// -wave_start_state FILE): u and v times this run's source amplitude over the
// saver's. The source's phase at a period boundary is its phase at t = 0, so the
// state fits the running source as the harmonic start's does. Linear waves scale
// exactly; a clapping crack's state only approximately, which is why it is meant
// for neighbouring amplitudes at one frequency (the LDR study's rescaling and
// threshold runs): what is left of the mismatch decays as a transient, shorter
// than the one a linearized (harmonic) start leaves a clapping crack.
// The file is a store::Checkpoint (written whole or not at all) with the wave
// solver's tables and these: "source/frequency", "source/amplitude" (the envelope
// at the saved time), "source/kind" (type, component), "source/saved_at",
// "wave/dofs" (the global count, so that another mesh is refused).
#pragma once

#include <string>

#include "vibrotherm/coupling/continuation/continued_parts.hpp"

namespace vibrotherm::coupling {

/// Writes the waves' state at time t (a period boundary) to path. Collective.
PetscErrorCode SaveWaveState(const std::string& path, const ContinuedWaves& waves, const mesh::Specimen& specimen,
                             const wave::Excitation& excitation, double t);

/// Starts solver (set up, its interface attached) in the state saved in path, scaled to
/// excitation's amplitude; refuses a file of another mesh, frequency or kind of source,
/// naming -wave_start_state. Collective.
PetscErrorCode StartFromSavedState(const std::string& path, const mesh::Specimen& specimen,
                                   const wave::Excitation& excitation, wave::WaveSolver* solver);

}  // namespace vibrotherm::coupling
