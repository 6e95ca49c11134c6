// vibrotherm-contact: drives one contact cell through a prescribed (t, a, b)
// history with the simulator's crack-law options, for calibrating laws.
//
//   vibrotherm-contact -history in.csv -o out.csv -crack_law mmd -contact_mu 1
//   vibrotherm-contact -history_b_amplitude 5e-9 -history_a_offset 1e-8 ...
#include <petscsys.h>

#include <fstream>
#include <string>
#include <iostream>
#include <sstream>

#include "vibrotherm/contact/cell_history.hpp"
#include "vibrotherm/interface/contact_options.hpp"
#include "vibrotherm/io/atomic_file.hpp"
#include "vibrotherm/util/errors.hpp"

namespace {

using namespace vibrotherm;

PetscErrorCode ReadSine(const char* prefix, const char* what, contact::SineComponent& c, PetscOptionItems* PetscOptionsObject) {
  PetscFunctionBeginUser;
  char name[64], help[128];
  const char* fields[] = {"amplitude", "offset", "phase", "rate"};
  double* values[] = {&c.amplitude, &c.offset, &c.phase_deg, &c.rate};
  const char* units[] = {"[m]", "[m]", "[deg]", "[m/s]"};
  for (int i = 0; i < 4; ++i) {
    PetscCall(PetscSNPrintf(name, sizeof(name), "-history_%s_%s", prefix, fields[i]));
    PetscCall(PetscSNPrintf(help, sizeof(help), "Built-in history: %s %s %s", what, fields[i], units[i]));
    PetscCall(PetscOptionsReal(name, help, nullptr, *values[i], values[i], nullptr));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode Run() {
  PetscFunctionBeginUser;
  MPI_Comm comm = PETSC_COMM_WORLD;
  contact::ContactParameters params;
  PetscCall(ReadContactOptions(comm, params));

  char history_file[PETSC_MAX_PATH_LEN] = "", out_file[PETSC_MAX_PATH_LEN] = "";
  PetscBool from_file = PETSC_FALSE, to_file = PETSC_FALSE;
  contact::SineHistory sine;
  sine.a.offset = 1e-8;
  sine.b.amplitude = 5e-9;
  PetscOptionsBegin(comm, nullptr, "Contact-cell history", nullptr);
  PetscCall(PetscOptionsString("-cell_history", "CSV file with columns t,a,b (else the built-in sinusoids); -history on the command line", nullptr,
                               history_file, history_file, sizeof(history_file), &from_file));
  PetscCall(PetscOptionsString("-o", "Output CSV (default: standard output)", nullptr, out_file, out_file,
                               sizeof(out_file), &to_file));
  PetscCall(ReadSine("a", "normal half approach a", sine.a, PetscOptionsObject));
  PetscCall(ReadSine("b", "tangential half displacement b", sine.b, PetscOptionsObject));
  PetscCall(PetscOptionsReal("-history_frequency", "Built-in history: frequency [Hz]", nullptr, sine.frequency,
                             &sine.frequency, nullptr));
  PetscCall(PetscOptionsReal("-history_cycles", "Built-in history: number of cycles", nullptr, sine.cycles,
                             &sine.cycles, nullptr));
  PetscCall(PetscOptionsInt("-history_steps_per_cycle", "Built-in history: steps per cycle", nullptr,
                            sine.steps_per_cycle, &sine.steps_per_cycle, nullptr));
  PetscCall(PetscOptionsReal("-history_ramp_cycles", "Built-in history: amplitude ramp length [cycles]", nullptr,
                             sine.ramp_cycles, &sine.ramp_cycles, nullptr));
  PetscOptionsEnd();

  std::vector<contact::HistoryPoint> history;
  VibrothermCallCpp(comm, history = from_file ? contact::read_history_csv(history_file) : contact::make_sine_history(sine));
  std::unique_ptr<contact::CrackLaw> law;
  VibrothermCallCpp(comm, law = contact::create_crack_law(params));

  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank != 0) PetscFunctionReturn(0);  // one cell: rank 0 does the work
  if (to_file) {
    std::unique_ptr<io::AtomicFile> out;
    VibrothermCallCpp(comm, out = std::make_unique<io::AtomicFile>(out_file));
    const double W = contact::drive_cell(*law, history, params.a0, out->stream());
    VibrothermCallCpp(comm, out->commit());
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "%zu steps, dissipated %.9g J/m^2 -> %s\n", history.size() - 1, W, out_file));
  } else {
    std::cout.precision(17);
    contact::drive_cell(*law, history, params.a0, std::cout);
  }
  PetscFunctionReturn(0);
}

}  // namespace

int main(int argc, char** argv) {
  // PETSc's own -history FILE would overwrite the user's history CSV with its
  // log: the command-line name -history is taken here as -cell_history.
  static char cell_history[] = "-cell_history";
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "-history") argv[i] = cell_history;
  PetscCall(PetscInitialize(&argc, &argv, nullptr,
                            "vibrotherm-contact: one contact cell driven through a (t, a, b) history.\n"));
  PetscCall(vibrotherm::PushUserErrorHandler("vibrotherm-contact"));
  const PetscErrorCode ierr = Run();
  PetscCall(PetscFinalize());
  return vibrotherm::ExitCode(ierr);
}
