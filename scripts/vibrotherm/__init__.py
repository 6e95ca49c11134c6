"""vibrotherm's results from Python: load a run, run a scene or a sweep, compare runs.

    import vibrotherm as vt

    run = vt.load("results/paper")                  # a run directory (vt.Run)
    run.value("dissipated_energy"), run.unit("dissipated_energy")    # 0.0047..., 'J/m'
    energy = run.energy()                           # energy.csv: pandas DataFrame, energy.attrs["units"]
    rise = run.field("heat", "temperature_rise")    # fields.h5: xarray DataArray (time, node), x, y coords
    frames = run.camera()                           # camera.h5: xarray Dataset (time, y, x)

    run = vt.run_scene("options/paper.opts", {"final_time": 2e-4}, output_dir="results/short", ranks=2)
    table = vt.sweep("options/paper.opts", vt.grid({"source_amplitude": [5e-8, 1e-7]}), "results/amp")
    vt.compare_summaries(run_a, run_b)              # the summary numbers that differ

Debian's python3 with python3-numpy, -h5py, -pandas, -xarray (and -matplotlib for the
plots). Importable after the set-up (scripts/run or scripts/test write vibrotherm.pth into
Python's site directory: scripts/lib/common.sh) or with PYTHONPATH=<repository>/scripts.
The README's "Results from Python" has an example."""
from .compare import compare_directories, compare_energy, compare_summaries
from .launch import RunFailed, option_words, run_scene
from .project import ROOT, build, executable, mpi_env
from .run_dir import MissingOutput, Run, load, summaries
from .sweep import SweepInterrupted, grid, sweep
from .units import STATES

__all__ = ["Run", "load", "summaries", "MissingOutput", "run_scene", "RunFailed", "option_words", "sweep", "grid",
           "SweepInterrupted", "compare_summaries", "compare_energy", "compare_directories", "build", "executable",
           "mpi_env", "ROOT", "STATES"]
