// Requirement: the CSV reader of the small input files never changes data —
// every bad row is a one-line error naming the file and the line, a header is
// recognised only by its column names, and good rows come back bit for bit.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "input_error_message.hpp"
#include "vibrotherm/contact/csv_rows.hpp"
#include "vibrotherm/contact/parameter_spec.hpp"

namespace vibrotherm::contact {
namespace {

// One file per test: ctest runs the tests of this file in parallel processes.
std::string test_path() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "csv_rows_" + test->name() + ".csv";
}

std::string write_file(const std::string& text) {
  std::ofstream(test_path(), std::ios::binary) << text;
  return test_path();
}

std::vector<CsvRow> read(const std::string& text) {
  return read_csv_rows(write_file(text), "-history", {"t", "a", "b"});
}

/// The error message for text, "" if it was accepted.
std::string error_of(const std::string& text) {
  return testing::input_error_message([&] { read(text); });
}

TEST(CsvRows, GoodRowsComeBackExactly) {
  const auto rows = read("# comment\nt,a,b\n\n0,1e-09,-2.5e-9\n  1.5 , .5 ,+3E2\r\n2,0,0\n");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].line, 4);
  EXPECT_EQ(rows[0].values, (std::vector<double>{0.0, 1e-9, -2.5e-9}));
  EXPECT_EQ(rows[1].values, (std::vector<double>{1.5, 0.5, 300.0}));
  EXPECT_EQ(rows[2].line, 6);
  // The shortest round-trip text of a double reads back to the same double.
  const double x = 0.1 + 0.2;
  char text[96];
  std::snprintf(text, sizeof(text), "%.17g,%.17g,%.17g\n", x, -x / 3, 1e-300);
  const auto exact = read(text);
  EXPECT_EQ(exact[0].values, (std::vector<double>{x, -x / 3, 1e-300}));
}

TEST(CsvRows, HeaderIsRecognisedByItsColumnNames) {
  EXPECT_EQ(read("T, A ,B\n0,0,0\n").size(), 1u);  // names, case and spaces aside
  EXPECT_EQ(read("\xEF\xBB\xBFt,a,b\n0,0,0\n").size(), 1u);  // spreadsheet byte-order mark
  EXPECT_EQ(read("0,0,0\n").size(), 1u);           // no header at all
  // A first data row that does not parse is an error, never a dropped header.
  EXPECT_EQ(error_of("nan,1,2\n0,0,0\n"), "-history " + test_path() + " line 1: field 1 (t): expected a number, got 'nan'");
  EXPECT_NE(error_of("time,a,b\n0,0,0\n").find("line 1: field 1 (t): expected a number, got 'time'"), std::string::npos);
  // Only the first row may be the header.
  EXPECT_NE(error_of("0,0,0\nt,a,b\n").find("line 2: field 1 (t)"), std::string::npos);
  EXPECT_NE(error_of("t,a,b\nt,a,b\n").find("line 2"), std::string::npos);
}

TEST(CsvRows, EveryBadRowIsAnErrorNamingFileAndLine) {
  const std::string path = test_path();
  struct Case {
    const char* text;
    const char* message;  // after "-history <path> "
  };
  const Case cases[] = {
      {"t,a,b\n0,1,5e-9,2\n", "line 2: expected 3 fields t,a,b, got 4 (a decimal comma?)"},  // decimal comma
      {"0,1,2\n1,1e-09xyz,2\n", "line 2: field 2 (a): expected a number, got '1e-09xyz'"},  // trailing text
      {"0,1\n", "line 1: expected 3 fields t,a,b, got 2"},                                   // missing column
      {"0,1,2,\n", "line 1: expected 3 fields t,a,b, got 4 (a decimal comma?)"},           // trailing comma
      {"0,,2\n", "line 1: field 2 (a): expected a number, got nothing"},                    // empty field
      {"0 1 2\n", "line 1: expected 3 fields t,a,b, got 1"},                                // not comma-separated
      {"0;1;2\n", "line 1: expected 3 fields t,a,b, got 1"},                                // semicolons
      {"0,inf,2\n", "line 1: field 2 (a): expected a number, got 'inf'"},                  // non-finite
      {"0,1,-nan\n", "line 1: field 3 (b): expected a number, got '-nan'"},
      {"0,1e999,2\n", "line 1: field 2 (a): number out of the double range, got '1e999'"},  // overflows to inf
      {"0,0x10,2\n", "line 1: field 2 (a): expected a number, got '0x10'"},                // hex
      {"0,1,2 # note\n", "line 1: field 3 (b): expected a number, got '2 # note'"},        // no trailing comments
      {"0,\"1\",2\n", "line 1: field 2 (a): expected a number, got '\"1\"'"},              // quoted
  };
  for (const Case& c : cases) EXPECT_EQ(error_of(c.text), "-history " + path + " " + c.message) << c.text;
}

TEST(CsvRows, OnlyAHeaderAddsTheOptionalColumns) {
  auto read_b2 = [](const std::string& text) {
    return read_csv_rows(write_file(text), "-history", {"t", "a", "b"}, {"b2"});
  };
  const auto rows = read_b2("t,a,b,b2\n0,1,2,3\n");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].values, (std::vector<double>{0.0, 1.0, 2.0, 3.0}));
  EXPECT_EQ(read_b2("t,a,b\n0,1,2\n")[0].values.size(), 3u);
  EXPECT_EQ(read_b2("0,1,2\n")[0].values.size(), 3u);
  // Without the header a fourth field is a decimal comma, not b2.
  EXPECT_NE(testing::input_error_message([&] { read_b2("0,1,5e-9,2\n"); }).find("expected 3 fields t,a,b, got 4"),
            std::string::npos);
  EXPECT_NE(testing::input_error_message([&] { read_b2("t,a,b,b2\n0,1,2\n"); }).find("expected 4 fields t,a,b,b2"),
            std::string::npos);
}

TEST(CsvRows, MissingFileIsNamed) {
  try {
    read_csv_rows("/nonexistent/h.csv", "-history", {"t", "a", "b"});
    ADD_FAILURE() << "missing file accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "-history /nonexistent/h.csv: cannot open the file");
  }
}

}  // namespace
}  // namespace vibrotherm::contact
