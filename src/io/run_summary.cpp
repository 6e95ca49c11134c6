#include "vibrotherm/io/run_summary.hpp"

#include "vibrotherm/io/atomic_file.hpp"
#include "vibrotherm/io/json_writer.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/util/version.hpp"

namespace vibrotherm::io {
namespace {

void WriteMesh(JsonWriter& json, const mesh::MeshSummary& m) {
  json.begin_object("mesh");
  json.value("source", m.source).value("cell_type", m.cell_type);
  json.value("cells", static_cast<long long>(m.cells)).value("vertices", static_cast<long long>(m.vertices));
  json.value("cohesive_cells", static_cast<long long>(m.cohesive_cells));
  json.value("heat_cells", static_cast<long long>(m.heat_cells));
  json.value("heat_vertices", static_cast<long long>(m.heat_vertices));
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
    json.end_object();
  }
  json.end_array();
  json.end_object();
}

}  // namespace

PetscErrorCode WriteRunSummary(MPI_Comm comm, const std::string& path, const RunSummary& s) {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  char* options = nullptr;
  PetscCall(PetscOptionsGetAll(nullptr, &options));  // collective
  if (rank == 0) {
    VibrothermCallCpp(PETSC_COMM_SELF, {
      AtomicFile file(path);
      JsonWriter json(file.stream());
      json.begin_object();
      json.value("version", version());
      json.begin_array("physics_ran");
      for (const std::string& p : s.physics_ran) json.value(nullptr, p);
      json.end_array();
      json.value("ranks", s.mesh.ranks).value("dofs_wave", s.dofs_wave).value("dofs_heat", s.dofs_heat);
      json.value("contact_cells", s.contact_cells).value("steps_wave", s.steps_wave).value("steps_heat", s.steps_heat);
      json.value("steps_heat_free", s.steps_heat_free);
      json.value("wall_time_s", s.wall_time_s).value("max_budget_error", s.max_budget_error);
      json.value("wave_dt_reductions", s.wave_dt_reductions);
      json.value("wave_energy_left", s.wave_energy_left);
      json.value("dissipated_energy", s.dissipated_energy).value("max_friction_excess", s.max_friction_excess);
      json.begin_object("physics_time");
      for (const auto& [name, span] : s.physics_time) {
        json.begin_array(name.c_str());
        json.value(nullptr, span.first).value(nullptr, span.second);
        json.end_array();
      }
      json.end_object();
      json.value("heat_deposited", s.heat_deposited).value("heat_content", s.heat_content);
      json.value("heat_boundary_loss", s.heat_boundary_loss);
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
      if (!s.modes.empty()) {
        json.begin_array("modes");
        for (const auto& [frequency, participation] : s.modes)
          json.begin_object().value("frequency", frequency).value("participation", participation).end_object();
        json.end_array();
      }
      json.begin_object("stages");
      for (const auto& [name, seconds] : s.stages) json.value(name.c_str(), seconds);
      json.end_object();
      WriteMesh(json, s.mesh);
      json.value("options", options ? options : "");
      json.end_object();
      file.commit();
    });
  }
  PetscCall(PetscFree(options));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::io
