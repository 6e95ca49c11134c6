"""Where the project is, how it is built (as scripts/run does it) and the environment
Open MPI needs to run as root."""
import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def build_dir():
    """The build directory: $VIBROTHERM_BUILD_DIR, else <repo>/build (scripts/lib/common.sh)."""
    return os.environ.get("VIBROTHERM_BUILD_DIR", os.path.join(ROOT, "build"))


BUILD_DIR = build_dir()


def executable(name="vibrotherm"):
    """The path of a built program; FileNotFoundError saying how to build it when it is missing."""
    path = os.path.join(build_dir(), name)
    if not os.access(path, os.X_OK):
        raise FileNotFoundError("%s is not built: run scripts/run or scripts/test (or vibrotherm.build()) first" % path)
    return path


def build(*targets):
    """Installs the missing Debian packages and builds (scripts/lib/common.sh): the given
    CMake targets only (e.g. "vibrotherm"), or everything when none is given."""
    subprocess.run(["bash", "-c", 'source "%s/scripts/lib/common.sh"; install_dependencies; build_project "$@" >&2'
                    % ROOT, "build"] + list(targets), check=True, env=dict(os.environ, VIBROTHERM_BUILD_DIR=build_dir()))


def mpi_env(base=None):
    """The environment (os.environ, or base) with what Open MPI needs as root and to oversubscribe."""
    return dict(base if base is not None else os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
