"""ParaView pictures of a Coulomb result (run by scripts/render under pvpython).

usage: pvpython render_paraview.py RESULT.e PREFIX [--width W] [--height H]

Writes, for the last time step of RESULT.e:
  PREFIX_pressure.png  the deformed bodies coloured by contact_pressure (by
                       von_mises when the result has no contact); in 3D the
                       bodies without slave nodes are translucent and the
                       camera looks at the slave surface from the master side,
                       where the pressure is (it is hidden from any other side);
  PREFIX_state.png     contact results only: the slave surface coloured by
                       contact_state (0 open, 1 slip, 2 stick; docs/deck.md),
                       seen from the master side;
  PREFIX_render.json   what was drawn: per picture the file, the field and the
                       colour-bar limits read back from ParaView's lookup
                       table, and the deformation scale (the ctest
                       Render.* check compares the limits with the result).
The deformation is exaggerated when it would be invisible (scale in the
title). Slave nodes are those with a contact normal (|contact_normal| > 0.5).
"""
import argparse
import json
import math
import os
import sys

from paraview import servermanager
from paraview.simple import (Calculator, ColorBy, CreateView, ExodusIIReader, ExtractEdges, ExtractSurface,
                             GetColorTransferFunction, GetScalarBar, MergeBlocks, Render, SaveScreenshot, Show,
                             Text, Threshold, WarpByVector)
from vtk.numpy_interface import dataset_adapter

STATE_NAMES = ["open", "slip", "stick"]
STATE_COLOURS = [0.78, 0.78, 0.78, 0.95, 0.55, 0.10, 0.15, 0.40, 0.85]


def vector_name(names, field):
    """ParaView 5.11 groups field_x/_y/_z into 'field_' (other versions: 'field')."""
    for candidate in (field + "_", field):
        if candidate in names:
            return candidate
    return None


def nice_scale(factor):
    """The next 1, 2, 5 x 10^k at or above factor (a scale a person reads)."""
    if factor <= 1:
        return 1.0
    power = 10 ** math.floor(math.log10(factor))
    for step in (1, 2, 5, 10):
        if step * power >= factor:
            return float(step * power)
    return float(10 * power)


def fetch_arrays(source, names):
    """Point coordinates and the named point arrays of a (merged) source, as numpy."""
    data = dataset_adapter.WrapDataObject(servermanager.Fetch(source))
    return data.Points, {n: data.PointData[n] for n in names if n in data.PointData.keys()}


class Result:
    def __init__(self, path):
        self.path = path
        probe = ExodusIIReader(FileName=[path])
        self.blocks = list(probe.ElementBlocks.Available)
        times = probe.TimestepValues
        self.times = list(times) if isinstance(times, (list, tuple)) or hasattr(times, "__len__") else [times]
        self.time = self.times[-1] if self.times else 0.0
        self.variables = list(probe.PointVariables.Available)

    def block(self, name):
        reader = ExodusIIReader(FileName=[self.path])
        reader.ElementBlocks = [name]
        reader.PointVariables = self.variables
        reader.UpdatePipeline(self.time)
        return MergeBlocks(Input=reader)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("result")
    parser.add_argument("prefix")
    parser.add_argument("--width", type=int, default=1200)
    parser.add_argument("--height", type=int, default=800)
    args = parser.parse_args()

    result = Result(args.result)
    blocks = {name: result.block(name) for name in result.blocks}
    any_block = next(iter(blocks.values()))
    names = list(any_block.PointData.keys())
    displacement = vector_name(names, "displacement")
    contact = "contact_pressure" in names and "contact_state" in names
    normal_name = vector_name(names, "contact_normal")
    field = "contact_pressure" if contact else "von_mises"

    # Which blocks hold slave nodes, the slave surface's centre and normal,
    # the field's range over all nodes and the size of the deformation.
    slave_blocks, slave_points, slave_normals, pressed_points = [], [], [], []
    low, high, largest_displacement = math.inf, -math.inf, 0.0
    lower_corner, upper_corner = [math.inf] * 3, [-math.inf] * 3
    for name, source in blocks.items():
        points, arrays = fetch_arrays(source, [field, displacement, normal_name])
        values = arrays[field]
        low, high = min(low, float(values.min())), max(high, float(values.max()))
        magnitudes = (arrays[displacement] ** 2).sum(axis=1) ** 0.5
        largest_displacement = max(largest_displacement, float(magnitudes.max()))
        for c in range(3):
            lower_corner[c] = min(lower_corner[c], float(points[:, c].min()))
            upper_corner[c] = max(upper_corner[c], float(points[:, c].max()))
        if contact and normal_name in arrays:
            normals = arrays[normal_name]
            on_slave = (normals ** 2).sum(axis=1) > 0.25
            if on_slave.any():
                slave_blocks.append(name)
                slave_points.extend(points[on_slave].tolist())
                slave_normals.extend(normals[on_slave].tolist())
                pressed = on_slave & (arrays[field] > 0)
                pressed_points.extend(points[pressed].tolist())
    size = math.sqrt(sum((u - l) ** 2 for l, u in zip(lower_corner, upper_corner)))
    two_d = (upper_corner[2] - lower_corner[2]) <= 1e-12 * max(size, 1e-300)
    scale = nice_scale(0.04 * size / largest_displacement) if largest_displacement > 0 else 1.0
    if two_d and pressed_points:
        # The 2D picture frames the contact zone (place_camera), where an
        # exaggerated deformation would draw the bodies overlapping.
        scale = 1.0

    centre = [(l + u) / 2 for l, u in zip(lower_corner, upper_corner)]
    normal = [0.0, 0.0, -1.0]
    if slave_points:
        centre = [sum(p[c] for p in slave_points) / len(slave_points) for c in range(3)]
        mean = [sum(n[c] for n in slave_normals) for c in range(3)]
        length = math.sqrt(sum(m * m for m in mean)) or 1.0
        normal = [m / length for m in mean]

    def warped(source):
        return WarpByVector(Input=source, Vectors=["POINTS", displacement], ScaleFactor=scale)

    def new_view():
        view = CreateView("RenderView")
        view.ViewSize = [args.width, args.height]
        view.Background = [1, 1, 1]
        try:
            view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        view.OrientationAxesVisibility = 1
        return view

    def title(view, text):
        label = Text(Text=text)
        display = Show(label, view)
        display.Color = [0, 0, 0]
        display.FontSize = 14
        display.WindowLocation = "Upper Left Corner"

    # The slave surface's in-plane axis of smaller extent ("across").
    in_plane = [c for c in range(3) if c != max(range(3), key=lambda c: abs(normal[c]))]
    extent = {c: (max(p[c] for p in slave_points) - min(p[c] for p in slave_points)) if slave_points else 0.0
              for c in in_plane}
    across = min(in_plane, key=lambda c: extent[c])

    def place_camera(view, kind):
        view.ViewTime = result.time
        if two_d:
            view.CameraPosition = [centre[0], centre[1], centre[2] + 10 * size]
            view.CameraFocalPoint = centre
            view.CameraViewUp = [0, 1, 0]
            view.CameraParallelProjection = 1
        elif kind == "oblique":
            # From the master side (the pressure is on the slave face, which
            # faces it), tilted towards -across so the bodies read as 3D (a
            # half model's symmetry plane is usually there); up away from the master.
            direction = [normal[c] - (0.5 if c == across else 0.0) for c in range(3)]
            view.CameraPosition = [centre[c] + 3 * size * direction[c] for c in range(3)]
            view.CameraFocalPoint = centre
            view.CameraViewUp = [-n for n in normal]
        else:
            # Straight at the slave surface from its own body's side (only
            # that body's edges are drawn), "across" up: not mirrored.
            view.CameraPosition = [centre[c] - 3 * size * normal[c] for c in range(3)]
            view.CameraFocalPoint = centre
            view.CameraViewUp = [1.0 if c == across else 0.0 for c in range(3)]
            view.CameraParallelProjection = 1
        view.ResetCamera()
        view.GetActiveCamera().Dolly(1.15 if two_d else 1.0)
        if two_d and pressed_points:
            # A 2D contact zone is a small part of the section: frame it
            # (three times the loaded width), centred on it.
            xs = [p[0] for p in pressed_points]
            ys = [p[1] for p in pressed_points]
            middle = [(min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, centre[2]]
            width = max(max(xs) - min(xs), max(ys) - min(ys), 1e-3 * size)
            view.CameraFocalPoint = middle
            view.CameraPosition = [middle[0], middle[1], middle[2] + 10 * size]
            view.CameraParallelScale = min(1.5 * width, 0.5 * size)

    def scalar_bar(view, display, array, label):
        lut = GetColorTransferFunction(array)
        bar = GetScalarBar(lut, view)
        bar.Title = label
        bar.ComponentTitle = ""
        bar.TitleColor = [0, 0, 0]
        bar.LabelColor = [0, 0, 0]
        bar.Visibility = 1
        display.SetScalarBarVisibility(view, True)
        return lut

    report = {"result": os.path.abspath(args.result), "time": result.time, "deformation_scale": scale,
              "dimension": 2 if two_d else 3, "pictures": {}}
    base = os.path.basename(args.result)
    scale_text = "" if scale == 1 else ", deformation x%g" % scale

    # 1. Deformed bodies coloured by the field.
    view = new_view()
    for name, source in blocks.items():
        display = Show(warped(source), view)
        ColorBy(display, ("POINTS", field))
        display.Specular = 0.2
        if contact and not two_d and name not in slave_blocks:
            # Nearly clear, with its edges drawn: its colour would otherwise
            # blend into the pressure seen through it.
            display.Opacity = 0.08
            edges = Show(warped(source), view)
            edges.Representation = "Feature Edges"
            edges.ColorArrayName = ["POINTS", ""]
            edges.AmbientColor = edges.DiffuseColor = [0.35, 0.35, 0.35]
    lut = GetColorTransferFunction(field)
    lut.ApplyPreset("Rainbow Uniform", True)
    lut.RescaleTransferFunction(low, high if high > low else low + 1.0)
    lut.AutomaticRescaleRangeMode = "Never"
    scalar_bar(view, display, field, field.replace("_", " "))
    title(view, "%s  t = %g%s" % (base, result.time, scale_text))
    Render(view)  # ParaView resets the camera at a view's first render: place it after
    place_camera(view, "oblique")
    Render(view)
    pressure_png = args.prefix + "_pressure.png"
    SaveScreenshot(pressure_png, view, ImageResolution=[args.width, args.height])
    points = lut.RGBPoints
    report["pictures"]["pressure"] = {"file": os.path.abspath(pressure_png), "field": field,
                                      "range": [points[0], points[-4]], "data_range": [low, high]}

    # 2. Contact state on the slave surface.
    if contact and slave_blocks:
        view = new_view()
        for name in slave_blocks:
            # The reference geometry: an exaggerated deformation would fold
            # the contact zone the picture is about.
            marked = Calculator(Input=blocks[name], ResultArrayName="slave",
                                Function="mag(%s)" % normal_name)
            # 3D: the faces of the body's surface with only slave nodes; 2D:
            # the edges with only slave nodes (a 2D slave surface is a line).
            boundary = ExtractEdges(Input=marked) if two_d else ExtractSurface(Input=marked)
            surface = Threshold(Input=boundary, Scalars=["POINTS", "slave"])
            try:
                surface.LowerThreshold, surface.UpperThreshold = 0.5, 2.0
                surface.ThresholdMethod = "Between"
            except AttributeError:
                surface.ThresholdRange = [0.5, 2.0]
            surface.AllScalars = 1
            outline = Show(blocks[name], view)
            outline.Representation = "Feature Edges" if not two_d else "Wireframe"
            outline.AmbientColor = outline.DiffuseColor = [0.55, 0.55, 0.55]
            outline.ColorArrayName = ['POINTS', '']
            display = Show(surface, view)
            ColorBy(display, ("POINTS", "contact_state"))
            # Colours blended between nodes, not looked up from interpolated
            # values (a categorical table has nothing between its values).
            display.InterpolateScalarsBeforeMapping = 0
            display.LineWidth = 6
            # A second proxy: Show() of the same one in a view returns the
            # same representation, and "Points" would replace the faces.
            nodes = Show(MergeBlocks(Input=surface), view)
            nodes.Representation = "Points"
            nodes.RenderPointsAsSpheres = 1
            nodes.PointSize = 10
            ColorBy(nodes, ("POINTS", "contact_state"))
        lut = GetColorTransferFunction("contact_state")
        lut.InterpretValuesAsCategories = 1
        lut.Annotations = ["0", STATE_NAMES[0], "1", STATE_NAMES[1], "2", STATE_NAMES[2]]
        lut.IndexedColors = STATE_COLOURS
        scalar_bar(view, display, "contact_state", "contact state")
        title(view, "%s  contact state on the slave surface, t = %g" % (base, result.time))
        Render(view)
        place_camera(view, "straight")
        Render(view)
        state_png = args.prefix + "_state.png"
        SaveScreenshot(state_png, view, ImageResolution=[args.width, args.height])
        report["pictures"]["state"] = {"file": os.path.abspath(state_png), "field": "contact_state",
                                       "categories": {"0": "open", "1": "slip", "2": "stick"}}

    with open(args.prefix + "_render.json", "w") as out:
        json.dump(report, out, indent=1)
    for picture in report["pictures"].values():
        print("  %s (%d kB)" % (picture["file"], (os.path.getsize(picture["file"]) + 512) // 1024))


if __name__ == "__main__":
    status = main() or 0
    # Skip ParaView's teardown: with two render views under Xvfb it fails
    # (GLXBadContext) after everything is written, and would turn a good
    # run into a failed one.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(status)
