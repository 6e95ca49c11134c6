// Requirement: vibrotherm-contact's PETSc-free option reader reads argv and
// option files with PETSc's syntax, parses numbers strictly, checks each value
// against its declaration, refuses unknown and retired names (suggesting the
// nearest known one), and reports each problem in one line naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "input_error_message.hpp"
#include "vibrotherm/contact/contact_parameter_list.hpp"
#include "vibrotherm/options/declared_options.hpp"

namespace vibrotherm::options {
namespace {

using contact::ContactParameters;
using contact::InputError;

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

/// Reads the contact options of args into a ContactParameters.
ContactParameters read(const std::vector<std::string>& args) {
  const OptionDatabase db(args);
  std::vector<std::string> known = {"-options_file"};
  append_names(known, contact::contact_parameters());
  reject_unknown(db, known, contact::renamed_contact_options());
  ContactParameters p;
  read_parameters(db, contact::contact_parameters(), p);
  return p;
}

std::string error_of(const std::vector<std::string>& args) {
  return contact::testing::input_error_message([&] { read(args); });
}

TEST(OptionReader, ValuesAndFlagsLikePetsc) {
  const OptionDatabase db({"-a", "-1e-9", "-flag", "-b", "x", "-c", "-.5", "-d", "-nan", "-a", "2"});
  EXPECT_EQ(db.value("-a"), "2");  // the last occurrence wins
  EXPECT_EQ(db.value("-flag"), "");
  EXPECT_EQ(db.value("-b"), "x");
  EXPECT_EQ(db.value("-c"), "-.5");
  EXPECT_EQ(db.value("-d"), "-nan");  // a value (refused later), not an option
  EXPECT_FALSE(db.value("-e").has_value());
  EXPECT_EQ(db.names(), (std::vector<std::string>{"-a", "-flag", "-b", "-c", "-d"}));
  EXPECT_THROW(OptionDatabase({"stray"}), InputError);
}

TEST(OptionReader, OptionsFilesInsertAtTheirPlaceAndNest) {
  const std::string inner = write_file("inner.opts", "# comment\n-contact_mu 0.25   # trailing comment\n\n-contact_a0 1e-9\n");
  const std::string outer =
      write_file("outer.opts", "-options_file " + inner + "\n-contact_mu 0.5\n-crack_law coulomb\n");
  ContactParameters p = read({"-contact_mu", "9", "-options_file", outer});
  EXPECT_EQ(p.mu, 0.5);
  EXPECT_EQ(p.a0, 1e-9);
  EXPECT_EQ(p.crack_law, "coulomb");
  p = read({"-options_file", outer, "-contact_mu", "0.75"});
  EXPECT_EQ(p.mu, 0.75);
  const std::string self = ::testing::TempDir() + "self.opts";
  write_file("self.opts", "-options_file " + self + "\n");
  EXPECT_NE(error_of({"-options_file", self}).find("nested more than 8 deep"), std::string::npos);
  EXPECT_EQ(error_of({"-options_file", "/nonexistent.opts"}), "-options_file /nonexistent.opts: cannot open the file");
  const std::string bad = write_file("bad.opts", "-contact_mu 1 2\n");
  EXPECT_EQ(error_of({"-options_file", bad}),
            "-options_file " + bad + " line 1: expected '-name value' or '-name', got '-contact_mu 1 2'");
  EXPECT_EQ(error_of({"-options_file"}), "-options_file: needs a file name");
}

// Issue 43: a file's includes are found beside it, not in the directory one runs from (scripts/run
// from elsewhere, options/thermosonic.opts including paper.opts), and an error inside an include
// names the including file and line.
TEST(OptionReader, IncludesAreRelativeToTheIncludingFile) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(::testing::TempDir()) / "includes";
  fs::create_directories(dir / "scenes");
  std::ofstream(dir / "base.opts") << "-contact_mu 0.25\n";
  std::ofstream(dir / "scenes" / "plate.opts") << "# the shared base, one directory up\n-options_file ../base.opts\n";
  const std::vector<std::string> tokens = expand_options_files({"-options_file", (dir / "scenes" / "plate.opts").string(), "-x", "1"});
  EXPECT_EQ(tokens, (std::vector<std::string>{"-contact_mu", "0.25", "-x", "1"}));
  std::ofstream(dir / "scenes" / "broken.opts") << "-contact_mu 0.5\n-options_file missing.opts\n";
  const std::string broken = (dir / "scenes" / "broken.opts").string();
  EXPECT_EQ(options_file_error({"-options_file", broken}),
            "-options_file " + broken + " line 2: -options_file " + (dir / "scenes" / "missing.opts").string() +
                ": cannot open the file");
  // Files written when includes were relative to the working directory still read from there.
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  std::ofstream(dir / "scenes" / "old_style.opts") << "-options_file base.opts\n";
  EXPECT_EQ(expand_options_files({"-options_file", "scenes/old_style.opts"}),
            (std::vector<std::string>{"-contact_mu", "0.25"}));
  fs::current_path(before);
}

TEST(OptionReader, DefaultsAreTheDeclaredValues) {
  const ContactParameters p = read({});
  EXPECT_EQ(p.crack_law, "mmd");
  EXPECT_EQ(p.normal_law, "biwa");
  EXPECT_EQ(p.biwa_C, 1e11);
  EXPECT_EQ(p.biwa_m, 0.5);
  EXPECT_EQ(p.nu, 0.33);
  EXPECT_EQ(p.mmd_max_breakpoints, 1024);
}

TEST(OptionReader, BadValuesAreOneLineNamingTheOption) {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const Case cases[] = {
      {{"-contact_mu", "abc"}, "-contact_mu: expected a number, got 'abc'"},
      {{"-contact_mu", "1,5"}, "-contact_mu: expected a number, got '1,5'"},
      {{"-contact_mu", "1e-9xyz"}, "-contact_mu: expected a number, got '1e-9xyz'"},
      {{"-contact_mu", "nan"}, "-contact_mu: expected a number, got 'nan'"},
      {{"-contact_mu", "-inf"}, "-contact_mu: expected a number, got '-inf'"},
      {{"-contact_mu", "1e400"}, "-contact_mu: number out of the double range, got '1e400'"},
      {{"-contact_mu"}, "-contact_mu: needs a value"},
      {{"-contact_mu", "-0.5"}, "-contact_mu must be >= 0, got -0.5"},
      {{"-contact_power_C", "-1e11"}, "-contact_power_C must be > 0, got -1e+11"},
      {{"-contact_biwa_C", "0"}, "-contact_biwa_C must be > 0, got 0"},
      {{"-contact_biwa_m", "1"}, "-contact_biwa_m must be in (0, 0.9], got 1"},
      {{"-contact_power_p", "0.5"}, "-contact_power_p must be in [1, 10], got 0.5"},
      {{"-contact_linear_k", "-1"}, "-contact_linear_k must be > 0, got -1"},
      {{"-material_nu", "0.5"}, "-material_nu must be in (-1, 0.5), got 0.5"},
      {{"-crack_mmd_tol", "0"}, "-crack_mmd_tol must be in (0, 0.01), got 0"},
      {{"-crack_mmd_max_breakpoints", "2"}, "-crack_mmd_max_breakpoints must be in [3, 1e+07], got 2"},
      {{"-crack_mmd_max_breakpoints", "2.5"}, "-crack_mmd_max_breakpoints: expected an integer, got '2.5'"},
      {{"-crack_mmd_max_breakpoints", "99999999999"}, "-crack_mmd_max_breakpoints: integer out of range, got '99999999999'"},
      {{"-crack_law", "glue"}, "-crack_law: unknown value 'glue' (known: open|linear|clapping|coulomb|mmd)"},
      {{"-contact_normal_law", "cubic"}, "-contact_normal_law: unknown value 'cubic' (known: power|biwa|linear|table)"},
  };
  for (const Case& c : cases) EXPECT_EQ(error_of(c.args), c.message) << c.args[0];
}

TEST(OptionReader, UnknownOptionsSuggestTheNearestName) {
  EXPECT_EQ(error_of({"-contact_muu", "1"}), "unknown option -contact_muu; did you mean -contact_mu?");
  EXPECT_EQ(error_of({"-contact_biwa_c", "1"}), "unknown option -contact_biwa_c; did you mean -contact_biwa_C?");
  EXPECT_EQ(error_of({"-crack_mmd_toll", "1"}), "unknown option -crack_mmd_toll; did you mean -crack_mmd_tol?");
  EXPECT_EQ(error_of({"-zzz"}), "unknown option -zzz (-help lists the options)");
}

TEST(OptionReader, RetiredNamesTellTheirReplacement) {
  EXPECT_EQ(error_of({"-contact_normal_C", "1e11"}),
            "-contact_normal_C was renamed: use -contact_power_C (power law) or -contact_biwa_C (biwa law)");
  EXPECT_EQ(error_of({"-contact_normal_m", "0.5"}), "-contact_normal_m was renamed: use -contact_biwa_m");
  EXPECT_EQ(error_of({"-contact_normal_p", "2"}), "-contact_normal_p was renamed: use -contact_power_p");
  EXPECT_EQ(error_of({"-contact_normal_table", "t.csv"}), "-contact_normal_table was renamed: use -contact_table_file");
  EXPECT_NE(error_of({"-contact_normal_k", "1"}).find("-contact_linear_k"), std::string::npos);
  EXPECT_EQ(error_of({"-contact_nu", "0.3"}), "-contact_nu was renamed: use -material_nu (the material's Poisson ratio)");
}

TEST(OptionReader, RangesSayTheirEnds) {
  // Each named interval holds its closed ends and not its open ones, and says so in its rule.
  using contact::Range;
  const struct {
    Range range;
    bool lo, hi;
    const char* rule;
  } cases[] = {{Range::between(0, 1), true, true, "must be in [0, 1]"},
               {Range::open(0, 1), false, false, "must be in (0, 1)"},
               {Range::closed_open(0, 1), true, false, "must be in [0, 1)"},
               {Range::open_closed(0, 1), false, true, "must be in (0, 1]"}};
  for (const auto& c : cases) {
    EXPECT_EQ(c.range.contains(0.0), c.lo) << c.rule;
    EXPECT_EQ(c.range.contains(1.0), c.hi) << c.rule;
    EXPECT_TRUE(c.range.contains(0.5)) << c.rule;
    EXPECT_FALSE(c.range.contains(NAN)) << c.rule;
    EXPECT_EQ(c.range.rule(), c.rule);
  }
}

TEST(OptionReader, EditDistance) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("-a", ""), 2u);
  EXPECT_EQ(nearest_name("-hlep", {"-help", "-o"}), "-help");
  EXPECT_EQ(nearest_name("-x", {"-contact_mu"}), "");
}

}  // namespace
}  // namespace vibrotherm::options
