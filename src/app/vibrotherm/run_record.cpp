#include "run_record.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>

#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/version.hpp"

namespace vibrotherm::app {
namespace {

/// A PETSc object's default as its help printed it; PETSc prints some array options without a
/// default from uninitialised memory (-wave_ts_time_span <6.9e-310>): a subnormal number is
/// such garbage, recorded as "unset".
std::string RecordedDefault(const std::string& value) {
  char* end = nullptr;
  const double x = std::strtod(value.c_str(), &end);
  const bool number = end && *end == '\0' && !value.empty();
  return number && x != 0.0 && std::fpclassify(x) == FP_SUBNORMAL ? "unset" : value;
}

}  // namespace

OptionValues RecordedOptions(const OptionRegistry& registry, const OptionValues& read,
                             const std::vector<DeclaredOption>& captured) {
  const std::vector<std::string> ours = registry.names();
  OptionValues recorded;
  for (const std::string& name : ours) {
    const auto it = read.find(name);
    if (it != read.end()) recorded.emplace(name, it->second);
  }
  for (const DeclaredOption& d : captured)
    if (!std::binary_search(ours.begin(), ours.end(), d.name)) recorded.emplace(d.name, d.value);
  return recorded;
}

std::vector<io::OptionRecord> OptionRecords(const std::vector<std::string>& command_line,
                                            const OptionValues& recorded) {
  std::vector<io::OptionRecord> records;
  for (const auto& [name, value] : recorded) {
    bool given = false;
    (void)OptionGiven(nullptr, name.c_str(), &given);
    const bool typed = std::find(command_line.begin(), command_line.end(), name) != command_line.end();
    records.push_back({name, given ? value : RecordedDefault(value),
                       typed ? "command line" : given ? "options file" : "default"});
  }
  return records;
}

void RecordRun(const std::vector<std::string>& command_line, const OptionValues& recorded,
               const coupling::Scene& scene, io::RunSummary* summary) {
  summary->git_commit = git_commit();
  char host[256] = "";
  gethostname(host, sizeof(host) - 1);
  summary->host = host;
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  summary->date = date;
  for (const std::string& word : command_line) summary->command_line += (summary->command_line.empty() ? "" : " ") + word;
  summary->option_values = OptionRecords(command_line, recorded);
  summary->derived["final_time"] = scene.final_time;
  summary->derived_rules["final_time"] = scene.run.final_time > 0 ? "-final_time" : "the source duration";
  summary->derived["couple_dt"] = scene.couple_dt;
  summary->derived_rules["couple_dt"] = scene.run.couple_dt > 0 ? "-couple_dt" : "1/8 of the source period";
  summary->derived["heat_dt"] = scene.couple_dt / static_cast<double>(scene.run.heat_substeps);
  summary->derived_rules["heat_dt"] = "couple_dt / -heat_substeps, rounded to whole wave steps";
}

}  // namespace vibrotherm::app
