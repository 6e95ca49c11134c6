"""Opens a run's mesh.xmf and fields_<grid>.xmf in ParaView the way a user would
and checks what ParaView sees; saves three screenshots.

usage: xvfb-run -a -s "-screen 0 1280x1024x24" pvpython paraview_check.py RUN_DIR PNG_DIR

Checked: mesh.xmf read by "Xdmf3 Reader T" and "XDMF Reader" gives the named
blocks wave, cracks, heat; each fields_<grid>.xmf read by the default reader
(OpenDataFile: "Xdmf3 Reader S") is one unstructured grid with the output
times; `displacement` is a 3-component point vector that Warp By Vector picks by
default and moves the points by it; `temperature_rise` has a range of its own
size (a colour bar of `temperature` reads T0 at every tick); `contact_state` is a
cell array on the crack's line cells with codes in {0, 1, 2, 3}.
Screenshots: temperature_rise.png (rise around the crack), displacement.png
(warped wave mesh), contact_state.png (categorical state on the crack)."""
import os
import sys

import numpy

from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, Delete, GetColorTransferFunction, GetScalarBar, Hide,
                             OpenDataFile, SaveScreenshot, Show, Text, WarpByVector, XDMFReader, Xdmf3ReaderT)
from vtkmodules.numpy_interface import dataset_adapter as dsa

run, png_dir = sys.argv[1:3]
failures = []
count = 0


def check(ok, what):
    global count
    count += 1
    if not ok:
        failures.append(what)
        print("FAILED:", what, file=sys.stderr)


def block_names(data):
    return [data.GetMetaData(i).Get(data.NAME()) for i in range(data.GetNumberOfBlocks())]


def check_mesh_blocks():
    path = os.path.join(run, "mesh.xmf")
    for name, make in (("Xdmf3 Reader T", lambda: Xdmf3ReaderT(FileName=[path])),
                       ("XDMF Reader", lambda: XDMFReader(FileNames=[path]))):
        reader = make()
        data = servermanager.Fetch(reader)
        names = block_names(data) if data.IsA("vtkMultiBlockDataSet") else []
        check(names == ["wave", "cracks", "heat"], "mesh.xmf with %s: blocks %s" % (name, names))
        if names == ["wave", "cracks", "heat"]:
            cracks = data.GetBlock(1)
            check(cracks.GetNumberOfCells() > 0 and all(cracks.GetCellType(i) in (3, 4)
                                                        for i in range(cracks.GetNumberOfCells())),
                  "mesh.xmf with %s: cracks are line cells" % name)
        Delete(reader)


def open_series(grid):
    """fields_<grid>.xmf with the reader ParaView picks; its data at its last time
    (the wave and crack grids end with the waves, the heat grid at -final_time)."""
    times = output_times(grid)
    reader = OpenDataFile(os.path.join(run, "fields_%s.xmf" % grid))
    check(reader is not None, "fields_%s.xmf: no reader" % grid)
    found = reader.TimestepValues if reader else []
    found = [found] if isinstance(found, float) else list(found)  # one time: ParaView gives a float
    check(len(found) == len(times) and all(abs(a - b) <= 1e-9 * b for a, b in zip(found, times)),
          "fields_%s.xmf: ParaView reads times %s, the file lists %s" % (grid, found, times))
    reader.UpdatePipeline(times[-1])
    data = servermanager.Fetch(reader)
    check(data.IsA("vtkUnstructuredGrid"), "fields_%s.xmf: %s, not one grid" % (grid, data.GetClassName()))
    return reader, data


def check_displacement(reader, data):
    u = data.GetPointData().GetArray("displacement")
    check(u is not None and u.GetNumberOfComponents() == 3, "displacement: 3-component point array")
    vectors = data.GetPointData().GetVectors()
    check(vectors is not None and vectors.GetName() in ("displacement", "velocity"), "wave grid: active vectors")
    warp = WarpByVector(Input=reader)  # the vector ParaView picks by default
    check(warp.Vectors[1] == "displacement", "WarpByVector picks %s" % list(warp.Vectors))
    warp.ScaleFactor = 1.0
    warped = dsa.WrapDataObject(servermanager.Fetch(warp))
    moved = warped.Points - dsa.WrapDataObject(data).Points
    worst = abs(moved - dsa.WrapDataObject(data).PointData["displacement"]).max()
    peak = abs(dsa.WrapDataObject(data).PointData["displacement"]).max()
    check(peak > 0 and worst <= 1e-9 * peak, "WarpByVector moves points by displacement: %g of %g" % (worst, peak))
    return warp, peak


def check_rise(data):
    rise = data.GetPointData().GetArray("temperature_rise")
    check(rise is not None, "heat grid: temperature_rise")
    if rise is None:
        return (0.0, 0.0)
    lo, hi = rise.GetRange()
    check(hi > 0 and hi - lo > 0.5 * max(abs(lo), abs(hi)), "temperature_rise range [%g, %g]" % (lo, hi))
    T = data.GetPointData().GetArray("temperature")
    if T is not None:
        t_lo, t_hi = T.GetRange()
        print("temperature range [%.9g, %.9g] K; temperature_rise [%.3g, %.3g] K" % (t_lo, t_hi, lo, hi))
    return lo, hi


def check_contact_state(data):
    cell = data.GetCellData().GetArray("contact_state")
    check(cell is not None and data.GetPointData().GetArray("contact_state") is None,
          "contact_state: a cell array (not a point array) on the cracks grid")
    if cell is not None:
        codes = {cell.GetValue(i) for i in range(cell.GetNumberOfTuples())}
        check(codes <= {0.0, 1.0, 2.0, 3.0}, "contact_state codes %s" % sorted(codes))
        print("contact_state codes at the last output:", sorted(codes))


def frame(v, window, legend_room=0.3):
    """Parallel projection onto the window (x0, x1, y0, y1), with room on the right for the colour bar."""
    x0, x1, y0, y1 = window
    x1 += legend_room * (x1 - x0)
    aspect = v.ViewSize[0] / v.ViewSize[1]
    v.CameraParallelProjection = 1
    v.CameraPosition = [(x0 + x1) / 2, (y0 + y1) / 2, 1]
    v.CameraFocalPoint = [(x0 + x1) / 2, (y0 + y1) / 2, 0]
    v.CameraViewUp = [0, 1, 0]
    v.CameraParallelScale = max(y1 - y0, (x1 - x0) / aspect) / 2


def bar(display, v, title, color=(0, 0, 0)):
    display.SetScalarBarVisibility(v, True)
    b = GetScalarBar(display.LookupTable, v)
    b.Title = title
    b.ComponentTitle = ""
    b.TitleColor = b.LabelColor = list(color)
    b.TitleFontSize = b.LabelFontSize = 18
    b.WindowLocation = "Any Location"
    b.Position = [0.84, 0.08]
    b.ScalarBarLength = 0.84


def caption(v, text, color=(0, 0, 0)):
    label = Text(Text=text)
    d = Show(label, v)
    d.Color = list(color)
    d.FontSize = 22
    d.WindowLocation = "Upper Left Corner"
    return label


def save(v, name, shown):
    SaveScreenshot(os.path.join(png_dir, name), v, ImageResolution=list(v.ViewSize))
    for source in shown:
        Hide(source, v)


def hot_window(data, zoom=5.0):
    """Square around the hottest point, `zoom` times the distance from it to where the
    rise drops below 5 % of its peak: the heated band is far thinner than the crack."""
    rise = dsa.WrapDataObject(data).PointData["temperature_rise"].ravel()
    xy = dsa.WrapDataObject(data).Points[:, :2]
    centre = xy[rise.argmax()]
    cold = xy[rise < 0.05 * rise.max()]
    x0, x1, y0, y1 = data.GetBounds()[:4]
    half = zoom * numpy.sqrt(((cold - centre) ** 2).sum(axis=1)).min() if len(cold) else numpy.inf
    if 2 * half >= max(x1 - x0, y1 - y0):  # late times: the heat has spread over the body
        return (x0, x1, y0, y1)
    return (centre[0] - half, centre[0] + half, centre[1] - half, centre[1] + half)


def screenshots(sources, heat_data, crack_data, warp, peak, t_heat, t_wave):
    """Each grid at its own last output time (the wave and crack grids end with the waves)."""
    wave, heat, cracks = sources
    v = CreateView("RenderView")
    v.ViewSize = [1000, 800]
    v.OrientationAxesVisibility = 0
    v.Background = [1, 1, 1]
    if hasattr(v, "UseColorPaletteForBackground"):
        v.UseColorPaletteForBackground = 0
    v.ViewTime = t_heat
    when = "t = %.4g ms" % (t_heat * 1e3)
    # 1: temperature rise around its hottest point on the crack, crack in cyan.
    rise = heat_data.GetPointData().GetArray("temperature_rise").GetRange()
    window = hot_window(heat_data)
    frame(v, window)
    d = Show(heat, v)
    ColorBy(d, ("POINTS", "temperature_rise"))
    lut = GetColorTransferFunction("temperature_rise")
    lut.ApplyPreset("Inferno (matplotlib)", True)
    lut.RescaleTransferFunction(0.0, rise[1])
    white = (1, 1, 1)  # on the dark end of the colour map
    v.Background = [0, 0, 0]  # late times: the hot window is larger than the body, text on the margins
    bar(d, v, "temperature_rise [K]", white)
    c = Show(cracks, v)
    ColorBy(c, None)
    c.AmbientColor = c.DiffuseColor = [0, 0.8, 1]
    c.LineWidth = 1
    label = caption(v, "heat grid: temperature_rise = T - T0 near its peak, %s\n(crack: cyan line; %.2g mm high)"
                    % (when, (window[3] - window[2]) * 1e3), white)
    save(v, "temperature_rise.png", [heat, cracks, label])
    v.Background = [1, 1, 1]
    v.ViewTime = t_wave
    when = "t = %.4g ms" % (t_wave * 1e3)
    # 2: the whole wave mesh warped by displacement.
    b = wave_bounds = servermanager.Fetch(wave).GetBounds()
    frame(v, (b[0], b[1], b[2] - 0.05 * (b[3] - b[2]), b[3] + 0.05 * (b[3] - b[2])), legend_room=0.6)
    warp.ScaleFactor = 0.03 * (b[3] - b[2]) / peak  # the largest displacement: 3 % of the height
    d = Show(warp, v)
    d.SetRepresentationType("Surface With Edges")
    d.EdgeColor = [0.3, 0.3, 0.3]
    ColorBy(d, ("POINTS", "displacement", "Magnitude"))
    GetColorTransferFunction("displacement").ApplyPreset("Viridis (matplotlib)", True)
    bar(d, v, "displacement magnitude [m]")
    label = caption(v, "wave grid warped by displacement x %.3g, %s" % (warp.ScaleFactor, when))
    save(v, "displacement.png", [warp, label])
    # 3: contact state on the crack's line cells (categorical) over the wave mesh.
    x0, x1, y0, y1 = crack_data.GetBounds()[:4]
    pad = 0.05 * max(x1 - x0, y1 - y0)
    frame(v, (x0 - pad, x1 + pad, y0 - pad, y1 + pad))
    m = Show(wave, v)
    ColorBy(m, None)
    m.SetRepresentationType("Wireframe")
    m.AmbientColor = m.DiffuseColor = [0.75, 0.75, 0.75]
    d = Show(cracks, v)
    ColorBy(d, ("CELLS", "contact_state"))
    d.LineWidth = 8
    lut = GetColorTransferFunction("contact_state")
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = ["-1", "no data", "0", "loss", "1", "slide", "2", "partial", "3", "stick"]
    lut.IndexedColors = [0.6, 0.6, 0.6, 0.85, 0.1, 0.1, 1.0, 0.6, 0.0, 0.2, 0.6, 1.0, 0.1, 0.6, 0.1]
    bar(d, v, "contact_state")
    label = caption(v, "cracks grid: contact_state per contact cell, %s" % when)
    save(v, "contact_state.png", [wave, cracks, label])
    Delete(v)


def output_times(grid):
    import xml.etree.ElementTree as ET
    root = ET.parse(os.path.join(run, "fields_%s.xmf" % grid)).getroot()
    return [float(t.get("Value")) for t in root.iter("Time")]


check_mesh_blocks()
times = output_times("heat")
wave, wave_data = open_series("wave")
heat, heat_data = open_series("heat")
cracks, crack_data = open_series("cracks")
warp, peak = check_displacement(wave, wave_data)
check_rise(heat_data)
check_contact_state(crack_data)
if not failures:
    os.makedirs(png_dir, exist_ok=True)
    screenshots((wave, heat, cracks), heat_data, crack_data, warp, peak, times[-1], output_times("wave")[-1])
    print("screenshots in", png_dir)
print("paraview check: %d passed, %d failed" % (count - len(failures), len(failures)))
sys.exit(1 if failures else 0)
