#include "vibrotherm/mesh/specimen.hpp"

#include "vibrotherm/mesh/crack_split.hpp"
#include "vibrotherm/mesh/mesh_data.hpp"
#include "vibrotherm/mesh/metis_partitioner.hpp"
#include "vibrotherm/mesh/plex_builder.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::mesh {
namespace {

struct MeshLog {
  PetscLogStage stage;
  PetscLogEvent generate, build, split, distribute;
};

PetscErrorCode RegisterMeshLogging(MeshLog* log) {
  PetscFunctionBeginUser;
  PetscClassId id;
  PetscCall(PetscClassIdRegister("vibrotherm mesh", &id));
  PetscCall(PetscLogStageGetId("Mesh", &log->stage));
  if (log->stage < 0) PetscCall(PetscLogStageRegister("Mesh", &log->stage));
  PetscCall(PetscLogEventRegister("MeshGenerate", id, &log->generate));
  PetscCall(PetscLogEventRegister("MeshBuildPlex", id, &log->build));
  PetscCall(PetscLogEventRegister("MeshSplitCracks", id, &log->split));
  PetscCall(PetscLogEventRegister("MeshDistribute", id, &log->distribute));
  PetscFunctionReturn(0);
}

/// Distributes dm in place with the partitioner chosen by the options.
PetscErrorCode Distribute(DM* dm, const char* name) {
  PetscFunctionBeginUser;
  PetscPartitioner part;
  PetscCall(DMPlexGetPartitioner(*dm, &part));
  PetscCall(PetscPartitionerSetFromOptions(part));
  DM distributed = nullptr;
  PetscCall(DMPlexDistribute(*dm, 0, nullptr, &distributed));
  if (distributed) {
    PetscCall(DMDestroy(dm));
    *dm = distributed;
  }
  PetscCall(PetscObjectSetName((PetscObject)*dm, name));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode SpecimenCreate(MPI_Comm comm, Specimen* s) {
  PetscFunctionBeginUser;
  MeshLog log;
  PetscCall(RegisterMeshLogging(&log));
  PetscCall(RegisterMetisPartitioner());
  PetscCall(PetscLogStagePush(log.stage));

  char file[PETSC_MAX_PATH_LEN] = "";
  PetscBool from_file = PETSC_FALSE;
  PetscInt refinements = 0;
  PetscOptionsBegin(comm, nullptr, "Specimen mesh", nullptr);
  PetscCall(PetscOptionsString("-mesh_file", "gmsh .msh file (physical curves: source, absorbing, free, roller, "
                               "fixed, sink, crack*); default: generate from -specimen_* and -crack_*",
                               nullptr, file, file, sizeof(file), &from_file));
  PetscCall(PetscOptionsBoundedInt("-dm_refine", "Uniform refinements of the mesh before splitting", nullptr,
                                   refinements, &refinements, nullptr, 0));
  PetscOptionsEnd();

  SpecimenGeometry geometry;
  if (!from_file) PetscCall(ReadSpecimenGeometry(comm, &geometry));
  MeshData data;
  PetscCall(PetscLogEventBegin(log.generate, 0, 0, 0, 0));
  PetscCall(RunOnRoot(comm, [&] {
    data = from_file ? read_mesh_file(file) : generate_specimen_mesh(geometry);
    check_crack_lines(data, from_file ? std::string("-mesh_file ") + file : std::string("generated mesh"));
  }));
  PetscCall(PetscLogEventEnd(log.generate, 0, 0, 0, 0));

  // Every rank needs the crack names (rank 0 knows them).
  int ncracks = static_cast<int>(data.crack_names.size());
  PetscCallMPI(MPI_Bcast(&ncracks, 1, MPI_INT, 0, comm));
  s->cracks.assign(ncracks, CrackInfo{});
  for (int c = 0; c < ncracks; ++c) {
    s->cracks[c].name = from_file ? "" : "crack" + std::to_string(c + 1);
    if (!from_file) s->cracks[c].requested_length = geometry.cracks[c].length;
  }
  if (from_file) {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(comm, &rank));
    for (int c = 0; c < ncracks; ++c) {
      char name[256] = "";
      if (rank == 0) PetscCall(PetscStrncpy(name, data.crack_names[c].c_str(), sizeof(name)));
      PetscCallMPI(MPI_Bcast(name, sizeof(name), MPI_CHAR, 0, comm));
      s->cracks[c].name = name;
    }
  }
  s->source = from_file ? file : "generated";
  std::vector<std::string> names;
  for (const CrackInfo& c : s->cracks) names.push_back(c.name);

  DM serial;
  PetscCall(PetscLogEventBegin(log.build, 0, 0, 0, 0));
  PetscCall(CreateSerialPlex(comm, data, &serial));
  data = MeshData{};  // free the arrays
  for (PetscInt r = 0; r < refinements; ++r) {
    DM fine;
    PetscCall(DMPlexSetRefinementUniform(serial, PETSC_TRUE));
    PetscCall(DMRefine(serial, comm, &fine));
    PetscCall(DMDestroy(&serial));
    serial = fine;
  }
  PetscCall(LabelCrackFacetsAndTips(serial, names));
  PetscCall(PetscLogEventEnd(log.build, 0, 0, 0, 0));

  PetscCall(PetscLogEventBegin(log.split, 0, 0, 0, 0));
  DM split;
  PetscCall(SplitCracks(serial, &split));
  PetscCall(PetscLogEventEnd(log.split, 0, 0, 0, 0));

  // Split serially, then distribute: the other order is broken in PETSc 3.18.
  PetscCall(PetscLogEventBegin(log.distribute, 0, 0, 0, 0));
  s->wave = split;
  s->heat = serial;
  PetscCall(Distribute(&s->wave, "wave_mesh"));
  PetscCall(Distribute(&s->heat, "heat_mesh"));
  PetscCall(PetscLogEventEnd(log.distribute, 0, 0, 0, 0));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode SpecimenDestroy(Specimen* s) {
  PetscFunctionBeginUser;
  PetscCall(DMDestroy(&s->wave));
  PetscCall(DMDestroy(&s->heat));
  s->cracks.clear();
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
