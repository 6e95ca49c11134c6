// Uses PETSc's private partitioner interface (petsc/private/partitionerimpl.h):
// the only way to plug a partitioner into DMPlexDistribute by type name.
#include "vibrotherm/mesh/plex/metis_partitioner.hpp"

#include <metis.h>

#include <algorithm>
#include <petsc/private/partitionerimpl.h>

#include <vector>

static_assert(sizeof(idx_t) == sizeof(PetscInt), "METIS idx_t and PetscInt must have the same width");

namespace vibrotherm::mesh {
namespace {

struct MetisData {
  PetscInt seed = 0;
};

/// Vertex weights as METIS constraints: one constraint per distinct weight (up
/// to 8; each vertex counts 1 in its own), so that every class of equal weight
/// is balanced on its own — local time stepping's levels (lts_partition.hpp),
/// whose products wait for the slowest rank level by level. More classes: the
/// weights themselves, one constraint.
PetscErrorCode ClassWeights(PetscSection section, PetscInt nvtxs, idx_t* ncon, std::vector<idx_t>* vwgt) {
  PetscFunctionBeginUser;
  std::vector<PetscInt> weight(nvtxs), distinct;
  for (PetscInt v = 0; v < nvtxs; ++v) PetscCall(PetscSectionGetDof(section, v, &weight[v]));
  distinct = weight;
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() > 8) {
    *ncon = 1;
    vwgt->assign(weight.begin(), weight.end());
    PetscFunctionReturn(0);
  }
  *ncon = static_cast<idx_t>(distinct.size());
  vwgt->assign(static_cast<std::size_t>(nvtxs) * distinct.size(), 0);
  for (PetscInt v = 0; v < nvtxs; ++v) {
    const auto c = std::lower_bound(distinct.begin(), distinct.end(), weight[v]) - distinct.begin();
    (*vwgt)[static_cast<std::size_t>(v) * distinct.size() + c] = 1;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode PartitionMetis(PetscPartitioner part, PetscInt nparts, PetscInt nvtxs, PetscInt start[],
                              PetscInt adjacency[], PetscSection vertSection, PetscSection /*targetSection*/,
                              PetscSection partSection, IS* partition) {
  PetscFunctionBeginUser;
  MPI_Comm comm = PetscObjectComm((PetscObject)part);
  const auto* data = static_cast<const MetisData*>(part->data);
  PetscMPIInt holders = 0, has = nvtxs > 0;
  PetscCallMPI(MPI_Allreduce(&has, &holders, 1, MPI_INT, MPI_SUM, comm));
  PetscCheck(holders <= 1, comm, PETSC_ERR_SUP,
             "the metis partitioner partitions serial meshes only (cells found on %d ranks)", holders);
  std::vector<idx_t> assignment(nvtxs, 0);
  if (nvtxs > 0 && nparts > 1) {
    idx_t n = nvtxs, ncon = 1, np = nparts, edgecut = 0;
    std::vector<idx_t> vwgt;
    if (vertSection) PetscCall(ClassWeights(vertSection, nvtxs, &ncon, &vwgt));
    idx_t options[METIS_NOPTIONS];
    METIS_SetDefaultOptions(options);
    options[METIS_OPTION_SEED] = static_cast<idx_t>(data->seed);
    const int err = METIS_PartGraphKway(&n, &ncon, start, adjacency, vwgt.empty() ? nullptr : vwgt.data(), nullptr,
                                        nullptr, &np, nullptr, nullptr, options, &edgecut, assignment.data());
    PetscCheck(err == METIS_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "METIS_PartGraphKway failed with code %d", err);
    part->edgeCut = edgecut;
  }
  // Output convention of PETSc's partitioners: dofs per part, points grouped by part.
  for (PetscInt v = 0; v < nvtxs; ++v) PetscCall(PetscSectionAddDof(partSection, assignment[v], 1));
  PetscInt* points;
  PetscCall(PetscMalloc1(nvtxs, &points));
  PetscInt i = 0;
  for (PetscInt p = 0; p < nparts; ++p)
    for (PetscInt v = 0; v < nvtxs; ++v)
      if (assignment[v] == p) points[i++] = v;
  PetscCall(ISCreateGeneral(comm, nvtxs, points, PETSC_OWN_POINTER, partition));
  PetscFunctionReturn(0);
}

PetscErrorCode DestroyMetis(PetscPartitioner part) {
  PetscFunctionBeginUser;
  delete static_cast<MetisData*>(part->data);
  part->data = nullptr;
  PetscFunctionReturn(0);
}

PetscErrorCode ViewMetis(PetscPartitioner part, PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscBool ascii;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii) PetscCall(PetscViewerASCIIPrintf(viewer, "METIS k-way (serial graph), seed %" PetscInt_FMT "\n",
                                              static_cast<MetisData*>(part->data)->seed));
  PetscFunctionReturn(0);
}

PetscErrorCode SetFromOptionsMetis(PetscPartitioner part, PetscOptionItems* PetscOptionsObject) {
  PetscFunctionBeginUser;
  auto* data = static_cast<MetisData*>(part->data);
  PetscOptionsHeadBegin(PetscOptionsObject, "METIS partitioner options");
  PetscCall(PetscOptionsInt("-petscpartitioner_metis_seed", "METIS random seed", nullptr, data->seed, &data->seed,
                            nullptr));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}

PetscErrorCode CreateMetis(PetscPartitioner part) {
  PetscFunctionBeginUser;
  part->data = new MetisData();
  part->noGraph = PETSC_FALSE;
  part->ops->partition = PartitionMetis;
  part->ops->destroy = DestroyMetis;
  part->ops->view = ViewMetis;
  part->ops->setfromoptions = SetFromOptionsMetis;
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode RegisterMetisPartitioner() {
  PetscFunctionBeginUser;
  PetscCall(PetscPartitionerRegister("metis", CreateMetis));
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::mesh
