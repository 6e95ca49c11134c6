#include "vibrotherm/coupling/exchange/crack_heat_record.hpp"

#include "vibrotherm/io/h5_tables.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {

void CrackHeatRecord::Append(double t, const FrictionHeat& heat) {
  times_.push_back(t);
  densities_.insert(densities_.end(), heat.density().begin(), heat.density().end());
}

PetscErrorCode CrackHeatRecord::Write(MPI_Comm comm, const std::string& path, const FrictionHeat& heat) const {
  PetscFunctionBeginUser;
  PetscMPIInt rank, size;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const int owned = static_cast<int>(heat.density().size());
  std::vector<int> counts(size), displs(size, 0);
  PetscCallMPI(MPI_Allgather(&owned, 1, MPI_INT, counts.data(), 1, MPI_INT, comm));
  for (int r = 1; r < size; ++r) displs[r] = displs[r - 1] + counts[r - 1];
  const int cells = displs.back() + counts.back();
  const std::size_t n = times_.size();
  // Interval by interval: rank r's cells are columns [displs[r], displs[r] + counts[r]).
  std::vector<double> density(rank == 0 ? n * cells : 0);
  for (std::size_t k = 0; k < n; ++k)
    PetscCallMPI(MPI_Gatherv(densities_.data() + k * owned, owned, MPI_DOUBLE, rank == 0 ? &density[k * cells] : nullptr,
                             counts.data(), displs.data(), MPI_DOUBLE, 0, comm));
  if (rank != 0) PetscFunctionReturn(0);
  std::map<std::string, io::H5Table> tables;
  tables["time"] = {n, 1, times_, "s"};
  tables["density"] = {n, static_cast<std::size_t>(cells), density, "W/m^2"};
  io::H5Table& elements = tables["elements"];
  for (const CrackElement& e : heat.wave_elements())
    elements.values.insert(elements.values.end(), {double(e.crack), e.xi0, e.xi1, e.length, double(e.degree),
                                                   double(e.node[0]), double(e.node[1]), double(e.node[2])});
  elements.rows = heat.wave_elements().size();
  elements.cols = 8;
  io::H5Table& vertices = tables["vertices"];
  for (const auto& v : heat.crack_vertices()) vertices.values.insert(vertices.values.end(), v.begin(), v.end());
  vertices.rows = heat.crack_vertices().size();
  vertices.cols = 4;
  VibrothermCallIo(PETSC_COMM_SELF, io::WriteH5Tables(path, tables));
  PetscFunctionReturn(0);
}

void CrackHeatRecord::Save(store::Checkpoint& checkpoint, const std::vector<long long>& keys) const {
  checkpoint.PutShared("crack_heat/time", times_);
  const std::size_t cells = keys.size(), n = times_.size();
  std::vector<double> by_cell(cells * n);  // cell-major: a cell's history is one item
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < cells; ++i) by_cell[i * n + k] = densities_[k * cells + i];
  checkpoint.PutKeyed("crack_heat/density", keys, static_cast<int>(n), by_cell);
}

PetscErrorCode CrackHeatRecord::Restore(const store::Checkpoint& checkpoint, const std::vector<long long>& keys) {
  PetscFunctionBeginUser;
  PetscCall(checkpoint.GetShared("crack_heat/time", &times_));
  const std::size_t cells = keys.size(), n = times_.size();
  std::vector<double> by_cell;
  PetscCall(checkpoint.GetKeyed("crack_heat/density", keys, static_cast<int>(n), &by_cell));
  densities_.assign(cells * n, 0.0);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t i = 0; i < cells; ++i) densities_[k * cells + i] = by_cell[i * n + k];
  PetscFunctionReturn(0);
}

}  // namespace vibrotherm::coupling
