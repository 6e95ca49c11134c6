// summary.json: what ran, how big, how long (ARCHITECTURE.md "Outputs").
#pragma once

#include <petscsys.h>

#include <array>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "vibrotherm/io/source_power_log.hpp"
#include "vibrotherm/mesh/mesh_summary.hpp"

namespace vibrotherm::io {

/// One option of the run record: its effective value and where it came from.
struct OptionRecord {
  std::string name, value, source;  ///< source: "command line", "options file" or "default"
};

/// The IR camera's record (coupling/heat_camera): frames, the hottest frame, and the verdict
/// about the defect (coupling/observe/camera_verdict.hpp). Places are pixel centres in the
/// camera's axes (camera.h5 x, y).
struct CameraSummary {
  long long frames = 0, rows = 0, cols = 0, peak_frame = 0, defect_peak_frame = 0;
  double netd = 0.0, detect_snr = 0.0, detect_contrast = 0.0;
  std::string defect_share;  ///< whole (only the crack heats), partial, none (nothing heats at the crack)
  double peak_rise = 0.0;  ///< largest pixel of the noise-free frames, all heat [K]
  double peak_time = 0.0;  ///< centre of that frame's window [s]
  std::array<double, 2> peak_at{};  ///< that pixel [m]
  bool peak_on_defect = false;       ///< the defect makes at least half of that pixel's rise
  double total_peak_snr = 0.0;       ///< peak_rise / NETD (any heat)
  double defect_peak_rise = 0.0;     ///< the defect's own largest signal [K]
  double defect_peak_time = 0.0;     ///< centre of its frame [s]
  std::array<double, 2> defect_peak_at{};  ///< its pixel [m]
  double background_peak_rise = 0.0;  ///< the background's largest pixel in that frame [K]
  double peak_snr = 0.0;   ///< defect_peak_rise / NETD
  double contrast = 0.0;   ///< defect_peak_rise / background_peak_rise (+inf: no background)
  bool detectable = false; ///< a frame with snr >= -camera_detect_snr and contrast >= -camera_detect_contrast
  double detection_time = -1.0;  ///< end of the first such frame [s] (-1: none)
};

/// One periodic continuation (coupling/periodic_continuation): when the run was found periodic,
/// when the waves were suspended and resumed, and the periods continued.
struct PeriodicSegment {
  double detected = 0.0, suspended = 0.0, resumed = 0.0;  ///< [s]
  double period_multiple = 0.0;    ///< source periods in the period recorded and replayed
  double periods_continued = 0.0;  ///< source periods the waves did not simulate
  double change = 0.0;             ///< the detector's change when it was found periodic
  double drift = 0.0;              ///< the friction per period's relative change per source period then
  double projected = 0.0;          ///< half the drift over the periods continued: the frozen heat's error if it went on
};

/// The source's mean powers over a steady stretch's last periods (coupling/observe/source_power.hpp).
struct SourcePowerSummary {
  SourcePowerRow power;
  bool steady = true;  ///< false: the run's last periods, not in a steady state (a sweep, a short run)
};

/// The largest rise over every heat dof at every heat step, when and where.
struct FieldPeakSummary {
  bool known = false;
  double rise = 0.0, t = 0.0, x = 0.0, y = 0.0;  ///< [K], [s], [m]
  double z = 0.0;                                ///< 3D only [m]
  int dimension = 2;
};

struct RunSummary {
  std::string git_commit, date, host, command_line;
  /// True only for a run that reached its end (false: stopped by a signal, see checkpoint.h5).
  bool complete = false;
  std::string restarted_from;  ///< the checkpoint a restarted run continued from
  std::vector<std::string> warnings;  ///< where the run left the model's validity (strain, resolution, heating)
  std::vector<OptionRecord> option_values;  ///< every option the program declared
  std::map<std::string, double> derived;    ///< values the program chose (dt, intervals, sizes)
  std::map<std::string, std::string> derived_rules;  ///< how it chose them
  std::vector<std::string> physics_ran;   ///< "wave", "contact", "heat"
  long long dofs_wave = 0, dofs_heat = 0, contact_cells = 0, steps_wave = 0, steps_heat = 0;
  long long steps_heat_free = 0;  ///< heat steps after the waves stopped
  double wall_time_s = 0.0;
  double max_budget_error = 0.0;
  long long wave_dt_reductions = 0;  ///< times contact stiffening forced a smaller wave step
  double dissipated_energy = 0.0;     ///< [J/m]
  std::vector<double> dissipated_energy_by_crack;  ///< each crack's share [J/m] (3D: J)
  double wave_energy_left = 0.0;      ///< mechanical energy when the waves stopped [J/m]
  double work_thermal = 0.0;          ///< work of the two-way thermal stress on the waves when they stopped [J/m]
  double max_friction_excess = -1.0;  ///< max (|T| − μN)/(μN) over cells and steps (≤ 0 when Coulomb held)
  std::map<std::string, double> stages;   ///< phase → wall seconds
  /// Simulated interval [start, end] of each physics that ran (s).
  std::map<std::string, std::pair<double, double>> physics_time;
  double heat_deposited = 0.0, heat_content = 0.0, heat_boundary_loss = 0.0;  ///< [J/m] at the end
  std::map<std::string, double> heat_deposited_by;  ///< per heat source (friction, thermoelastic) [J/m]
  /// Probe index (as in probes.csv) → description, largest rise above T0 [K],
  /// and the rise at each output time.
  std::map<int, std::string> probe_labels;
  std::map<int, double> probe_max_temperature_rise;
  std::vector<std::pair<double, std::map<int, double>>> output_temperature_rise;
  FieldPeakSummary field_peak;  ///< summary.json field_max_temperature_rise(_at), when heat ran
  CameraSummary camera;         ///< summary.json camera, camera_peak_snr, camera_detectable (frames > 0)
  /// -modes: (frequency [Hz], defect participation) of each mode found.
  std::vector<std::pair<double, double>> modes;
  std::vector<PeriodicSegment> periodic;  ///< the periodic continuations (summary.json "periodic")
  /// Per steady stretch of the source, its last periods' powers (summary.json source_power; the last
  /// one also as input_power, friction_power, thermosonic_efficiency).
  std::vector<SourcePowerSummary> source_power;
  mesh::MeshSummary mesh;
};

/// Writes the summary (and the effective options) atomically from rank 0. Collective.
PetscErrorCode WriteRunSummary(MPI_Comm comm, const std::string& path, const RunSummary& summary);

}  // namespace vibrotherm::io
