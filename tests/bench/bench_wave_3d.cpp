// The 3D wave operator against this machine's limit (issue 26: choose the operator by
// measurement). An explicit step is one product y = A x with the assembled elastic
// stiffness (3×3 blocks, BAIJ); in 3D its matrix no longer fits in cache, so the
// product streams the matrix from memory and its ceiling is the memory bandwidth:
//   ceiling [dof-updates/s] = STREAM triad bandwidth / bytes a product moves per dof
// (the matrix: 8 B per value and 4 B per block index, plus x read and y written).
// The triad runs on every rank at once (the ranks share the memory bus), on arrays
// far larger than the caches. Also printed: the matrix memory per 10⁶ dofs, which the
// 3D memory estimate uses.
//   mpiexec -n R bench_wave_3d -bench_cells N [-wave_degree D] [-bench_products P]
// The product is timed twice: PETSc's MatMult and the 3×3-block kernel the wave solver
// steps with (block_csr3.hpp).
// Prints one line: ranks degree dofs values_per_row bytes_per_dof matrix_GB_per_Mdof
// stream_GB_per_s ceiling_dof_per_s matmult_dof_per_s matmult_fraction kernel_dof_per_s
// kernel_fraction kernel_path
#include <petscdmplex.h>

#include <algorithm>
#include <cstdio>

#include "vibrotherm/fe/lagrange_space.hpp"
#include "vibrotherm/wave/block_kernel.hpp"
#include "vibrotherm/wave/elastic_operator.hpp"

using namespace vibrotherm;

/// A hex box of n³ cells on the unit cube, distributed.
static PetscErrorCode HexBox(MPI_Comm comm, PetscInt n, DM* dm) {
  PetscFunctionBeginUser;
  const PetscInt faces[3] = {n, n, n};
  PetscCall(DMPlexCreateBoxMesh(comm, 3, PETSC_FALSE, faces, nullptr, nullptr, nullptr, PETSC_TRUE, dm));
  DM distributed = nullptr;
  PetscCall(DMPlexDistribute(*dm, 0, nullptr, &distributed));
  if (distributed) {
    PetscCall(DMDestroy(dm));
    *dm = distributed;
  }
  PetscFunctionReturn(0);
}

/// Memory bandwidth of a = b + s c on every rank at once [bytes/s, summed over the ranks]: best of 5.
static PetscErrorCode TriadBandwidth(MPI_Comm comm, double* bandwidth) {
  PetscFunctionBeginUser;
  constexpr PetscInt kLength = 1 << 24;  // 128 MB per array, far beyond any cache
  Vec a, b, c;
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, kLength, &a));
  PetscCall(VecDuplicate(a, &b));
  PetscCall(VecDuplicate(a, &c));
  PetscCall(VecSet(b, 1.0));
  PetscCall(VecSet(c, 2.0));
  double best = 1e30;
  for (int k = 0; k < 5; ++k) {
    PetscCallMPI(MPI_Barrier(comm));
    const double t0 = MPI_Wtime();
    PetscCall(VecWAXPY(a, 0.5, c, b));
    const double t = MPI_Wtime() - t0;
    double slowest;
    PetscCallMPI(MPI_Allreduce(&t, &slowest, 1, MPI_DOUBLE, MPI_MAX, comm));
    best = std::min(best, slowest);
  }
  PetscMPIInt ranks;
  PetscCallMPI(MPI_Comm_size(comm, &ranks));
  *bandwidth = ranks * 3.0 * 8.0 * kLength / best;
  for (Vec* v : {&a, &b, &c}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(0);
}

/// Seconds per product y = K x (PETSc's MatMult, or the block kernel when given), best of 3 batches.
static PetscErrorCode TimeProducts(Mat K, const wave::BlockKernel* kernel, PetscInt products, double* seconds) {
  PetscFunctionBeginUser;
  Vec x, y;
  PetscCall(MatCreateVecs(K, &x, &y));
  PetscCall(VecSet(x, 1.0));
  const auto product = [&]() { return kernel ? kernel->Apply(x, y) : MatMult(K, x, y); };
  PetscCall(product());  // warm-up
  *seconds = 1e30;
  for (int batch = 0; batch < 3; ++batch) {
    PetscCallMPI(MPI_Barrier(PetscObjectComm((PetscObject)K)));
    const double t0 = MPI_Wtime();
    for (PetscInt k = 0; k < products; ++k) PetscCall(product());
    *seconds = std::min(*seconds, (MPI_Wtime() - t0) / products);
  }
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

static PetscErrorCode Run() {
  PetscFunctionBeginUser;
  MPI_Comm comm = PETSC_COMM_WORLD;
  PetscInt cells = 12, degree = 2, products = 20;
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-bench_cells", &cells, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-wave_degree", &degree, nullptr));
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-bench_products", &products, nullptr));
  DM dm;
  PetscCall(HexBox(comm, cells, &dm));
  fe::LagrangeSpace space;
  PetscCall(space.Setup(dm, static_cast<int>(degree), 3));
  wave::ElasticMaterial material;
  Mat K;
  Vec mass;
  PetscCall(wave::AssembleElasticOperators(space, material, &K, &mass));
  PetscInt dofs;
  MatInfo info;
  PetscCall(MatGetSize(K, &dofs, nullptr));
  PetscCall(MatGetInfo(K, MAT_GLOBAL_SUM, &info));
  const double values = info.nz_used, block_indices = values / 9.0;
  const double bytes_per_dof = (8.0 * values + 4.0 * block_indices) / dofs + 16.0;  // + x read, y written
  double seconds, kernel_seconds, stream;
  wave::BlockKernel kernel;
  PetscCall(kernel.Setup(K));
  PetscCall(TimeProducts(K, nullptr, products, &seconds));
  PetscCall(TimeProducts(K, &kernel, products, &kernel_seconds));
  PetscCall(TriadBandwidth(comm, &stream));
  const double rate = dofs / seconds, kernel_rate = dofs / kernel_seconds, ceiling = stream / bytes_per_dof;
  PetscMPIInt ranks;
  PetscCallMPI(MPI_Comm_size(comm, &ranks));
  PetscCall(PetscPrintf(comm, "ranks degree dofs values_per_row bytes_per_dof matrix_GB_per_Mdof stream_GB_per_s "
                              "ceiling_dof_per_s matmult_dof_per_s matmult_fraction kernel_dof_per_s kernel_fraction "
                              "kernel_path\n"));
  PetscCall(PetscPrintf(comm, "%d %" PetscInt_FMT " %" PetscInt_FMT " %.1f %.0f %.2f %.2f %.3g %.3g %.2f %.3g %.2f %s\n",
                        ranks, degree, dofs, values / dofs, bytes_per_dof, (bytes_per_dof - 16.0) * 1e6 / 1e9,
                        stream / 1e9, ceiling, rate, rate / ceiling, kernel_rate, kernel_rate / ceiling,
                        kernel.wide() ? "avx2" : "portable"));
  PetscCall(MatDestroy(&K));
  PetscCall(VecDestroy(&mass));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

int main(int argc, char** argv) {
  PetscCall(PetscInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(Run());
  PetscCall(PetscFinalize());
  return 0;
}
