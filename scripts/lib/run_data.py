"""One run's outputs for the plots: summary.json, the CSV logs (read fast), the crack
names of the mesh, and the windows of time a plot zooms into.

A missing file or an empty log raises Skip (a plot without its data is skipped, not
an error); anything else a plot raises is a bug. An incomplete run (summary.json
"complete": false: stopped by a signal, or still running) is read from its .partial
files, up to their last whole row."""
import io
import json
import os
import re
import xml.etree.ElementTree as ElementTree

import numpy as np

STATES = ["loss", "slide", "partial", "stick"]


class Skip(Exception):
    """The run did not produce what a plot needs: the message says what is missing."""


def read_csv(path):
    """A CSV with a header as a dict of float columns; the contact state names become
    their index in STATES and empty cells NaN. np.loadtxt on the bytes: about 0.3 s and
    a copy of the file's size for the 50 MB crack_state.csv of the paper scene. A last
    row without its newline (a run killed mid-write) is left out."""
    with open(path, "rb") as f:
        names = f.readline().decode().strip().split(",")
        data = f.read()
    if data and not data.endswith(b"\n"):
        data = data[:data.rfind(b"\n") + 1]
    for k, state in enumerate(STATES):
        data = data.replace(b"," + state.encode() + b",", b",%d," % k)
    data = data.replace(b",,", b",nan,").replace(b",,", b",nan,")
    values = np.loadtxt(io.BytesIO(data), delimiter=",", ndmin=2) if data.strip() else np.zeros((0, len(names)))
    if values.shape[1] != len(names):
        raise ValueError("%s: %d columns in the header, %d in the rows" % (path, len(names), values.shape[1]))
    return {name: values[:, i] for i, name in enumerate(names)}


class Run:
    """The outputs of one run directory, each file read once, when a plot first asks."""

    def __init__(self, out):
        self.out = out
        with open(self.path("summary.json")) as f:
            self.summary = json.load(f)
        self._tables = {}
        self.complete = self.summary.get("complete", True) is not False

    def path(self, name):
        return os.path.join(self.out, name)

    def output(self, name):
        """The path of an output: of an incomplete run, its .partial file when that is all there is."""
        path = self.path(name)
        if not self.complete and not os.path.exists(path) and os.path.exists(path + ".partial"):
            return path + ".partial"
        return path

    def need(self, *names):
        """The paths of these outputs, or Skip naming the first that is missing."""
        paths = [self.output(name) for name in names]
        for name, path in zip(names, paths):
            if not os.path.exists(path):
                raise Skip("no %s" % name)
        return paths if len(names) > 1 else paths[0]

    def field_times(self, grid):
        """Output times of one grid's temporal collection in fields_<grid>.xmf."""
        root = ElementTree.parse(self.need("fields_%s.xmf" % grid)).getroot()
        for collection in root.iter("Grid"):
            if collection.get("Name") == grid and collection.get("GridType") == "Collection":
                return [float(g.find("Time").get("Value")) for g in collection.findall("Grid")]
        return []

    def stopped_at(self):
        """The last time an incomplete run recorded (energy.csv), or None."""
        try:
            t = self.table("energy.csv")["t"]
            return float(t[-1]) if len(t) else None
        except (Skip, ValueError, OSError):
            return None

    def table(self, name):
        """A CSV output as columns; Skip when missing or without rows."""
        if name not in self._tables:
            self._tables[name] = read_csv(self.need(name))
        columns = self._tables[name]
        if len(next(iter(columns.values()))) == 0:
            raise Skip("%s has no rows" % name)
        return columns

    def option(self, name, default=None):
        """An option's effective value (summary.json option_values), as a string."""
        value = self.summary.get("option_values", {}).get("-" + name, {}).get("value", "")
        return value if value not in ("", None) else default

    def number(self, name, default):
        try:
            return float(self.option(name, default))
        except (TypeError, ValueError):
            return float(default)

    @property
    def crack_names(self):
        """The mesh's crack names in crack order (crack k of the CSVs is crack_names[k - 1])."""
        return [c.get("name", "crack %d" % (i + 1)) for i, c in enumerate(self.summary.get("mesh", {}).get("cracks", []))]

    def crack_name(self, k):
        names = self.crack_names
        return names[k - 1] if 1 <= k <= len(names) else "crack %d" % k

    @property
    def period(self):
        return 1.0 / self.number("source_frequency", 1e5)

    def excitation_window(self, t_last, cycles):
        """[start, end) of `cycles` source periods in the middle of the excitation that ran
        (the run may stop before the source does); None when less than one period ran."""
        ran = min(self.number("source_duration", t_last), t_last)
        if ran < self.period:
            return None
        start = max(0.0, min(ran / 2, ran - cycles * self.period))
        return start, min(start + cycles * self.period, ran)

    def crack_probes(self):
        """{crack k: (probe index, xi)} of the crack probe nearest each crack's centre."""
        best = {}
        for index, label in self.summary.get("probe_labels", {}).items():
            match = re.match(r"crack (\d+) at xi = (\S+)", label)
            if match:
                crack, xi = int(match.group(1)), float(match.group(2))
                if crack not in best or abs(xi - 0.5) < abs(best[crack][1] - 0.5):
                    best[crack] = (int(index), xi)
        return best
