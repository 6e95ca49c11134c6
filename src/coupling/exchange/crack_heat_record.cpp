#include "vibrotherm/coupling/exchange/crack_heat_record.hpp"

#include "vibrotherm/io/h5_tables.hpp"
#include "vibrotherm/util/all_gather.hpp"
#include "vibrotherm/util/errors.hpp"

namespace vibrotherm::coupling {
namespace {

/// On rank 0, the n × cells table of every rank's n × owned densities (rank r's
/// cells are the columns after those of the ranks before it). Collective.
PetscErrorCode GatherDensities(MPI_Comm comm, const std::vector<double>& mine, std::size_t n, std::size_t owned,
                               std::vector<double>* density, std::size_t* cells) {
  PetscFunctionBeginUser;
  std::vector<double> blocks;  // rank by rank, each rank's n × owned
  std::vector<long long> owned_by_rank;
  PetscCall(util::GatherToRoot(comm, mine, &blocks));
  PetscCall(util::GatherToRoot(comm, std::vector<long long>{static_cast<long long>(owned)}, &owned_by_rank));
  *cells = 0;
  for (long long width : owned_by_rank) *cells += static_cast<std::size_t>(width);
  density->assign(n * *cells, 0.0);
  std::size_t block = 0, column = 0;
  for (long long width : owned_by_rank) {
    for (std::size_t k = 0; k < n; ++k)
      for (long long j = 0; j < width; ++j) (*density)[k * *cells + column + j] = blocks[block + k * width + j];
    block += n * width;
    column += width;
  }
  PetscFunctionReturn(0);
}

}  // namespace

void CrackHeatRecord::Append(double t, const FrictionHeat& heat) {
  times_.push_back(t);
  densities_.insert(densities_.end(), heat.density().begin(), heat.density().end());
}

PetscErrorCode CrackHeatRecord::Write(MPI_Comm comm, const std::string& path, const FrictionHeat& heat) const {
  PetscFunctionBeginUser;
  PetscMPIInt rank;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  const std::size_t n = times_.size();
  std::vector<double> density;
  std::size_t cells = 0;
  PetscCall(GatherDensities(comm, densities_, n, heat.density().size(), &density, &cells));
  std::vector<double> places;  // the columns' cells, rank by rank as the densities
  PetscCall(util::GatherToRoot(comm, heat.cell_places(), &places));
  if (rank != 0) PetscFunctionReturn(0);
  std::map<std::string, io::H5Table> tables;
  tables["time"] = {n, 1, times_, "s"};
  tables["density"] = {n, cells, density, "W/m^2"};
  tables["cells"] = {cells, 4, places, "x, y, z [m], weight (2D: tributary length [m]; 3D: area [m^2])"};
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
