#include "vibrotherm/coupling/observe/field_peak.hpp"

#include <array>
#include <cstdio>
#include <string>
#include <vector>


namespace vibrotherm::coupling {

FieldPeak::~FieldPeak() {
  for (Vec& v : axes_) (void)VecDestroy(&v);
}

PetscErrorCode FieldPeak::Setup(const fe::LagrangeSpace& space) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  dim_ = space.dim();
  std::vector<double> nodes;
  PetscCall(space.NodePositions(&nodes));
  Vec local;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscInt n;
  PetscCall(VecGetLocalSize(local, &n));
  PetscCheck(static_cast<std::size_t>(n) * dim_ == nodes.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "field peak: %" PetscInt_FMT " local dofs for %zu node coordinates", n, nodes.size());
  for (int d = 0; d < dim_; ++d) {
    Vec& global = axes_[d];
    PetscScalar* a;
    PetscCall(VecGetArray(local, &a));
    for (PetscInt i = 0; i < n; ++i) a[i] = nodes[dim_ * i + d];
    PetscCall(VecRestoreArray(local, &a));
    PetscCall(DMCreateGlobalVector(dm, &global));
    PetscCall(DMLocalToGlobal(dm, local, INSERT_VALUES, global));
  }
  PetscCall(DMRestoreLocalVector(dm, &local));
  PetscFunctionReturn(0);
}

PetscErrorCode FieldPeak::Update(const heat::HeatSolver& heat) {
  PetscFunctionBeginUser;
  PetscInt at;
  PetscReal rise;
  PetscCall(VecMax(heat.rise(), &at, &rise));
  if (peak_.known && rise <= peak_.rise) PetscFunctionReturn(0);
  PetscInt first, end;
  PetscCall(VecGetOwnershipRange(axes_[0], &first, &end));
  double place[3] = {0.0, 0.0, 0.0};
  for (int d = 0; d < dim_ && at >= first && at < end; ++d) {
    const PetscScalar* x;
    PetscCall(VecGetArrayRead(axes_[d], &x));
    place[d] = PetscRealPart(x[at - first]);
    PetscCall(VecRestoreArrayRead(axes_[d], &x));
  }
  MPI_Comm comm = PetscObjectComm((PetscObject)axes_[0]);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, place, 3, MPI_DOUBLE, MPI_SUM, comm));
  const bool crossed = rise > kConstantPropertyRise && !(peak_.known && peak_.rise > kConstantPropertyRise);
  peak_ = {true, rise, heat.time(), place[0], place[1], place[2], dim_};
  if (crossed)  // once: a restart past it knows from the restored peak
    PetscCall(PetscPrintf(comm, "vibrotherm: warning: %s\n", ValidityWarning().c_str()));
  PetscFunctionReturn(0);
}

std::string FieldPeak::ValidityWarning() const {
  char text[320];
  std::snprintf(text, sizeof(text),
                "the temperature rise reached %.3g K at t = %.4g s (x = %.4g m, y = %.4g m): the model keeps the "
                "material properties constant, which holds for rises up to about %g K",
                peak_.rise, peak_.t, peak_.x, peak_.y, kConstantPropertyRise);
  return text;
}

void FieldPeak::Summarise(io::RunSummary* summary) const {
  summary->field_peak = peak_;
  if (peak_.known && peak_.rise > kConstantPropertyRise) summary->warnings.push_back(ValidityWarning());
}

}  // namespace vibrotherm::coupling
