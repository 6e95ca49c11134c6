"""Kept for older imports: a run's outputs are read by the vibrotherm package
(scripts/vibrotherm: vibrotherm.Run; Skip is vibrotherm.MissingOutput)."""
import package  # noqa: F401
from vibrotherm.csv_tables import read_columns as read_csv  # noqa: F401
from vibrotherm.run_dir import MissingOutput as Skip, Run  # noqa: F401
from vibrotherm.units import STATES  # noqa: F401
