#include "vibrotherm/mesh/specimen.hpp"

#include "vibrotherm/mesh/memory_estimate.hpp"

#include "vibrotherm/mesh/box_specimen.hpp"
#include "vibrotherm/mesh/geometry_script.hpp"
#include "vibrotherm/mesh/mesh_file_3d.hpp"
#include "vibrotherm/mesh/plex/crack_split.hpp"
#include "vibrotherm/mesh/plex/distribute.hpp"
#include "vibrotherm/mesh/plex/lts_partition.hpp"
#include "vibrotherm/mesh/mesh_data.hpp"
#include "vibrotherm/mesh/plex/metis_partitioner.hpp"
#include "vibrotherm/mesh/plex_builder.hpp"
#include "vibrotherm/options/query/option_query.hpp"
#include "vibrotherm/util/errors.hpp"
#include "vibrotherm/util/root_task.hpp"

namespace vibrotherm::mesh {
namespace {

struct MeshLog {
  PetscLogStage stage;
  PetscLogEvent generate, heat_generate, build, split, distribute;
};

PetscErrorCode RegisterMeshLogging(MeshLog* log) {
  PetscFunctionBeginUser;
  PetscClassId id;
  PetscCall(PetscClassIdRegister("vibrotherm mesh", &id));
  PetscCall(PetscLogStageGetId("Mesh", &log->stage));
  if (log->stage < 0) PetscCall(PetscLogStageRegister("Mesh", &log->stage));
  PetscCall(PetscLogEventRegister("MeshGenerate", id, &log->generate));
  PetscCall(PetscLogEventRegister("MeshGenerateHeat", id, &log->heat_generate));
  PetscCall(PetscLogEventRegister("MeshBuildPlex", id, &log->build));
  PetscCall(PetscLogEventRegister("MeshSplitCracks", id, &log->split));
  PetscCall(PetscLogEventRegister("MeshDistribute", id, &log->distribute));
  PetscFunctionReturn(0);
}

/// Crack names and requested lengths on every rank (rank 0 read them).
PetscErrorCode ShareCrackNames(MPI_Comm comm, const MeshData& data, const SpecimenGeometry& geometry, bool from_file,
                               std::vector<CrackInfo>* cracks) {
  PetscFunctionBeginUser;
  int ncracks = static_cast<int>(data.crack_names.size());
  PetscCallMPI(MPI_Bcast(&ncracks, 1, MPI_INT, 0, comm));
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  cracks->assign(ncracks, CrackInfo{});
  for (int c = 0; c < ncracks; ++c) {
    char name[256] = "";
    if (rank == 0) PetscCall(PetscStrncpy(name, data.crack_names[c].c_str(), sizeof(name)));
    PetscCallMPI(MPI_Bcast(name, sizeof(name), MPI_CHAR, 0, comm));
    (*cracks)[c].name = name;
    if (!from_file) (*cracks)[c].requested_length = geometry.cracks[c].length;
  }
  PetscFunctionReturn(0);
}

/// Serial DMPlex with labels (crack faces numbered along each crack, tips).
PetscErrorCode BuildSerialPlex(MPI_Comm comm, const MeshData& data, const std::vector<std::string>& names,
                               PetscInt refinements, DM* dm) {
  PetscFunctionBeginUser;
  PetscCall(CreateSerialPlex(comm, data, dm));
  for (PetscInt r = 0; r < refinements; ++r) {
    DM fine;
    PetscCall(DMPlexSetRefinementUniform(*dm, PETSC_TRUE));
    PetscCall(DMRefine(*dm, comm, &fine));
    PetscCall(DMDestroy(dm));
    *dm = fine;
  }
  PetscCall(LabelCrackFacetsAndTips(*dm, names));
  PetscFunctionReturn(0);
}

/// Rank 0's geometry on every rank (a -mesh_file rectangle found on rank 0).
PetscErrorCode ShareGeometry(MPI_Comm comm, bool* usable, SpecimenGeometry* g) {
  PetscFunctionBeginUser;
  std::vector<double> flat = {*usable ? 1.0 : 0.0, g->width, g->height, g->h, g->h_crack, double(g->cracks.size())};
  for (const Crack& c : g->cracks) flat.insert(flat.end(), {c.x, c.y, c.length, c.angle_deg});
  int n = static_cast<int>(flat.size());
  PetscCallMPI(MPI_Bcast(&n, 1, MPI_INT, 0, comm));
  flat.resize(n);
  PetscCallMPI(MPI_Bcast(flat.data(), n, MPI_DOUBLE, 0, comm));
  *usable = flat[0] != 0.0;
  g->width = flat[1], g->height = flat[2], g->h = flat[3], g->h_crack = flat[4];
  g->cracks.resize(static_cast<std::size_t>(flat[5]));
  for (std::size_t c = 0; c < g->cracks.size(); ++c)
    g->cracks[c] = {flat[6 + 4 * c], flat[7 + 4 * c], flat[8 + 4 * c], flat[9 + 4 * c]};
  PetscFunctionReturn(0);
}

/// Meshing may take minutes (gmsh's recombination into quads grows faster than the
/// cells): said before it starts, with the cells to expect and the faster way.
PetscErrorCode AnnounceMeshing(MPI_Comm comm, const MeshSource& source, const SpecimenGeometry& geometry) {
  PetscFunctionBeginUser;
  if (source.from_file) {
    PetscCall(PetscPrintf(comm, "Meshing: reading %s\n", source.file.c_str()));
    PetscFunctionReturn(0);
  }
  const double cells = EstimateMemory(geometry, 0, 1, 1).wave_cells;
  constexpr double kLarge = 1e5;  // cells: gmsh then takes tens of seconds to minutes on one core
  PetscCall(PetscPrintf(comm, "Meshing with gmsh on rank 0: about %.2g wave cells, then the heat mesh%s\n", cells,
                        cells > kLarge && source.refinements == 0
                            ? " (a large mesh: minutes; meshing coarser and -dm_refine 1 is about 4x faster)"
                            : ""));
  PetscFunctionReturn(0);
}

/// A mesh file whose heat mesh cannot be graded to its cracks (ungraded: why, on
/// rank 0): the heat falls back to the wave mesh, far too coarse at the cracks.
/// Said loudly, with the cost and the ways out, unless -heat_mesh wave asked for it.
PetscErrorCode WarnUngradedHeatMesh(MPI_Comm comm, const std::string& file, const HeatMeshOptions& heat,
                                    const std::string& ungraded, double exchange_length) {
  PetscFunctionBeginUser;
  if (!heat.graded) PetscFunctionReturn(0);
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0)
    PetscCall(PetscPrintf(PETSC_COMM_SELF,
                          "vibrotherm: warning: -mesh_file %s: %s, so no heat mesh can be graded to its cracks: the heat "
                          "runs on the unsplit wave mesh, whose elements at a crack are far thicker than the %.2g m "
                          "layer friction heats in one exchange (crack temperatures tens of percent low early on: "
                          "-50 %% at 0.1 ms in the paper scene). Give -heat_mesh_file with a heat mesh graded to the "
                          "cracks, or -heat_mesh wave to accept this\n",
                          file.c_str(), ungraded.c_str(), exchange_length));
  PetscFunctionReturn(0);
}

/// The serial heat mesh, or null when the heat uses the unsplit wave mesh:
/// -heat_mesh_file; else generated and graded (a generated specimen, or a
/// mesh-file rectangle with straight cracks, its sinks kept from the file).
PetscErrorCode BuildHeatMesh(MPI_Comm comm, const MeshSource& source, const MeshData& wave_data,
                             const SpecimenGeometry& geometry, bool generate, const HeatMeshSizes& sizes,
                             const std::vector<std::string>& names, DM* heat, std::string* heat_source) {
  PetscFunctionBeginUser;
  *heat = nullptr;
  *heat_source = "wave";
  if (!source.heat_from_file && !(generate && sizes.graded)) PetscFunctionReturn(0);
  MeshData data;
  PetscCall(RunOnRoot(comm, [&] {
    if (source.heat_from_file) {
      data = read_mesh_file(source.heat_file);
      check_crack_lines(data, std::string("-heat_mesh_file ") + source.heat_file);
      check_cracks_apart(data, std::string("-heat_mesh_file ") + source.heat_file);
      if (data.crack_names != names)
        throw std::invalid_argument("-heat_mesh_file " + source.heat_file +
                                    ": its crack curves must be those of -mesh_file, in the same order");
    } else {
      data = generate_heat_mesh(geometry, sizes);
      if (source.from_file) keep_sinks_of(wave_data, &data);
      data.crack_names = names;
    }
  }));
  *heat_source = source.heat_from_file ? source.heat_file : "graded";
  PetscCall(BuildSerialPlex(comm, data, names, 0, heat));
  PetscFunctionReturn(0);
}

/// The 2D source: a generated rectangle (gmsh) or a 2D -mesh_file, as MeshData → the serial
/// wave DMPlex (refined by -dm_refine, labelled) in *serial; its heat mesh in s->heat when it has
/// its own (graded, or -heat_mesh_file).
PetscErrorCode CreatePlanarSpecimen(MPI_Comm comm, const SpecimenOptions& options, double exchange_length,
                                    const MeshLog& log, DM* serial, Specimen* s) {
  PetscFunctionBeginUser;
  const MeshSource& source = options.source;
  SpecimenGeometry geometry = source.from_file ? SpecimenGeometry{} : options.geometry;  // a file: read from it
  MeshData data;
  bool generate_heat = !source.from_file;
  PetscCall(AnnounceMeshing(comm, source, geometry));
  const double t0 = MPI_Wtime();
  std::string ungraded;  // why a mesh file's heat mesh cannot be generated (rank 0)
  PetscCall(RunOnRoot(comm, [&] {
    const std::string where = source.from_file ? std::string("-mesh_file ") + source.file : "generated mesh";
    data = source.from_file ? read_mesh_file(source.file) : generate_specimen_mesh(geometry);
    for (const std::string& note : data.notes)  // rank 0 only: RunOnRoot
      (void)PetscPrintf(PETSC_COMM_SELF, "vibrotherm: note: -mesh_crack_mirror: %s: its mesh is not mirror-symmetric across it\n", note.c_str());
    check_crack_lines(data, where);
    check_cracks_apart(data, where);
    if (source.from_file) generate_heat = rectangle_geometry(data, &geometry, &ungraded);
  }));
  if (source.from_file) PetscCall(ShareGeometry(comm, &generate_heat, &geometry));
  HeatMeshSizes heat_sizes;
  if (generate_heat) heat_sizes = HeatMeshSizesFor(options.heat, geometry, exchange_length);
  if (generate_heat && heat_sizes.graded) VibrothermCallCpp(comm, heat_sizes.validate());
  PetscCall(ShareCrackNames(comm, data, geometry, source.from_file, &s->cracks));
  if (!generate_heat && !source.heat_from_file && !s->cracks.empty())
    PetscCall(WarnUngradedHeatMesh(comm, source.file, options.heat, ungraded, exchange_length));
  s->source = source.from_file ? source.file : "generated";
  std::vector<std::string> names;
  for (const CrackInfo& c : s->cracks) names.push_back(c.name);

  PetscCall(PetscLogEventBegin(log.heat_generate, 0, 0, 0, 0));
  PetscCall(BuildHeatMesh(comm, source, data, geometry, generate_heat, heat_sizes, names, &s->heat, &s->heat_source));
  PetscCall(PetscLogEventEnd(log.heat_generate, 0, 0, 0, 0));
  PetscCall(PetscPrintf(comm, "Meshing: %.2f s\n", MPI_Wtime() - t0));
  PetscCall(PetscLogEventBegin(log.build, 0, 0, 0, 0));
  PetscCall(BuildSerialPlex(comm, data, names, source.refinements, serial));
  PetscCall(PetscLogEventEnd(log.build, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/// Every specimen's tail, 2D or 3D: the wave mesh (split serially, LTS-weighted) and the
/// heat mesh, each distributed by its own partition.
PetscErrorCode DistributeSpecimen(const MeshLog& log, const LtsWeighting& lts, Specimen* s) {
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(log.distribute, 0, 0, 0, 0));
  PetscCall(SetLtsPartitionWeights(s->wave, lts));
  PetscCall(DistributeMesh(&s->wave, "wave_mesh", &s->wave_origin));
  PetscCall(DistributeMesh(&s->heat, "heat_mesh", &s->heat_origin));
  PetscCall(PetscLogEventEnd(log.distribute, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode SpecimenCreate(MPI_Comm comm, const SpecimenOptions& options, double exchange_length, Specimen* s,
                              const LtsWeighting& lts) {
  PetscFunctionBeginUser;
  MeshLog log;
  PetscCall(RegisterMeshLogging(&log));
  PetscCall(RegisterMetisPartitioner());
  PetscCall(PetscLogStagePush(log.stage));
  // One source makes the serial wave mesh, unsplit, and its heat mesh (none: the wave mesh unsplit).
  const MeshSource& source = options.source;
  PetscCheck(!(source.from_file && IsGeometryScript(source.file)) && !(source.heat_from_file &&
             IsGeometryScript(source.heat_file)), comm, PETSC_ERR_ARG_WRONG,
             "SpecimenCreate reads mesh files: mesh a .geo first (MeshGeometryScripts)");
  int file_dimension = source.file_dimension;  // the scene opened the file once for it already
  if (source.from_file && !file_dimension) PetscCall(MeshFileDimension(comm, source.file, &file_dimension));
  DM serial = nullptr;
  PetscCall(PetscLogEventBegin(log.generate, 0, 0, 0, 0));
  if (file_dimension == 3)
    PetscCall(CreateMeshFileSpecimen3D(comm, source.file, source.heat_from_file ? source.heat_file : "", &serial, s));
  else if (!source.from_file && options.geometry.depth > 0.0)
    PetscCall(CreateBoxSpecimen(comm, options.geometry, HeatMeshSizesFor(options.heat, options.geometry, exchange_length),
                                &serial, s));
  else
    PetscCall(CreatePlanarSpecimen(comm, options, exchange_length, log, &serial, s));
  PetscCall(PetscLogEventEnd(log.generate, 0, 0, 0, 0));
  // Then one path for every specimen: split serially (the other order is broken in PETSc 3.18;
  // SplitCracks labels the front and checks one cohesive cell per crack face), distribute.
  PetscCall(PetscLogEventBegin(log.split, 0, 0, 0, 0));
  PetscCall(SplitCracks(serial, &s->wave));
  PetscCall(PetscLogEventEnd(log.split, 0, 0, 0, 0));
  if (s->heat) PetscCall(DMDestroy(&serial));
  else s->heat = serial;  // unsplit: temperature is continuous across the cracks
  PetscCall(DistributeSpecimen(log, lts, s));
  const PetscInt ncracks = static_cast<PetscInt>(s->cracks.size());
  PetscCall(s->wave_cracks.Setup(s->wave, ncracks));
  PetscCall(s->heat_cracks.Setup(s->heat, ncracks));
  PetscCall(PetscLogStagePop());
  PetscFunctionReturn(0);
}

PetscErrorCode CheckSpecimenMemory(MPI_Comm comm, const SpecimenOptions& options, PetscInt wave_degree,
                                   double exchange_length) {
  PetscFunctionBeginUser;
  const MeshSource& source = options.source;
  if (source.from_file) PetscFunctionReturn(0);  // its size is known only once read
  const SpecimenGeometry& geometry = options.geometry;
  PetscMPIInt ranks;
  PetscCallMPI(MPI_Comm_size(comm, &ranks));
  BoxGridSizes heat_grid{};
  if (geometry.depth > 0.0) {  // the 3D heat grid is known before meshing too
    heat_grid = BoxHeatGridSizes(geometry, HeatMeshSizesFor(options.heat, geometry, exchange_length));
  }
  const MemoryEstimate e = EstimateMemory(geometry, static_cast<int>(source.refinements), static_cast<int>(wave_degree),
                                          ranks, geometry.depth > 0.0 ? &heat_grid : nullptr);
  double available = AvailableMemory();
  PetscCallMPI(MPI_Bcast(&available, 1, MPI_DOUBLE, 0, comm));
  PetscCall(PetscPrintf(comm, "Memory estimate: %.3g wave cells, %.3g wave dofs, %.3g heat dofs: about %.3g GB (%.3g GB available)\n",
                        e.wave_cells, e.wave_dofs, e.heat_dofs, e.bytes / 1e9, available / 1e9));
  PetscCheck(source.force || available <= 0.0 || e.bytes <= 0.9 * available, comm, PETSC_ERR_USER_INPUT,
             "the scene needs about %.3g GB (%.3g wave cells, %.3g wave dofs), more than the %.3g GB available: coarsen "
             "-mesh_h or -mesh_h_crack, lower -dm_refine, or -force",
             e.bytes / 1e9, e.wave_cells, e.wave_dofs, available / 1e9);
  PetscFunctionReturn(0);
}

PetscErrorCode SpecimenDestroy(Specimen* s) {
  PetscFunctionBeginUser;
  PetscCall(DMDestroy(&s->wave));
  PetscCall(DMDestroy(&s->heat));
  s->cracks.clear();
  s->wave_cracks = CrackSurface{};
  s->heat_cracks = CrackSurface{};
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
