#include "vibrotherm/io/run_summary.hpp"

#include <cmath>

#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/store/atomic_file.hpp"
#include "vibrotherm/io/json_writer.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/util/version.hpp"

namespace vibrotherm::io {
namespace {

/// The heat field's peak and the camera's record (each only when it ran).
void WriteHeatView(JsonWriter& json, const RunSummary& s) {
  if (s.field_peak.known) {
    json.value("field_max_temperature_rise", s.field_peak.rise);
    json.begin_object("field_max_temperature_rise_at");
    json.value("t", s.field_peak.t).value("x", s.field_peak.x).value("y", s.field_peak.y);
    if (s.field_peak.dimension == 3) json.value("z", s.field_peak.z);
    json.end_object();
  }
  const CameraSummary& c = s.camera;
  if (c.frames == 0) return;
  json.value("camera_peak_snr", c.peak_snr).value("camera_detectable", c.detectable);
  json.value("camera_detection_time", c.detection_time);
  json.value("camera_defect_contrast", c.contrast);  // null: no background heat at all
  json.begin_object("camera");
  json.value("frames", c.frames).value("rows", c.rows).value("cols", c.cols).value("netd", c.netd);
  json.value("peak_rise", c.peak_rise).value("peak_frame", c.peak_frame).value("peak_time", c.peak_time);
  json.begin_array("peak_at").value(nullptr, c.peak_at[0]).value(nullptr, c.peak_at[1]).end_array();
  json.value("peak_on_defect", c.peak_on_defect).value("total_peak_snr", c.total_peak_snr);
  json.value("defect_share", c.defect_share);
  json.value("defect_peak_rise", c.defect_peak_rise).value("defect_peak_frame", c.defect_peak_frame);
  json.value("defect_peak_time", c.defect_peak_time);
  json.begin_array("defect_peak_at").value(nullptr, c.defect_peak_at[0]).value(nullptr, c.defect_peak_at[1]).end_array();
  json.value("background_peak_rise", c.background_peak_rise);
  json.value("detect_snr", c.detect_snr).value("detect_contrast", c.detect_contrast);
  json.end_object();
}

void WriteMesh(JsonWriter& json, const mesh::MeshSummary& m) {
  json.begin_object("mesh");
  json.value("source", m.source).value("cell_type", m.cell_type);
  json.value("cells", static_cast<long long>(m.cells)).value("vertices", static_cast<long long>(m.vertices));
  json.value("cohesive_cells", static_cast<long long>(m.cohesive_cells));
  json.value("heat_cells", static_cast<long long>(m.heat_cells));
  json.value("heat_vertices", static_cast<long long>(m.heat_vertices));
  json.value("heat_source", m.heat_source).value("heat_h_min", m.heat_h_min).value("heat_h_max", m.heat_h_max);
  json.begin_array("heat_cells_per_rank");
  for (PetscInt n : m.heat_cells_per_rank) json.value(nullptr, static_cast<long long>(n));
  json.end_array();
  json.value("h_min", m.h_min).value("h_max", m.h_max);
  json.begin_array("cells_per_rank");
  for (PetscInt n : m.cells_per_rank) json.value(nullptr, static_cast<long long>(n));
  json.end_array();
  json.begin_array("cracks");
  for (const mesh::CrackSummary& c : m.cracks) {
    json.begin_object();
    json.value("name", c.name).value("facets", static_cast<long long>(c.facets));
    json.value("contact_node_pairs", static_cast<long long>(c.node_pairs));
    json.value("buried_tips", static_cast<long long>(c.tips));
    json.value("length", c.length).value("requested_length", c.requested_length);
    if (m.dimension == 3) json.value("area", c.area);
    if (c.breaks) {
      json.begin_array("breaks");
      for (const std::string& face : *c.breaks) json.value(nullptr, face);
      json.end_array();
    }
    json.end_object();
  }
  json.end_array();
  if (m.dimension == 3) json.value("source_area", m.source_area);
  json.end_object();
}

/// Every option with its value and source, the derived values, and the units of the keys.
void WriteRecord(JsonWriter& json, const RunSummary& s) {
  json.begin_object("option_values");
  for (const OptionRecord& o : s.option_values)
    json.begin_object(o.name.c_str()).value("value", o.value).value("source", o.source).end_object();
  json.end_object();
  json.begin_object("derived");
  for (const auto& [name, value] : s.derived) json.value(name.c_str(), value);
  json.end_object();
  json.begin_object("derived_rules");
  for (const auto& [name, rule] : s.derived_rules) json.value(name.c_str(), rule);
  json.end_object();
  const char* energy = s.mesh.dimension == 3 ? "J" : "J/m";  // 2D: per metre of depth
  const char* power = s.mesh.dimension == 3 ? "W" : "W/m";
  const std::pair<const char*, std::string> units[] = {
      {"wall_time_s", "s"}, {"stages", "s"}, {"physics_time", "s"}, {"dissipated_energy", energy},
      {"dissipated_energy_by_crack", energy},
      {"heat_deposited", energy}, {"heat_content", energy}, {"heat_boundary_loss", energy},
      {"wave_energy_left", energy}, {"work_thermal", energy},
      {"probe_max_temperature_rise", "K"}, {"output_temperature_rise", "K (t in s)"}, {"max_budget_error", "1"},
      {"max_friction_excess", "1"}, {"mesh.h_min", "m"}, {"mesh.h_max", "m"}, {"mesh.heat_h_min", "m"},
      {"mesh.heat_h_max", "m"}, {"mesh.cracks.length", "m"}, {"mesh.source_area", "m^2"}, {"derived.wave_dt", "s"},
      {"derived.wave_stable_dt", "s"},
      {"derived.couple_dt", "s"}, {"derived.heat_dt", "s"}, {"derived.final_time", "s"}, {"modes.frequency", "Hz"},
      {"field_max_temperature_rise", "K"}, {"field_max_temperature_rise_at", "t in s, x, y (and z in 3D) in m"},
      {"camera.peak_rise", "K"}, {"camera.netd", "K"}, {"camera.peak_time", "s"}, {"camera_peak_snr", "1"},
      {"camera.peak_at", "m (the camera's x, y)"}, {"camera.defect_peak_rise", "K"}, {"camera.defect_peak_time", "s"},
      {"camera.defect_peak_at", "m (the camera's x, y)"}, {"camera.background_peak_rise", "K"},
      {"camera_defect_contrast", "1"},
      {"input_power", power}, {"friction_power", power}, {"thermosonic_efficiency", "1"},
      {"source_power", std::string("t_start, t_end in s, frequency in Hz, amplitude in m (displacement) or Pa "
                                   "(traction), powers in ") + power}};
  json.begin_object("units");
  for (const auto& [key, unit] : units) json.value(key, unit);
  json.end_object();
}

/// The probes' labels and temperature extremes, and the rises at the output times.
void WriteProbeTemperatures(JsonWriter& json, const RunSummary& s) {
  json.begin_object("probe_labels");
  for (const auto& [k, label] : s.probe_labels) json.value(std::to_string(k).c_str(), label);
  json.end_object();
  json.begin_object("probe_max_temperature_rise");
  for (const auto& [k, rise] : s.probe_max_temperature_rise) json.value(std::to_string(k).c_str(), rise);
  json.end_object();
  json.begin_array("output_temperature_rise");
  for (const auto& [t, rises] : s.output_temperature_rise) {
    json.begin_object();
    json.value("t", t);
    for (const auto& [k, rise] : rises) json.value(std::to_string(k).c_str(), rise);
    json.end_object();
  }
  json.end_array();
}

/// The periodic continuation's segments (coupling/periodic_continuation.hpp).
void WritePeriodic(JsonWriter& json, const RunSummary& s) {
  json.begin_array("periodic");
  for (const PeriodicSegment& p : s.periodic)
    json.begin_object()
        .value("detected", p.detected)
        .value("suspended", p.suspended)
        .value("resumed", p.resumed)
        .value("period_multiple", p.period_multiple)
        .value("periods_continued", p.periods_continued)
        .value("change", p.change)
        .value("friction_drift", p.drift)
        .value("drift_projected", p.projected)
        .end_object();
  json.end_array();
}

/// The source's powers per steady stretch; the last stretch's at the top level.
void WriteSourcePower(JsonWriter& json, const RunSummary& s) {
  if (s.source_power.empty()) return;
  const SourcePowerRow& last = s.source_power.back().power;
  json.value("input_power", last.input).value("friction_power", last.friction);
  json.value("thermosonic_efficiency", last.input > 0.0 ? last.efficiency() : std::nan(""));
  json.begin_array("source_power");
  for (const SourcePowerSummary& p : s.source_power)
    json.begin_object()
        .value("t_start", p.power.t_start)
        .value("t_end", p.power.t_end)
        .value("periods", p.power.periods)
        .value("frequency", p.power.frequency)
        .value("amplitude", p.power.amplitude)
        .value("input_power", p.power.input)
        .value("friction_power", p.power.friction)
        .value("damping_power", p.power.damping)
        .value("radiated_power", p.power.radiated)
        .value("efficiency", p.power.input > 0.0 ? p.power.efficiency() : std::nan(""))
        .value("steady", p.steady)
        .end_object();
  json.end_array();
}

}  // namespace

PetscErrorCode WriteRunSummary(MPI_Comm comm, const std::string& path, const RunSummary& s) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  std::string options;
  PetscCall(AllOptions(&options));
  if (rank == 0) {
    VibrothermCallIo(PETSC_COMM_SELF, {
      store::AtomicFile file(path);
      JsonWriter json(file.stream());
      json.begin_object();
      json.value("version", version()).value("git_commit", s.git_commit).value("date", s.date);
      json.value("host", s.host).value("command_line", s.command_line);
      json.value("complete", s.complete);
      if (s.mesh.dimension == 3) json.value("dimension", s.mesh.dimension);  // 2D summaries keep their keys
      if (!s.restarted_from.empty()) json.value("restarted_from", s.restarted_from);
      json.begin_array("warnings");  // where the run left the model's validity (coupling/model_validity.hpp)
      for (const std::string& w : s.warnings) json.value(nullptr, w);
      json.end_array();
      json.begin_array("physics_ran");
      for (const std::string& p : s.physics_ran) json.value(nullptr, p);
      json.end_array();
      json.value("ranks", s.mesh.ranks).value("dofs_wave", s.dofs_wave).value("dofs_heat", s.dofs_heat);
      json.value("contact_cells", s.contact_cells).value("steps_wave", s.steps_wave).value("steps_heat", s.steps_heat);
      json.value("steps_heat_free", s.steps_heat_free);
      json.value("wall_time_s", s.wall_time_s).value("max_budget_error", s.max_budget_error);
      json.value("wave_dt_reductions", s.wave_dt_reductions);
      json.value("wave_energy_left", s.wave_energy_left).value("work_thermal", s.work_thermal);
      json.value("dissipated_energy", s.dissipated_energy).value("max_friction_excess", s.max_friction_excess);
      json.begin_array("dissipated_energy_by_crack");
      for (double w : s.dissipated_energy_by_crack) json.value(nullptr, w);
      json.end_array();
      json.begin_object("physics_time");
      for (const auto& [name, span] : s.physics_time) {
        json.begin_array(name.c_str());
        json.value(nullptr, span.first).value(nullptr, span.second);
        json.end_array();
      }
      json.end_object();
      json.value("heat_deposited", s.heat_deposited).value("heat_content", s.heat_content);
      json.value("heat_boundary_loss", s.heat_boundary_loss);
      json.begin_object("heat_deposited_by");
      for (const auto& [name, energy] : s.heat_deposited_by) json.value(name.c_str(), energy);
      json.end_object();
      WriteProbeTemperatures(json, s);
      WriteHeatView(json, s);
      if (!s.modes.empty()) {
        json.begin_array("modes");
        for (const auto& [frequency, participation] : s.modes)
          json.begin_object().value("frequency", frequency).value("participation", participation).end_object();
        json.end_array();
      }
      WritePeriodic(json, s);
      WriteSourcePower(json, s);
      json.begin_object("stages");
      for (const auto& [name, seconds] : s.stages) json.value(name.c_str(), seconds);
      json.end_object();
      WriteMesh(json, s.mesh);
      json.value("options", options);
      WriteRecord(json, s);
      json.end_object();
      file.commit();
    });
  }
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
