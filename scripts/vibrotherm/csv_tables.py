"""The CSV outputs read two ways: as numpy columns (fast, for the plots) and as pandas
DataFrames with their units (for users).

A last row without its newline (a run killed mid-write, a .partial file) is left out;
a header and rows of different widths are an error naming the file."""
import io

import numpy as np

from .units import STATES, column_units


def _whole_rows(path):
    """(header names, the bytes of the whole rows after the header)."""
    with open(path, "rb") as f:
        names = f.readline().decode().strip().split(",")
        data = f.read()
    if data and not data.endswith(b"\n"):
        data = data[:data.rfind(b"\n") + 1]
    return names, data


def read_columns(path):
    """A CSV with a header as a dict of float columns; the contact state names become
    their index in STATES and empty cells NaN. np.loadtxt on the bytes: about 0.3 s and
    a copy of the file's size for the 50 MB crack_state.csv of the paper scene."""
    names, data = _whole_rows(path)
    for k, state in enumerate(STATES):
        data = data.replace(b"," + state.encode() + b",", b",%d," % k)
    data = data.replace(b",,", b",nan,").replace(b",,", b",nan,")
    values = np.loadtxt(io.BytesIO(data), delimiter=",", ndmin=2) if data.strip() else np.zeros((0, len(names)))
    if values.shape[1] != len(names):
        raise ValueError("%s: %d columns in the header, %d in the rows" % (path, len(names), values.shape[1]))
    return {name: values[:, i] for i, name in enumerate(names)}


def read_frame(path, name=None, dimension=2):
    """A CSV output as a pandas DataFrame: columns as in the file (their names are a
    contract), numbers as float64 (integers for probe, crack, mode, multiple), the contact
    state as a categorical of STATES (NaN where a row has none); frame.attrs["units"] =
    {column: unit} (units.column_units) and frame.attrs["source"] = the file read."""
    import pandas as pd

    names, data = _whole_rows(path)
    frame = pd.read_csv(io.BytesIO(b",".join(n.encode() for n in names) + b"\n" + data),
                        float_precision="round_trip")  # the numbers as written, to the last bit
    if len(frame.columns) != len(names):
        raise ValueError("%s: %d columns in the header, %d in the rows" % (path, len(names), len(frame.columns)))
    if frame.empty:  # a header only: every column a number
        frame = frame.astype("float64")
    if "state" in frame and frame["state"].dtype == object:  # contact states (periodic.csv's is a number)
        unknown = set(frame["state"].dropna()) - set(STATES)
        if unknown:
            raise ValueError("%s: unknown contact states %s" % (path, sorted(unknown)[:3]))
        frame["state"] = pd.Categorical(frame["state"], categories=STATES)
    for column in ("probe", "crack", "mode", "multiple"):
        if column in frame and frame[column].notna().all() and len(frame):
            frame[column] = frame[column].astype("int64")
    frame.attrs["units"] = column_units(name or path.rsplit("/", 1)[-1], frame.columns, dimension)
    frame.attrs["source"] = path
    return frame
