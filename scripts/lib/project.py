"""Shared by the Python scripts: the project root, the build (as scripts/run does it)
and the environment Open MPI needs to run as root."""
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD_DIR = os.environ.get("VIBROTHERM_BUILD_DIR", os.path.join(ROOT, "build"))


def build(*targets):
    """Installs the missing Debian packages and builds (scripts/lib/common.sh): the given
    CMake targets only (e.g. "vibrotherm"), or everything when none is given."""
    subprocess.run(["bash", "-c", 'source "%s/scripts/lib/common.sh"; install_dependencies; build_project "$@" >&2'
                    % ROOT, "build"] + list(targets), check=True, env=dict(os.environ, VIBROTHERM_BUILD_DIR=BUILD_DIR))


def mpi_env():
    return dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                OMPI_MCA_rmaps_base_oversubscribe="1")
