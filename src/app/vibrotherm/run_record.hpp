// The run record of summary.json: where and from what a run came, every option with its
// value and where the value came from, and what the program derived from them.
#pragma once

#include <string>
#include <vector>

#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/options/petsc/option_audit.hpp"
#include "vibrotherm/options/petsc/option_registry.hpp"

namespace vibrotherm::app {

/// The options a run records, by name: vibrotherm's own (the registry's) with the values its
/// readers read, and the options of the PETSc objects it made with the values their help lines
/// showed (`captured`, rank 0's; option_audit.hpp).
OptionValues RecordedOptions(const OptionRegistry& registry, const OptionValues& read,
                             const std::vector<DeclaredOption>& captured);

/// Each recorded option with its source: "command line", "options file" or "default".
std::vector<io::OptionRecord> OptionRecords(const std::vector<std::string>& command_line,
                                            const OptionValues& recorded);

/// The record: commit, host, date, command line, the options, and the derived times.
void RecordRun(const std::vector<std::string>& command_line, const OptionValues& recorded,
               const coupling::Scene& scene, io::RunSummary* summary);

}  // namespace vibrotherm::app
