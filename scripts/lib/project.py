"""Kept for older imports: the project root, the build and Open MPI's environment are
vibrotherm.project's (scripts/vibrotherm)."""
import package  # noqa: F401
from vibrotherm.project import BUILD_DIR, ROOT, build, mpi_env  # noqa: F401
