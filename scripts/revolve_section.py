#!/usr/bin/env python3
"""Shows an axisymmetric run (<Material/Two-dimensional model> =
axisymmetric: the section x = r, y the axis) as the bodies of revolution
it stands for: the deformed section turned about its axis by ParaView's
Rotational Extrusion (three quarters of a turn, so that the section
shows), coloured by a field, one PNG of the last time.

The same in ParaView's window: open solution.pvd, Apply; Warp By Vector
(displacement); Transform with Rotate 90, 0, 0 (the axis y onto z, about
which Rotational Extrusion turns); Extract Surface; Rotational Extrusion
with Resolution 48 and Angle 270; colour by the field.

Run it with ParaView's Python on a virtual display:

  scripts/headless.sh pvbatch --no-mpi scripts/revolve_section.py OUTPUT_DIR [options]

Options:
  --out DIR      where the PNG goes (default OUTPUT_DIR/figures)
  --name NAME    file name stem (default: the folder's name, with -revolved)
  --size WxH     image size in pixels (default 900x700)
  --field NAME   the point field to colour by (default von_mises_stress)
"""
import argparse
import os
import sys


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    parser.add_argument("output_directory")
    parser.add_argument("--out")
    parser.add_argument("--name")
    parser.add_argument("--size", default="900x700")
    parser.add_argument("--field", default="von_mises_stress")
    args = parser.parse_args()
    directory = os.path.abspath(args.output_directory)
    pvd = os.path.join(directory, "solution.pvd")
    if not os.path.isfile(pvd):
        sys.exit(f"no {pvd}: run the scene with <Postprocess/Visualization/Write vtu> = true")
    out = args.out or os.path.join(directory, "figures")
    os.makedirs(out, exist_ok=True)
    name = args.name or os.path.basename(directory) + "-revolved"
    try:
        from paraview.simple import (ColorBy, ExtractSurface, GetActiveViewOrCreate,
                                     PVDReader, Render, RotationalExtrusion, SaveScreenshot,
                                     Show, Transform, WarpByVector)
    except ImportError:
        sys.exit("ParaView's Python is missing: run with pvbatch "
                 "(apt-get install paraview xvfb; scripts/headless.sh pvbatch ...)")

    reader = PVDReader(FileName=pvd)
    reader.UpdatePipeline(max(reader.TimestepValues or [0]))
    warped = WarpByVector(Input=reader)
    warped.Vectors = ["POINTS", "displacement"]
    turned = Transform(Input=warped)
    turned.Transform.Rotate = [90, 0, 0]
    revolved = RotationalExtrusion(Input=ExtractSurface(Input=turned))
    revolved.Resolution = 48
    revolved.Angle = 270

    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [int(v) for v in args.size.split("x")]
    view.ViewTime = max(reader.TimestepValues or [0])
    view.OrientationAxesVisibility = 0
    display = Show(revolved, view)
    ColorBy(display, ("POINTS", args.field))
    display.RescaleTransferFunctionToDataRange(True)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [2, -3, 2]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 0, 1]
    view.ResetCamera(False)
    Render(view)
    path = os.path.join(out, name + ".png")
    SaveScreenshot(path, view)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
