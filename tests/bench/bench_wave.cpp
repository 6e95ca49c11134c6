// Wave stepping speed: DOF-updates per second (dofs × steps / wall time of the
// stepping loop, with the -wave_kernel of the options) next to bare products
// with the same A = −M⁻¹K in the same run: PETSc's MatMult and the 2×2-block kernel
// (AVX2 where the machine has it, and its portable path).
//   mpiexec -n R bench_wave -mesh_h H -dm_refine K -wave_degree D [-bench_steps N] [-wave_kernel K]
//                           [-bench_cpu_time]  (the process's CPU clock instead of the wall clock: on a
//                           shared machine steadier for 1 rank; on more, MPI's waits count as busy)
// Prints one line: ranks degree dofs steps_per_s dof_updates_per_s matmult_rate ratio blocked_rate
// blocked_over_matmult portable_over_matmult (rates in dof-updates per second, ratio = stepping / MatMult).
#include <slepcsys.h>

#include <algorithm>
#include <cmath>
#include <ctime>

#include "vibrotherm/coupling/run/scene.hpp"
#include "vibrotherm/mesh/specimen.hpp"
#include "vibrotherm/wave/block_kernel.hpp"
#include "vibrotherm/wave/wave_solver.hpp"

using namespace vibrotherm;

/// Seconds by the wall clock, or by this process's CPU clock.
static double Now(bool cpu_time) {
  if (!cpu_time) return MPI_Wtime();
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static PetscErrorCode Run() {
  PetscFunctionBeginUser;
  MPI_Comm comm = PETSC_COMM_WORLD;
  PetscInt steps = 200;
  PetscBool cpu_time = PETSC_FALSE;
  PetscCall(PetscOptionsGetInt(nullptr, nullptr, "-bench_steps", &steps, nullptr));
  PetscCall(PetscOptionsGetBool(nullptr, nullptr, "-bench_cpu_time", &cpu_time, nullptr));
  mesh::Specimen specimen;
  coupling::Scene scene;
  PetscCall(coupling::ReadScene(comm, &scene));
  const mesh::LtsWeighting lts{scene.wave.lts.on, scene.wave.lts.max_levels, scene.wave.lts.wiggle};
  PetscCall(mesh::SpecimenCreate(comm, scene.specimen, scene.exchange_length(), &specimen, lts));
  wave::ElasticMaterial material;
  wave::Excitation excitation;
  wave::WaveOptions options;
  PetscCall(wave::ReadElasticMaterial(comm, &material));
  PetscCall(wave::ReadExcitation(comm, &excitation));
  PetscCall(wave::ReadWaveOptions(comm, &options));
  wave::WaveSolver solver;
  PetscCall(solver.Setup(specimen.wave, material, excitation, options));
  PetscCall(solver.AdvanceSteps(10));  // warm up
  Vec x, y;
  PetscCall(MatCreateVecs(solver.op().stepping(), &x, &y));
  PetscCall(VecSet(x, 1.0));
  PetscCall(MatMult(solver.op().stepping(), x, y));
  wave::BlockKernel kernel, portable;
  PetscCall(kernel.Setup(solver.op().stepping()));
  PetscCall(portable.Setup(solver.op().stepping(), false));
  PetscCall(kernel.Apply(x, y));
  PetscCall(portable.Apply(x, y));
  // Alternate the measurements and keep the best of five: the machine is shared.
  double wave_time = INFINITY, matmult_time = INFINITY, blocked_time = INFINITY, portable_time = INFINITY;
  for (int rep = 0; rep < 5; ++rep) {
    PetscCallMPI(MPI_Barrier(comm));
    double t0 = Now(cpu_time);
    PetscCall(solver.AdvanceSteps(steps));
    PetscCallMPI(MPI_Barrier(comm));
    wave_time = std::min(wave_time, Now(cpu_time) - t0);
    t0 = Now(cpu_time);
    for (PetscInt k = 0; k < steps; ++k) PetscCall(MatMult(solver.op().stepping(), x, y));
    PetscCallMPI(MPI_Barrier(comm));
    matmult_time = std::min(matmult_time, Now(cpu_time) - t0);
    t0 = Now(cpu_time);
    for (PetscInt k = 0; k < steps; ++k) PetscCall(kernel.Apply(x, y));
    PetscCallMPI(MPI_Barrier(comm));
    blocked_time = std::min(blocked_time, Now(cpu_time) - t0);
    t0 = Now(cpu_time);
    for (PetscInt k = 0; k < steps; ++k) PetscCall(portable.Apply(x, y));
    PetscCallMPI(MPI_Barrier(comm));
    portable_time = std::min(portable_time, Now(cpu_time) - t0);
  }
  PetscMPIInt size;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  const double dofs = solver.op().dofs(), wave_rate = dofs * steps / wave_time, mm_rate = dofs * steps / matmult_time;
  const double blocked_rate = dofs * steps / blocked_time;
  PetscCall(PetscPrintf(comm, "%d %" PetscInt_FMT " %.0f %.4g %.4g %.4g %.3f %.4g %.3f %.3f\n", size, options.degree,
                        dofs, steps / wave_time, wave_rate, mm_rate, wave_rate / mm_rate, blocked_rate,
                        blocked_rate / mm_rate, matmult_time / portable_time));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y));
  PetscCall(mesh::SpecimenDestroy(&specimen));
  PetscFunctionReturn(0);
}

int main(int argc, char** argv) {
  PetscCall(SlepcInitialize(&argc, &argv, nullptr, nullptr));
  PetscCall(Run());
  PetscCall(SlepcFinalize());
  return 0;
}
