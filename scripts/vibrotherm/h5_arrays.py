"""The HDF5 outputs as xarray objects with their units (attrs["units"], from the files'
own "units" attributes):

    grid_fields(fields.h5, grid)   every field of one grid: a Dataset over (time, node or cell[, component])
    camera_frames(camera.h5)       every frame series: a Dataset over (time, y, x)
    mode_shapes(modes.h5)          the mode shapes: a DataArray over (mode, node, component)
    mesh_arrays(file, grid)        a grid's node coordinates and cells

A numbered series `<name>_<k>` becomes one variable over time; a dataset or attribute these
readers do not know passes through (a variable of its own, or an attribute), so newer
outputs load without a change here."""
import collections
import re

import numpy as np

Mesh = collections.namedtuple("Mesh", "nodes cells")
_SERIES = re.compile(r"^(.+)_(\d+)$")
COMPONENTS = ("x", "y", "z")


def _text(value):
    return value.decode() if isinstance(value, bytes) else value


def _attrs(obj):
    """HDF5 attributes as plain Python values (bytes decoded, 1-element arrays as numbers)."""
    out = {}
    for key, value in obj.attrs.items():
        value = _text(value)
        if isinstance(value, np.ndarray) and value.size == 1:
            value = value.item()
        out[key] = value
    return out


def _series(group):
    """{name: [dataset of step 0, 1, ...]} of the numbered datasets of an HDF5 group; and the others."""
    numbered, others = collections.defaultdict(dict), []
    for key, item in group.items():
        match = _SERIES.match(key)
        if match and hasattr(item, "shape"):
            numbered[match.group(1)][int(match.group(2))] = item
        elif hasattr(item, "shape"):
            others.append(key)
    return {name: [steps[k] for k in sorted(steps)] for name, steps in numbered.items()}, others


def mesh_arrays(path, grid):
    """Mesh(nodes (n × dim), cells (m × nodes per cell)) of `grid` in an HDF5 output; KeyError when absent."""
    import h5py

    with h5py.File(path, "r") as f:
        if grid + "/geometry" not in f:
            raise KeyError("%s has no grid %r" % (path, grid))
        cells = f[grid + "/topology"][:] if grid + "/topology" in f else None
        return Mesh(f[grid + "/geometry"][:], cells)


def _centres(nodes, cells):
    return nodes[cells].mean(axis=1)


def _place(n_values, nodes, cells, center):
    """("node" or "cell", coordinates of each value) of a field with n_values rows."""
    if center == "Cell" or (center is None and cells is not None and n_values == len(cells) != len(nodes)):
        return "cell", _centres(nodes, cells)
    if n_values != len(nodes):
        raise ValueError("a field of %d values on a grid of %d nodes and %d cells" % (
            n_values, len(nodes), len(cells) if cells is not None else 0))
    return "node", nodes


def _centers_from_xmf(xmf_path):
    """{attribute name: "Node" or "Cell"} of an XDMF file (empty when there is none)."""
    import os
    import xml.etree.ElementTree as ElementTree

    if not xmf_path or not os.path.exists(xmf_path):
        return {}
    return {a.get("Name"): a.get("Center") for a in ElementTree.parse(xmf_path).getroot().iter("Attribute")}


def _series_array(name, steps, place, coords):
    """One numbered series (values of k = 0, 1, ... with attribute "time") as a DataArray over time."""
    import xarray as xr

    values = np.stack([s[()] for s in steps])
    attrs = _attrs(steps[0])
    attrs.pop("time", None)
    dims = ["time", place]
    if values.ndim == 3 and values.shape[2] == 1:
        values = values[:, :, 0]
    elif values.ndim == 3:
        dims.append("component")
    coords = dict(coords, time=("time", np.array([float(s.attrs.get("time", np.nan)) for s in steps])))
    if "component" in dims:
        coords["component"] = ("component", list(COMPONENTS[:values.shape[2]]))
    return xr.DataArray(values, dims=dims, coords=coords, name=name, attrs=attrs)


def grid_fields(path, grid, xmf_path=None):
    """Every field of `grid` ("wave", "heat", "cracks") in fields.h5 as an xarray Dataset:
    a variable per field over (time[, node or cell][, component]); coordinates x, y (z) of
    each node, or each cell's centre for cell values (the XDMF file's Center when given,
    else the sizes); time from each dataset's "time" attribute (exact, unlike the XDMF's
    rounded <Time>); units in each variable's attrs. Fields on different times are aligned
    (NaN where one has no value). KeyError when the grid has no fields."""
    import h5py
    import xarray as xr

    centers = _centers_from_xmf(xmf_path)
    with h5py.File(path, "r") as f:
        if grid not in f:
            raise KeyError("%s has no grid %r" % (path, grid))
        group = f[grid]
        nodes = group["geometry"][:]
        cells = group["topology"][:] if "topology" in group else None
        numbered, _ = _series(group)
        arrays = []
        for name, steps in sorted(numbered.items()):
            place, points = _place(steps[0].shape[0], nodes, cells, centers.get(name))
            axes = COMPONENTS[:points.shape[1]]
            coords = {axis: (place, points[:, i]) for i, axis in enumerate(axes)}
            arrays.append(_series_array(name, steps, place, coords))
    if not arrays:
        raise KeyError("%s has no fields on grid %r" % (path, grid))
    dataset = xr.merge(arrays, join="outer", combine_attrs="drop")
    for array in arrays:
        dataset[array.name].attrs = array.attrs
    for coordinate in dataset.coords:  # merge keeps no coordinate attributes
        if coordinate != "component":
            dataset[coordinate].attrs["units"] = "s" if coordinate == "time" else "m"
    dataset.attrs.update(grid=grid, source=path)
    return dataset


def camera_frames(path):
    """camera.h5 as an xarray Dataset over (time, y, x): a variable per frame series
    ("frame": what the camera reads, with NETD noise; "clean": without noise; any other
    series the file holds), coordinates time (window centre), window_start, window_end [s]
    and the pixel centres x, y [m] in the filmed face's axes; the camera's settings (fps,
    integration, netd, pixel, window, ...) in attrs."""
    import h5py
    import xarray as xr

    with h5py.File(path, "r") as f:
        group = f["camera"]
        numbered, others = _series(group)
        coords = {}
        if "x" in group and "y" in group:
            coords["x"] = ("x", group["x"][()].ravel(), {"units": "m"})
            coords["y"] = ("y", group["y"][()].ravel(), {"units": "m"})
        variables = {}
        times = None
        for name, steps in sorted(numbered.items()):
            values = np.stack([s[()] for s in steps]) if steps else np.zeros((0, 0, 0))
            attrs = _attrs(steps[0]) if steps else {}
            for key in ("time", "window_start", "window_end"):
                attrs.pop(key, None)
            variables[name] = (("time", "y", "x"), values, attrs)
            if times is None:
                times = [[float(s.attrs.get(k, np.nan)) for k in ("time", "window_start", "window_end")] for s in steps]
        if times is None and "time" in group:
            times = group["time"][()].reshape(-1, 3).tolist()
        times = np.array(times if times else np.zeros((0, 3)), float).reshape(-1, 3)
        coords["time"] = ("time", times[:, 0], {"units": "s"})
        coords["window_start"] = ("time", times[:, 1], {"units": "s"})
        coords["window_end"] = ("time", times[:, 2], {"units": "s"})
        for key in others:  # a dataset this reader does not know: passed through
            if key not in ("x", "y", "time"):
                data = group[key][()]
                variables[key] = (tuple("%s_%d" % (key, i) for i in range(np.ndim(data))), data, _attrs(group[key]))
        attrs = _attrs(group)
    dataset = xr.Dataset(variables, coords=coords, attrs=attrs)
    dataset.attrs["source"] = path
    return dataset


def mode_shapes(path):
    """modes.h5's shapes as a DataArray over (mode, node, component) with coordinates
    frequency [Hz] per mode and x, y (z) per node; mode numbers as in modes.csv."""
    import h5py
    import xarray as xr

    with h5py.File(path, "r") as f:
        group = f["wave"]
        nodes = group["geometry"][:]
        modes = sorted(int(k.rsplit("_", 1)[1]) for k in group if k.startswith("mode_"))
        values = np.stack([group["mode_%d" % k][()] for k in modes]) if modes else np.zeros((0, len(nodes), 3))
        frequency = [float(group["mode_%d" % k].attrs.get("frequency", np.nan)) for k in modes]
        units = _attrs(group["mode_%d" % modes[0]]).get("units", "1") if modes else "1"
    axes = COMPONENTS[:nodes.shape[1]]
    coords = {"mode": modes, "frequency": ("mode", frequency, {"units": "Hz"}),
              "component": list(COMPONENTS[:values.shape[2]])}
    coords.update({axis: ("node", nodes[:, i], {"units": "m"}) for i, axis in enumerate(axes)})
    return xr.DataArray(values, dims=("mode", "node", "component"), coords=coords, name="mode_shape",
                        attrs={"units": units, "source": path})
