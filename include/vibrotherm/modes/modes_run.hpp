// vibrotherm -modes: natural frequencies and defect participation of the
// cracked specimen instead of a time run (modal_analysis.hpp does the work).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/io/run_summary.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/modes/modal_analysis.hpp"

namespace vibrotherm::modes {

class ModesRun {
 public:
  /// Reads -modes_*, solves (stage "Modes") and fills the summary.
  PetscErrorCode Setup(const mesh::Specimen& specimen, const coupling::Scene& scene, io::RunSummary* summary);
  /// modes.csv, modes.h5/.xmf into dir.
  PetscErrorCode Write(const std::string& dir) const { return analysis_.Write(dir); }

 private:
  ModesOptions options_;
  ModalAnalysis analysis_;
};

}  // namespace vibrotherm::modes
