#include "vibrotherm/coupling/observe/field_peak.hpp"

#include <array>
#include <cstdio>
#include <string>
#include <vector>


namespace vibrotherm::coupling {

FieldPeak::~FieldPeak() {
  (void)VecDestroy(&x_);
  (void)VecDestroy(&y_);
}

PetscErrorCode FieldPeak::Setup(const fe::LagrangeSpace& space) {
  PetscFunctionBeginUser;
  DM dm = space.dm();
  std::vector<std::array<double, 2>> nodes;
  PetscCall(space.NodeCoordinates(&nodes));
  Vec local;
  PetscCall(DMGetLocalVector(dm, &local));
  PetscInt n;
  PetscCall(VecGetLocalSize(local, &n));
  PetscCheck(static_cast<std::size_t>(n) == nodes.size(), PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "field peak: %" PetscInt_FMT " local dofs for %zu nodes", n, nodes.size());
  for (int d = 0; d < 2; ++d) {
    Vec& global = d == 0 ? x_ : y_;
    PetscScalar* a;
    PetscCall(VecGetArray(local, &a));
    for (PetscInt i = 0; i < n; ++i) a[i] = nodes[i][d];
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
  PetscCall(VecGetOwnershipRange(x_, &first, &end));
  double place[2] = {0.0, 0.0};
  if (at >= first && at < end) {
    const PetscScalar *x, *y;
    PetscCall(VecGetArrayRead(x_, &x));
    PetscCall(VecGetArrayRead(y_, &y));
    place[0] = PetscRealPart(x[at - first]);
    place[1] = PetscRealPart(y[at - first]);
    PetscCall(VecRestoreArrayRead(x_, &x));
    PetscCall(VecRestoreArrayRead(y_, &y));
  }
  MPI_Comm comm = PetscObjectComm((PetscObject)x_);
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, place, 2, MPI_DOUBLE, MPI_SUM, comm));
  const bool crossed = rise > kConstantPropertyRise && !(peak_.known && peak_.rise > kConstantPropertyRise);
  peak_ = {true, rise, heat.time(), place[0], place[1]};
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
