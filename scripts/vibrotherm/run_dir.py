"""One run directory: summary.json as a dict with typed accessors, the CSV outputs as
pandas DataFrames (or numpy columns), the HDF5 outputs as xarray objects, each with units.

A missing output raises MissingOutput (a plot without its data is skipped, not an error).
An incomplete run (summary.json "complete": false: stopped by a signal, or failed) is read
from its .partial files, up to their last whole row."""
import json
import math
import os
import re
import xml.etree.ElementTree as ElementTree

import numpy as np

from . import crack_geometry, csv_tables, h5_arrays


class MissingOutput(LookupError):
    """The run did not write what was asked for: the message says what is missing."""


def _dotted(tree, key):
    """tree["a"]["b"] for key "a.b" (a list index as a number: "mesh.cracks.0.length"); KeyError when absent."""
    node = tree
    for part in key.split("."):
        if isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        elif isinstance(node, dict) and part in node:
            node = node[part]
        else:
            raise KeyError(key)
    return node


class Run:
    """The outputs of one run directory, each file read once, when first asked for.

    summary           summary.json as a dict (every key, known or not)
    value(key)        a summary value by dotted key ("camera.peak_rise"), unit(key) its unit
    option(name)      an option's effective value as a string; option_number(name) as a float
    energy(), probes(), crack_state(), periodic(), source_power(), modes(), csv(name)   DataFrames with attrs["units"]
    fields(grid), field(grid, name), camera(), mode_shapes(), mesh(grid)  xarray objects with units
    """

    def __init__(self, directory):
        self.directory = os.fspath(directory)
        path = os.path.join(self.directory, "summary.json")
        if not os.path.exists(path):
            raise FileNotFoundError("%s: no summary.json (not a vibrotherm run directory, or a run that never "
                                    "started)" % self.directory)
        with open(path) as f:
            self.summary = json.load(f)
        self._columns = {}

    def __repr__(self):
        return "vibrotherm.Run(%r: %s, %dD)" % (self.directory, "complete" if self.complete else "INCOMPLETE",
                                                self.dimension)

    # --- files ------------------------------------------------------------------------------------

    @property
    def out(self):  # the plots' name for the directory
        return self.directory

    def path(self, name):
        return os.path.join(self.directory, name)

    def output(self, name):
        """The path of an output: of an incomplete run, its .partial file when that is all there is."""
        path = self.path(name)
        if not self.complete and not os.path.exists(path) and os.path.exists(path + ".partial"):
            return path + ".partial"
        return path

    def has(self, name):
        return os.path.exists(self.output(name))

    def need(self, *names):
        """The paths of these outputs, or MissingOutput naming the first that is missing."""
        paths = [self.output(name) for name in names]
        for name, path in zip(names, paths):
            if not os.path.exists(path):
                raise MissingOutput("no %s" % name)
        return paths if len(names) > 1 else paths[0]

    # --- summary.json -----------------------------------------------------------------------------

    @property
    def complete(self):
        return self.summary.get("complete", True) is not False

    @property
    def dimension(self):
        return int(self.summary.get("dimension", 2))

    @property
    def warnings(self):
        return list(self.summary.get("warnings", []))

    def value(self, key, default=KeyError):
        """A summary value by dotted key ("dissipated_energy", "camera.peak_rise",
        "mesh.cracks.0.length"); `default` when absent, KeyError without one."""
        try:
            return _dotted(self.summary, key)
        except KeyError:
            if default is KeyError:
                raise KeyError("%s: summary.json has no %r" % (self.directory, key)) from None
            return default

    def unit(self, key):
        """The unit of a summary key (summary.json "units"; a list's entries share their key's:
        "mesh.cracks.0.length" → "mesh.cracks.length"), or None when the run gives none."""
        units = self.summary.get("units", {})
        return units.get(key, units.get(re.sub(r"\.\d+(?=\.|$)", "", key)))

    def option(self, name, default=None):
        """An option's effective value (summary.json option_values) as a string; name with or without "-"."""
        value = self.summary.get("option_values", {}).get("-" + name.lstrip("-"), {}).get("value", "")
        return value if value not in ("", None) else default

    def option_number(self, name, default=None):
        """An option's value as a float; `default` when it has none or is not a number."""
        try:
            return float(self.option(name, default))
        except (TypeError, ValueError):
            return None if default is None else float(default)

    def number(self, name, default):
        """option_number with a default (the plots' name)."""
        return self.option_number(name, default)

    def scalars(self):
        """Every number of summary.json (nested keys dotted, lists indexed) as a pandas Series,
        series.attrs["units"] = {key: unit} where the run gives one; option values are left out."""
        import pandas as pd

        flat = {}

        def walk(node, prefix):
            if isinstance(node, bool):
                flat[prefix] = node
            elif isinstance(node, (int, float)):
                flat[prefix] = node
            elif isinstance(node, dict):
                for key, value in node.items():
                    walk(value, prefix + "." + key if prefix else key)
            elif isinstance(node, list):
                for i, value in enumerate(node):
                    walk(value, "%s.%d" % (prefix, i))

        walk({k: v for k, v in self.summary.items() if k not in ("option_values", "units", "derived_rules")}, "")
        series = pd.Series(flat, dtype=object, name=self.directory)
        series.attrs["units"] = {k: self.unit(k) for k in flat if self.unit(k) is not None}
        return series

    @property
    def probe_labels(self):
        """{probe index: label} ("point (x, y)", "crack 1 at xi = 0.500000")."""
        return {int(k): v for k, v in self.summary.get("probe_labels", {}).items()}

    @property
    def crack_names(self):
        """The mesh's crack names in crack order (crack k of the CSVs is crack_names[k - 1])."""
        return [c.get("name", "crack %d" % (i + 1)) for i, c in enumerate(self.summary.get("mesh", {}).get("cracks", []))]

    def crack_name(self, k):
        names = self.crack_names
        return names[k - 1] if 1 <= k <= len(names) else "crack %d" % k

    @property
    def period(self):
        """The source period [s] (1 / -source_frequency)."""
        return 1.0 / self.option_number("source_frequency", 1e5)

    def crack_outlines(self):
        """[(crack name, polyline (n × dim) [m])]: 2D the cracks' lines (mesh.h5), 3D their outlines
        from the options (rectangle or ellipse); a crack the run cannot place is left out."""
        return crack_geometry.outlines(self)

    def crack_probes(self):
        """{crack k: (probe index, xi)} of the crack probe nearest each crack's centre."""
        best = {}
        for index, label in self.probe_labels.items():
            match = re.match(r"crack (\d+) at xi = (\S+)", label)
            if match:
                crack, xi = int(match.group(1)), float(match.group(2))
                if crack not in best or abs(xi - 0.5) < abs(best[crack][1] - 0.5):
                    best[crack] = (index, xi)
        return best

    # --- CSV outputs ------------------------------------------------------------------------------

    def columns(self, name):
        """A CSV output as a dict of numpy float columns (fast; contact states as their index in
        units.STATES); MissingOutput when the file is missing or has no rows."""
        if name not in self._columns:
            self._columns[name] = csv_tables.read_columns(self.need(name))
        columns = self._columns[name]
        if len(next(iter(columns.values()))) == 0:
            raise MissingOutput("%s has no rows" % name)
        return columns

    table = columns  # the plots' name

    def rows(self, name):
        """A CSV output's rows as dicts of the texts written (csv.DictReader): what a check that
        compares written values reads; MissingOutput when the file is missing."""
        import csv

        with open(self.need(name), newline="") as f:
            return list(csv.DictReader(f))

    def h5(self, name):
        """An HDF5 output opened for reading (h5py.File: `with run.h5("fields.h5") as f`); MissingOutput
        when the file is missing."""
        import h5py

        return h5py.File(self.need(name), "r")

    def csv(self, name):
        """A CSV output as a pandas DataFrame (csv_tables.read_frame: the file's columns, units in
        attrs["units"]); MissingOutput when the file is missing. Read anew at every call."""
        return csv_tables.read_frame(self.need(name), name, self.dimension)

    def energy(self):
        """energy.csv: the energy accounts over time [J/m in 2D, J in 3D]."""
        return self.csv("energy.csv")

    def probes(self, probe=None):
        """probes.csv (one probe's rows when given); attrs["labels"] = {probe: label}."""
        frame = self.csv("probes.csv")
        if probe is not None:
            frame = frame[frame["probe"] == probe].reset_index(drop=True)
        frame.attrs["labels"] = self.probe_labels
        return frame

    def crack_state(self, crack=None):
        """crack_state.csv (one crack's rows when given), one schema in both dimensions: each cell
        by xi along a 2D crack line (nan on a 3D crack surface) and s1, s2 from the crack's centre."""
        frame = self.csv("crack_state.csv")
        if crack is not None:
            frame = frame[frame["crack"] == crack].reset_index(drop=True)
        return frame

    def periodic(self):
        """periodic.csv: the change at every source-period boundary against 1..4 periods back."""
        return self.csv("periodic.csv")

    def source_power(self):
        """source_power.csv: per source period the mean powers in and out and the efficiency
        (a sweep's rows carry its instantaneous frequency)."""
        return self.csv("source_power.csv")

    def modes(self):
        """modes.csv (-modes): frequency [Hz] and defect participation of every mode."""
        return self.csv("modes.csv")

    def crack_history(self, variable, crack=1):
        """One crack_state.csv column of one crack as an xarray DataArray over (t, xi) in 2D or
        (t, cell) in 3D (coordinates s1, s2, x, y, z of each cell), with its unit."""
        import xarray as xr

        frame = self.crack_state(crack)
        if frame.empty:
            raise MissingOutput("crack_state.csv has no rows of crack %d" % crack)
        keys = ["xi"] if frame["xi"].notna().all() else ["s1", "s2"]  # a 3D surface has no xi
        if variable == "state":
            frame = frame.assign(state=frame["state"].cat.codes.where(frame["state"].notna()))
        table = frame.pivot_table(index="t", columns=keys, values=variable, aggfunc="first", dropna=False)
        unit = frame.attrs["units"].get(variable)
        attrs = {"units": unit} if unit is not None else {}
        if variable == "state":
            attrs["states"] = ", ".join("%d %s" % (k, s) for k, s in enumerate(csv_tables.STATES))
        if keys == ["xi"]:
            return xr.DataArray(table.to_numpy(), dims=("t", "xi"), name=variable, attrs=attrs,
                                coords={"t": ("t", table.index.to_numpy(), {"units": "s"}),
                                        "xi": ("xi", table.columns.to_numpy(float), {"units": "1"})})
        cells = frame.drop_duplicates(keys).set_index(keys).loc[table.columns]
        coords = {"t": ("t", table.index.to_numpy(), {"units": "s"})}
        coords.update({c: ("cell", cells.index.get_level_values(c).to_numpy() if c in keys else cells[c].to_numpy(),
                           {"units": "m"}) for c in ("s1", "s2", "x", "y", "z")})
        return xr.DataArray(table.to_numpy(), dims=("t", "cell"), name=variable, attrs=attrs, coords=coords)

    # --- HDF5 outputs -----------------------------------------------------------------------------

    def fields(self, grid="heat"):
        """Every field of one grid of fields.h5 ("heat", "wave", "cracks") as an xarray Dataset
        (h5_arrays.grid_fields); MissingOutput when the run wrote none."""
        path = self.need("fields.h5")
        try:
            return h5_arrays.grid_fields(path, grid, self.output("fields_%s.xmf" % grid))
        except KeyError as why:
            raise MissingOutput(str(why).strip("'\"")) from None

    def field(self, grid, name):
        """One field of fields.h5 as an xarray DataArray over (time, node or cell[, component])."""
        dataset = self.fields(grid)
        if name not in dataset:
            raise MissingOutput("fields.h5 has no field %r on grid %r (it has %s)" % (
                name, grid, ", ".join(sorted(dataset.data_vars))))
        return dataset[name]

    def field_times(self, grid):
        """Output times of one grid's temporal collection in fields_<grid>.xmf."""
        root = ElementTree.parse(self.need("fields_%s.xmf" % grid)).getroot()
        for collection in root.iter("Grid"):
            if collection.get("Name") == grid and collection.get("GridType") == "Collection":
                return [float(g.find("Time").get("Value")) for g in collection.findall("Grid")]
        return []

    def camera(self):
        """camera.h5 (-camera) as an xarray Dataset over (time, y, x) (h5_arrays.camera_frames)."""
        return h5_arrays.camera_frames(self.need("camera.h5"))

    def mode_shapes(self):
        """modes.h5 (-modes) as an xarray DataArray over (mode, node, component)."""
        return h5_arrays.mode_shapes(self.need("modes.h5"))

    def mesh(self, grid="wave"):
        """Mesh(nodes, cells) of a grid ("wave", "heat", "cracks"): from mesh.h5, else from the
        first output holding it (fields.h5, modes.h5: runs of builds before mesh.h5 was written in 3D)."""
        for name in ("mesh.h5", "fields.h5", "modes.h5"):
            if self.has(name):
                try:
                    return h5_arrays.mesh_arrays(self.output(name), grid)
                except KeyError:
                    continue
        raise MissingOutput("no grid %r in mesh.h5, fields.h5 or modes.h5" % grid)

    # --- windows of time --------------------------------------------------------------------------

    def stopped_at(self):
        """The last time an incomplete run recorded (energy.csv), or None."""
        try:
            t = self.columns("energy.csv")["t"]
            return float(t[-1]) if len(t) else None
        except (MissingOutput, ValueError, OSError):
            return None

    def excitation_window(self, t_last, cycles):
        """[start, end) of `cycles` source periods in the middle of the excitation that ran
        (the run may stop before the source does); None when less than one period ran."""
        ran = min(self.option_number("source_duration", t_last), t_last)
        if ran < self.period or math.isnan(ran):
            return None
        start = max(0.0, min(ran / 2, ran - cycles * self.period))
        return start, min(start + cycles * self.period, ran)

    def steady_window(self, times, cycles):
        """[start, end) of `cycles` source periods that the record `times` (a table's t column)
        covers without a gap: the middle of the excitation that ran (excitation_window) when
        recorded there, else the last `cycles` periods recorded before the source stopped (a
        periodic continuation records nothing while it continues: its rows are the simulated
        stretches); None when no such window was recorded."""
        times = np.unique(np.asarray(times, float))
        if len(times) < 3:
            return None
        period = self.period

        def covered(window):
            inside = times[(times >= window[0]) & (times <= window[1])]
            if len(inside) < 3:
                return False
            gaps = np.diff(np.concatenate([[window[0]], inside, [window[1]]]))
            return gaps.max() <= 0.5 * period

        middle = self.excitation_window(times[-1], cycles)
        if middle and covered(middle):
            return middle
        ran = min(self.option_number("source_duration", times[-1]), times[-1])
        before = times[times <= ran * (1 + 1e-12)]
        if len(before) == 0:
            return None
        last = (max(0.0, before[-1] - cycles * period), before[-1])
        return last if last[1] - last[0] >= period * (1 - 1e-9) and covered(last) else None


def load(directory):
    """The run in `directory` (a Run); FileNotFoundError when it has no summary.json."""
    return Run(directory)


def summaries(runs):
    """One row per run (Run objects or directories): every number of its summary.json
    (Run.scalars), a column per key; frame.attrs["units"] merges the runs' units."""
    import pandas as pd

    rows = [(r if isinstance(r, Run) else Run(r)).scalars() for r in runs]
    frame = pd.DataFrame(rows)
    frame.attrs["units"] = {k: u for row in rows for k, u in row.attrs["units"].items()}
    return frame
