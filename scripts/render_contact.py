#!/usr/bin/env python3
"""Renders a run's output with ParaView: one PNG per chosen time with three
views side by side,

  1. the deformed body coloured by the von Mises stress (by the equivalent
     plastic strain where it flowed plastically), in 3D cut through the
     middle of its contact zone, with the obstacle (or the rigid tool, from
     tool.pvd) drawn at its position at that time;
  2. the contact face (the faces whose vertices are all contact candidates)
     coloured by the contact pressure, seen from the obstacle;
  3. the same face with each candidate drawn as a dot of its contact state
     (free, stick, slip; "in contact" where the scene has no friction).

Run it with ParaView's Python, without a screen on a virtual display:

  scripts/headless.sh pvbatch --no-mpi scripts/render_contact.py OUTPUT_DIR [options]

(xvfb-run -a pvbatch ... works as well; scripts/headless.sh adds a time
limit and cannot wait forever for the display.)

OUTPUT_DIR is a run's <Output directory> (solution.pvd, parameters.prm).
Options:
  --out DIR          where the PNG files go (default OUTPUT_DIR/figures)
  --times WHICH      contact (default: the time with the most vertices in
                     contact, the latest of equals), last, all, or a
                     comma-separated list of times
  --warp FACTOR      scale of the displacement (default 1: true positions,
                     consistent with the obstacle)
  --size WxH         image size in pixels (default 1800x600)
  --name NAME        file name stem (default: the folder's name)
  --state FILE.pvsm  also save a ParaView state to open in the GUI
Writes NAME-tNNNN.png per time (NAME.png for a single time). Nothing but
--help works without ParaView.
"""
import argparse
import math
import os
import re
import sys


def parse_arguments():
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("output_directory")
    parser.add_argument("--out")
    parser.add_argument("--times", default="contact")
    parser.add_argument("--warp", type=float, default=1.0)
    parser.add_argument("--size", default="1800x600")
    parser.add_argument("--name")
    parser.add_argument("--state")
    return parser.parse_args()


def read_parameters(path):
    """The entries of a parameters.prm as {'Contact/Obstacle/Model name': value}."""
    entries, sections = {}, []
    with open(path) as f:
        for line in f:
            line = line.split("#")[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end":
                sections.pop()
            elif line.startswith("set ") and "=" in line:
                key, value = line[4:].split("=", 1)
                entries["/".join(sections + [key.strip()])] = value.strip()
    return entries


def vector(text, dim):
    values = [float(x) for x in re.split(r"[,;]", text) if x.strip()]
    return (values + [0.0] * 3)[:3] if dim == 2 else values[:3]


def rigid_displacement(text, t):
    """The obstacle's displacement at time t (components separated by ';')."""
    names = {name: getattr(math, name) for name in dir(math)
             if not name.startswith("_")}
    # muparser's functions, as deal.II's FunctionParser knows them.
    names.update(t=t, min=min, max=max, abs=abs, ln=math.log, rint=round,
                 sign=lambda x: (x > 0) - (x < 0),
                 if_=lambda condition, a, b: a if condition else b)
    values = []
    for component in text.split(";"):
        expression = re.sub(r"\bif\s*\(", "if_(", component.replace("^", "**"))
        try:
            values.append(float(eval(expression, {"__builtins__": {}}, names)))
        except Exception:
            sys.exit(f"cannot evaluate the obstacle's Rigid displacement "
                     f"'{component.strip()}' at t = {t}")
    return (values + [0.0] * 3)[:3]


def obstacle_source(simple, entries, dim, t, bounds):
    """A ParaView source drawing the obstacle at time t, or None."""
    prefix = "Contact/Obstacle/"
    model = entries.get(prefix + "Model name", "plane")
    shift = rigid_displacement(entries.get(prefix + "Rigid displacement", "0"), t)
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2],
               bounds[5] - bounds[4], 1e-30)
    centre_of_body = [(bounds[0] + bounds[1]) / 2, (bounds[2] + bounds[3]) / 2,
                      (bounds[4] + bounds[5]) / 2]
    if model == "plane":
        point = vector(entries[prefix + "Plane/Point"], dim)
        normal = vector(entries[prefix + "Plane/Outward normal"], dim)
        point = [p + s for p, s in zip(point, shift)]
        # The foot of the body's centre on the plane, and two directions in it.
        length = math.sqrt(sum(n * n for n in normal))
        normal = [n / length for n in normal]
        offset = sum((c - p) * n for c, p, n in zip(centre_of_body, point, normal))
        foot = [c - offset * n for c, n in zip(centre_of_body, normal)]
        helper = [0, 0, 1] if abs(normal[2]) < 0.9 else [1, 0, 0]
        u = [normal[1] * helper[2] - normal[2] * helper[1],
             normal[2] * helper[0] - normal[0] * helper[2],
             normal[0] * helper[1] - normal[1] * helper[0]]
        length = math.sqrt(sum(x * x for x in u))
        u = [x / length * size for x in u]
        if dim == 2:
            return simple.Line(Point1=[f - x for f, x in zip(foot, u)],
                               Point2=[f + x for f, x in zip(foot, u)])
        v = [normal[1] * u[2] - normal[2] * u[1], normal[2] * u[0] - normal[0] * u[2],
             normal[0] * u[1] - normal[1] * u[0]]
        origin = [f - a - b for f, a, b in zip(foot, u, v)]
        return simple.Plane(Origin=origin,
                            Point1=[o + 2 * a for o, a in zip(origin, u)],
                            Point2=[o + 2 * b for o, b in zip(origin, v)])
    if model in ("sphere", "cylinder"):
        key = "Sphere/Center" if model == "sphere" else "Cylinder/Point on axis"
        centre = [c + s for c, s in zip(vector(entries[prefix + key], dim), shift)]
        radius = float(entries[prefix + model.capitalize() + "/Radius"])
        if dim == 2:
            return simple.Ellipse(Center=centre, Normal=[0, 0, 1],
                                  MajorRadiusVector=[radius, 0, 0], Ratio=1,
                                  SectorAngle=360, Resolution=180, Close=1)
        if model == "sphere":
            return simple.Sphere(Center=centre, Radius=radius,
                                 ThetaResolution=64, PhiResolution=64)
        axis = vector(entries.get(prefix + "Cylinder/Axis direction", "0,0,1"), dim)
        cylinder = simple.Cylinder(Radius=radius, Height=4 * size, Resolution=96)
        transform = simple.Transform(Input=cylinder)
        # ParaView's cylinder runs along y: turn y onto the axis.
        length = math.sqrt(sum(a * a for a in axis))
        axis = [a / length for a in axis]
        angle = math.degrees(math.acos(max(-1.0, min(1.0, axis[1]))))
        turn = [axis[2], 0.0, -axis[0]]  # y x axis
        transform.Transform.Translate = centre
        if angle > 1e-9 and any(abs(x) > 1e-12 for x in turn):
            transform.Transform.RotateWXYZ = [angle] + turn
        return transform
    return None


def frictionless(entries):
    """Whether no contact of the scene has friction (Contact/Friction
    coefficient 0 and no pair with its own)."""
    if float(entries.get("Contact/Friction coefficient", "0") or 0) > 0:
        return False
    for pair in entries.get("Contact/Pairs", "").split(","):
        parts = pair.split(":")
        if len(parts) > 2 and float(parts[2]) > 0:
            return False
    return True


def merged_by_body(simple, reader):
    """The reader's cells with coincident vertices merged within each body
    (the point field 'body'), not across bodies: each body is moved by
    1e-9 of the scene's size times its number before the merge."""
    reader.UpdatePipeline()
    if "body" not in reader.PointData.keys():
        return simple.CleantoGrid(Input=reader)
    bounds = reader.GetDataInformation().GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    apart = simple.Calculator(Input=reader, ResultArrayName="apart",
                              Function=f"coords + body * {1e-9 * size:.3e} * iHat",
                              CoordinateResults=1)
    return simple.CleantoGrid(Input=apart)


def times_to_render(reader, which, touching):
    available = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    if which == "contact":
        # Not the last time by default: a history may end unloaded (the
        # press-and-drag scene lifts its tool), with nothing to see.
        def touching_points(t):
            touching.UpdatePipeline(t)
            return touching.GetDataInformation().GetNumberOfPoints()
        counts = [(touching_points(t), t) for t in available]
        return [max(counts)[1]]
    if which == "last":
        return [available[-1]]
    if which == "all":
        return available
    wanted = [float(x) for x in which.split(",")]
    return [min(available, key=lambda a: abs(a - w)) for w in wanted]


def main():
    arguments = parse_arguments()
    directory = os.path.abspath(arguments.output_directory)
    pvd = os.path.join(directory, "solution.pvd")
    prm = os.path.join(directory, "parameters.prm")
    for path in (pvd, prm):
        if not os.path.exists(path):
            sys.exit(f"{path} is missing: give a run's output directory "
                     "(with Postprocess/Visualization/Write vtu = true)")
    try:
        from paraview import simple
    except ImportError:
        sys.exit("ParaView's Python is missing: run with pvbatch "
                 "(apt-get install paraview xvfb; scripts/headless.sh pvbatch ...)")

    entries = read_parameters(prm)
    dim = int(entries.get("Dimension", "2"))
    out = os.path.abspath(arguments.out or os.path.join(directory, "figures"))
    os.makedirs(out, exist_ok=True)
    name = arguments.name or os.path.basename(directory.rstrip("/"))
    width, height = (int(x) for x in arguments.size.split("x"))

    simple.LoadPalette("WhiteBackground")
    reader = simple.PVDReader(FileName=pvd)
    # deal.II writes the vertices of each cell separately: merge them, so
    # that the surface is the body's boundary, not every cell's; body by
    # body, so that two bodies touching at a vertex stay two.
    merged = merged_by_body(simple, reader)
    warped = simple.WarpByVector(Input=merged, Vectors=["POINTS", "displacement"],
                                 ScaleFactor=arguments.warp)
    # The boundary: faces in 3D, edges in 2D.
    surface = simple.ExtractSurface(Input=warped)
    if dim == 2:
        surface = simple.FeatureEdges(Input=surface, BoundaryEdges=1,
                                      FeatureEdges=0, NonManifoldEdges=0,
                                      ManifoldEdges=0)
    # Cells with a contact candidate (hanging vertices are not candidates,
    # so asking for all vertices would leave holes where the mesh is
    # refined), and those in contact, which the views 2 and 3 zoom on.
    face = simple.Threshold(Input=surface, Scalars=["POINTS", "contact_state"],
                            LowerThreshold=0, UpperThreshold=2,
                            ThresholdMethod="Between", AllScalars=0)
    touching = simple.Threshold(Input=face, Scalars=["POINTS", "contact_state"],
                                LowerThreshold=1, UpperThreshold=2,
                                ThresholdMethod="Between", AllScalars=0)

    # Three views side by side: split the layout's cell 0 at a third, then
    # its right part (cell 2) in halves (cells 5 and 6).
    layout = simple.CreateLayout(name)
    layout.SplitHorizontal(0, 1.0 / 3)
    layout.SplitHorizontal(2, 0.5)
    views = []
    for cell in (1, 5, 6):
        view = simple.CreateView("RenderView")
        # No axes triad: it sat on the legends.
        view.OrientationAxesVisibility = 0
        layout.AssignView(cell, view)
        views.append(view)

    # In 3D the body cut through the middle of its contact zone (the plane
    # y = const, the far half kept): what happens under the contact shows.
    # A body that flowed plastically is coloured by its equivalent plastic
    # strain, another by the von Mises stress.
    cut = None
    if dim == 3:
        cut = simple.Clip(Input=warped)
        cut.ClipType = "Plane"
        cut.ClipType.Normal = [0, 1, 0]
        cut.Crinkleclip = 0
        cut.Invert = 0
    field, field_title = "von_mises_stress", "von Mises stress"
    reader.UpdatePipeline(max(reader.TimestepValues) if reader.TimestepValues else 0)
    plastic = reader.PointData.GetArray("equivalent_plastic_strain")
    if plastic is not None and plastic.GetRange()[1] > 0:
        field, field_title = "equivalent_plastic_strain", "equivalent plastic strain"
    body = simple.Show(cut if cut is not None else warped, views[0])
    simple.ColorBy(body, ("POINTS", field))
    body.SetScalarBarVisibility(views[0], True)
    simple.GetScalarBar(simple.GetColorTransferFunction(field),
                        views[0]).Title = field_title
    pressure = simple.Show(face, views[1])
    simple.ColorBy(pressure, ("POINTS", "contact_pressure"))
    pressure.SetScalarBarVisibility(views[1], True)
    simple.GetScalarBar(simple.GetColorTransferFunction("contact_pressure"),
                        views[1]).Title = "contact pressure"
    # The contact state as categories: a dot per vertex of the face in the
    # colour of its state, over the face in grey (coloured as a field the
    # states blended between vertices into colours of no state). A view
    # shows a source once: the dots are of an identity transform of it.
    background = simple.Show(face, views[2])
    background.ColorArrayName = ["POINTS", ""]
    background.DiffuseColor = background.AmbientColor = [0.85, 0.85, 0.85]
    state = simple.Show(simple.Transform(Input=face), views[2])
    state.SetRepresentationType("Points")
    state.PointSize = 14 if dim == 2 else 9
    state.RenderPointsAsSpheres = 1
    simple.ColorBy(state, ("POINTS", "contact_state"))
    state_lut = simple.GetColorTransferFunction("contact_state")
    state_lut.InterpretValuesAsCategories = 1
    # -1: a vertex of the face that is not a candidate (a hanging vertex,
    # one on a fixed boundary). Without friction every node in contact
    # slips: "in contact".
    if frictionless(entries):
        state_lut.Annotations = ["-1", "not a candidate", "0", "free", "2", "in contact"]
        state_lut.IndexedColors = [0.92, 0.92, 0.85, 0.6, 0.6, 0.6, 0.9, 0.3, 0.1]
    else:
        state_lut.Annotations = ["-1", "not a candidate", "0", "free", "1", "stick",
                                 "2", "slip"]
        state_lut.IndexedColors = [0.92, 0.92, 0.85, 0.6, 0.6, 0.6, 0.1, 0.4, 0.9,
                                   0.9, 0.3, 0.1]
    state.SetScalarBarVisibility(views[2], True)
    simple.GetScalarBar(state_lut, views[2]).Title = "contact state"
    if dim == 2:
        # The contact boundary of a 2D body is a line: draw it thick.
        for display in (pressure, background):
            display.LineWidth = 12
            display.RenderLinesAsTubes = 1
    # Legends below the pictures, not over them.
    for function, view in ((simple.GetColorTransferFunction(field), views[0]),
                           (simple.GetColorTransferFunction("contact_pressure"), views[1]),
                           (state_lut, views[2])):
        bar = simple.GetScalarBar(function, view)
        bar.Orientation = "Horizontal"
        bar.WindowLocation = "Lower Center"
        bar.ScalarBarLength = 0.6
        # The ends of the range alone, in one format: ticks beside range
        # labels of another format collided ("0.3 3.9e-01").
        if function is not state_lut:
            bar.DrawTickLabels = 0
            bar.DrawTickMarks = 0
            bar.AddRangeLabels = 1
            bar.RangeLabelFormat = "%-#.2g"

    obstacle_display, obstacle = None, None
    # A rigid tool from a surface mesh: its surface where it stands at each
    # time (tool.pvd, written next to solution.pvd).
    tool_pvd = os.path.join(directory, "tool.pvd")
    if os.path.exists(tool_pvd):
        tool_display = simple.Show(simple.PVDReader(FileName=tool_pvd), views[0])
        tool_display.DiffuseColor = [0.45, 0.45, 0.45]
        tool_display.AmbientColor = [0.45, 0.45, 0.45]
        tool_display.Opacity = 0.5 if dim == 3 else 1.0
        tool_display.LineWidth = 4.0
    files = []
    chosen = times_to_render(reader, arguments.times, touching)
    for t in chosen:
        for view in views:
            view.ViewTime = t
        warped.UpdatePipeline(t)
        bounds = warped.GetDataInformation().GetBounds()
        if obstacle is not None:
            simple.Delete(obstacle)
        obstacle = obstacle_source(simple, entries, dim, t, bounds) \
            if entries.get("Contact/Contact boundaries", "").strip() else None
        if obstacle is not None and cut is not None:
            # Cut as the body is: a whole obstacle in front of the cut
            # hid what happens under it (step-42's plastic zone).
            obstacle = simple.Clip(Input=obstacle, ClipType="Plane", Crinkleclip=0,
                                   Invert=0)
            obstacle.ClipType.Normal = [0, 1, 0]
        if obstacle is not None:
            obstacle_display = simple.Show(obstacle, views[0])
            obstacle_display.DiffuseColor = [0.45, 0.45, 0.45]
            obstacle_display.Opacity = 0.5 if dim == 3 else 1.0
        # Views 2 and 3: the zone in contact with a margin of half its size
        # on each side (so that the free end of a pressed face shows),
        # within the candidate face.
        face.UpdatePipeline(t)
        touching.UpdatePipeline(t)
        (cut if cut is not None else warped).UpdatePipeline(t)
        # The colour ranges of this time (the face brought to it first).
        for display in (body, pressure):
            display.RescaleTransferFunctionToDataRange(False, True)
        zone = face.GetDataInformation().GetBounds() \
            if face.GetDataInformation().GetNumberOfCells() > 0 else bounds
        if cut is not None:
            middle = touching.GetDataInformation().GetBounds() \
                if touching.GetDataInformation().GetNumberOfCells() > 0 else bounds
            cut.ClipType.Origin = [0, 0.5 * (middle[2] + middle[3]), 0]
            if obstacle is not None:
                obstacle.ClipType.Origin = list(cut.ClipType.Origin)
        if touching.GetDataInformation().GetNumberOfCells() > 0:
            inner = touching.GetDataInformation().GetBounds()
            zone = [f(z, i + s * 0.5 * (inner[2 * k + 1] - inner[2 * k]))
                    for k in range(3)
                    for f, z, i, s in ((max, zone[2 * k], inner[2 * k], -1),
                                       (min, zone[2 * k + 1], inner[2 * k + 1], 1))]
        # View 1 of a 3D body: around the contact zone (three times its size,
        # within the body) where that is much smaller than the body, so that
        # what happens under the contact fills the picture.
        whole = bounds
        if dim == 3 and touching.GetDataInformation().GetNumberOfCells() > 0:
            inner = touching.GetDataInformation().GetBounds()
            size = max(inner[1] - inner[0], inner[3] - inner[2], inner[5] - inner[4])
            body_size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
            if 3 * size < body_size:
                whole = []
                for k in range(3):
                    middle = 0.5 * (inner[2 * k] + inner[2 * k + 1])
                    whole += [max(bounds[2 * k], middle - 1.5 * size),
                              min(bounds[2 * k + 1], middle + 1.5 * size)]
        for i, view in enumerate(views):
            view.InteractionMode = "2D" if dim == 2 else "3D"
            box = whole if i == 0 else zone
            centre = [0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]),
                      0.5 * (box[4] + box[5])]
            extent = max(box[1] - box[0], box[3] - box[2], box[5] - box[4], 1e-9)
            simple.ResetCamera(view)
            view.CameraFocalPoint = centre
            if dim == 2:
                view.CameraPosition = [centre[0], centre[1], 10 * extent]
                view.CameraViewUp = [0, 1, 0]
            elif i == 0:
                view.CameraPosition = [centre[0] + 2 * extent,
                                       centre[1] - 3 * extent,
                                       centre[2] + 1.5 * extent]
                view.CameraViewUp = [0, 0, 1]
            else:
                # The contact zone seen along its thinnest axis (its
                # normal), from the side on which the other two axes run
                # right and up as in a drawing of the body (x right: from
                # +z with y up, from -y with z up; y right: from +x with z
                # up): not mirrored against view 1.
                normal_axis = min(range(3), key=lambda k: box[2 * k + 1] - box[2 * k])
                up_axis = 1 if normal_axis == 2 else 2
                side = -1 if normal_axis == 1 else 1
                position = list(centre)
                position[normal_axis] = centre[normal_axis] + side * 10 * extent
                view.CameraPosition = position
                view.CameraViewUp = [1 if k == up_axis else 0 for k in range(3)]
            if i == 0 and dim == 3 and whole is not bounds:
                # The zoom on the contact zone, from the same side.
                view.CameraParallelProjection = 1
                view.CameraParallelScale = 0.6 * extent
            elif i == 0 and dim == 3:
                simple.ResetCamera(view)
                # Back off a little and lift the body above the legend.
                camera = view.GetActiveCamera()
                camera.Dolly(0.8)
                focal = list(view.CameraFocalPoint)
                position = list(view.CameraPosition)
                view.CameraFocalPoint = [focal[0], focal[1], focal[2] - 0.15 * extent]
                view.CameraPosition = [position[0], position[1],
                                       position[2] - 0.15 * extent]
            else:
                # Fit the box, with a margin and room for the legend below:
                # the panels are as wide as high.
                view.CameraParallelProjection = 1
                view.CameraParallelScale = 0.7 * extent
                # Moving the focal point down the screen's up axis moves
                # the picture up, above the legend.
                up = list(view.CameraViewUp)
                low = [c - 0.12 * extent * u for c, u in zip(centre, up)]
                position = [p - 0.12 * extent * u
                            for p, u in zip(view.CameraPosition, up)]
                view.CameraFocalPoint = low
                view.CameraPosition = position
        single = len(chosen) == 1
        file_name = os.path.join(out, f"{name}.png" if single else
                                 f"{name}-t{t:08.4f}.png")
        simple.SaveScreenshot(file_name, layout, ImageResolution=[width, height])
        files.append(file_name)
        print(f"wrote {file_name} (t = {t:g})")
    if arguments.state:
        simple.SaveState(os.path.abspath(arguments.state))
        print(f"wrote {arguments.state}")
    return 0


if __name__ == "__main__":
    code = main()
    # pvbatch under Xvfb fails with an X error while it tears its OpenGL
    # context down, after everything is written: leave without the
    # teardown, with the script's own exit code.
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)
