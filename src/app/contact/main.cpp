// vibrotherm-contact: drives one contact cell through a prescribed (t, a, b)
// history with the simulator's crack-law options, for calibrating laws. A
// second tangential component b2 (CSV column or -history_b2_*) drives the law
// with two components, as in 3D.
//
//   vibrotherm-contact -history in.csv -o out.csv -crack_law mmd -contact_mu 1
//   vibrotherm-contact -history_b_amplitude 5e-9 -history_a_offset 1e-8 ...
//   vibrotherm-contact -options_file calibration.opts -o cell.csv
//
// No PETSc and no MPI: the options are the declared contact parameters
// (contact::contact_parameters(), the list the simulator reads through PETSc)
// plus the history options, read by the PETSc-free options::OptionDatabase.
// Options only the simulator knows are refused, so a scene's options file is
// usable here only through the contact options it holds.
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "history_options.hpp"
#include "vibrotherm/contact/contact_parameter_list.hpp"
#include "vibrotherm/contact/crack_law.hpp"
#include "vibrotherm/contact/normal_law_registry.hpp"
#include "vibrotherm/store/atomic_file.hpp"
#include "vibrotherm/options/declared_options.hpp"

namespace {

using namespace vibrotherm;

template <class Entry>
void print_laws(std::ostream& out, const char* title, const std::vector<Entry>& laws) {
  out << title << "\n";
  for (const Entry& e : laws) out << "  " << e.name << ": " << e.help << "\n";
}

void print_help(std::ostream& out) {
  out << "vibrotherm-contact: one contact cell driven through a (t, a, b) history; writes\n"
         "t,a,b,b0,btilde,N,T,state,dW,W rows (a, b: half normal approach and tangential\n"
         "displacement [m]; N, T tractions [Pa]; dW, W dissipated energy [J/m^2]). With a\n"
         "second tangential component b2 (two components, as in 3D; coulomb, linear,\n"
         "clapping, open): t,a,b,b2,b0,b02,btilde,btilde2,N,T,T2,state,dW,W.\n\n";
  print_laws(out, "Crack laws (-crack_law):", contact::crack_laws());
  print_laws(out, "Normal laws (-contact_normal_law):", contact::normal_laws());
  out << "\nContact options <default>:\n";
  for (const contact::ContactParameter& p : contact::contact_parameters()) out << options::help_line(p.spec) << "\n";
  out << "\nHistory options <default>:\n";
  for (const auto& p : app::history_parameters()) out << options::help_line(p.spec) << "\n";
  out << "\n  -options_file FILE                    read options from FILE (-name value per line, # comments)\n"
         "  -help                                 print this list and exit\n";
}

std::vector<std::string> known_options() {
  std::vector<std::string> names = {"-options_file", "-help", "-h"};
  options::append_names(names, contact::contact_parameters());
  options::append_names(names, app::history_parameters());
  return names;
}

std::vector<contact::HistoryPoint> make_history(const app::HistoryOptions& h) {
  const std::string file = h.history_file();
  return file.empty() ? contact::make_sine_history(h.sine()) : contact::read_history_csv(file, h.history_option());
}

/// Drives the cell; the rows reach their destination only if every row is finite.
void run(const options::OptionDatabase& db) {
  options::reject_unknown(db, known_options(), contact::renamed_contact_options());
  contact::ContactParameters params;
  options::read_parameters(db, contact::contact_parameters(), params);
  app::HistoryOptions h;
  options::read_parameters(db, app::history_parameters(), h);
  const std::unique_ptr<contact::CrackLaw> law = contact::create_crack_law(params);
  const std::vector<contact::HistoryPoint> history = make_history(h);
  if (h.output.empty()) {
    std::ostringstream rows;
    rows.precision(17);
    contact::drive_cell(*law, history, params.a0, rows);
    std::cout << rows.str();
    return;
  }
  std::unique_ptr<store::AtomicFile> out;
  try {
    out = std::make_unique<store::AtomicFile>(h.output);
  } catch (const std::runtime_error& e) {
    throw contact::InputError("-o " + h.output + ": " + e.what());
  }
  const double W = contact::drive_cell(*law, history, params.a0, out->stream());
  out->commit();
  std::cout.precision(9);
  std::cout << history.size() - 1 << " steps, dissipated " << W << " J/m^2 -> " << h.output << "\n";
}

bool wants_help(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "-help" || std::string(argv[i]) == "-h") return true;
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (wants_help(argc, argv)) {
    print_help(std::cout);
    return 0;
  }
  try {
    run(options::OptionDatabase::from_argv(argc, argv));
  } catch (const contact::InputError& e) {
    std::cerr << "vibrotherm-contact: error: " << e.what() << std::endl;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vibrotherm-contact: internal error: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
