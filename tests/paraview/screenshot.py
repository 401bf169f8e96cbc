"""A pvbatch screenshot of the plugin's streamlines through the real Enzo sample, compared with a
reference image: ParaView's Enzo reader, the AMR Stream Tracer from a Line source (CPU backend),
tubes coloured by speed over the AMR blocks' outline. Run by pvbatch:

    pvbatch screenshot.py DATA OUT REFERENCE

writes OUT/enzo_streamlines.png and fails when it differs from REFERENCE by more than a
tolerance (rasterisers differ a little between machines); with REFERENCE '-' it only writes."""

import os
import sys

import numpy
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

import amrstream

DATA, OUT, REFERENCE = sys.argv[1:4]
PLUGIN = os.path.join(os.path.dirname(amrstream.__file__), "paraview_plugin",
                      "amrstream_paraview.xml")
SIZE = [800, 600]
# The largest mean difference per channel (of 255), and share of pixels allowed to differ by
# more than 64 in some channel.
MEAN_TOLERANCE = 2.0
OUTLIER_SHARE = 0.01


def render(path):
    if not hasattr(simple, "AMRStreamTraceramrstream"):
        simple.LoadPlugin(PLUGIN, ns=vars(simple))
    enzo = os.path.join(DATA, "enzo-moving7", "DD0010", "moving7_0010.hierarchy")
    reader = simple.EnzoReader(FileNames=[enzo])
    reader.CellArrayStatus = ["x-velocity", "y-velocity", "z-velocity", "Density"]
    reader.ConvertToCGS = 0
    reader.Level = 100
    seeds = simple.Plane(Origin=[0.735, 0.735, 0.75], Point1=[0.765, 0.735, 0.75],
                         Point2=[0.735, 0.765, 0.75], XResolution=7, YResolution=7)
    tracer = simple.AMRStreamTraceramrstream(Input=reader, SeedSource=seeds, Backend="cpu",
                                             Periodic="none", FrameVelocity="auto",
                                             MaximumSteps=3000, MaximumStreamlineLength=0.05)
    tubes = simple.Tube(Input=tracer, Radius=0.0004, NumberofSides=10)
    cut = simple.Slice(Input=reader)
    cut.SliceType.Origin = [0.75, 0.75, 0.75]
    cut.SliceType.Normal = [0, 0, 1]
    view = simple.CreateView("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    density = simple.Show(cut, view)
    simple.ColorBy(density, ("CELLS", "Density"))
    density_colours = simple.GetColorTransferFunction("Density")
    density_colours.ApplyPreset("Grayscale", True)
    density.RescaleTransferFunctionToDataRange(True, False)
    density_colours.MapControlPointsToLogSpace()
    density_colours.UseLogScale = 1
    shown = simple.Show(tubes, view)
    simple.ColorBy(shown, ("POINTS", "Speed"))
    simple.GetColorTransferFunction("Speed").ApplyPreset("Viridis (matplotlib)", True)
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)
    bar = simple.GetScalarBar(simple.GetColorTransferFunction("Speed"), view)
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    simple.Render(view)  # the first render frames everything; the camera is set after it
    view.CameraPosition = [0.81, 0.67, 0.83]
    view.CameraFocalPoint = [0.75, 0.75, 0.75]
    view.CameraViewUp = [0, 0, 1]
    view.CameraViewAngle = 30
    simple.Render(view)
    simple.SaveScreenshot(path, view, ImageResolution=SIZE)


def pixels(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    values = vtk_to_numpy(image.GetPointData().GetScalars())
    return image.GetDimensions()[:2], values[:, :3].astype(numpy.int16)


def main():
    if not os.path.isdir(DATA):
        print(f"real data {DATA} is absent: skipped")
        sys.exit(77)
    os.makedirs(OUT, exist_ok=True)
    path = os.path.join(OUT, "enzo_streamlines.png")
    render(path)
    print(f"wrote {path}")
    if REFERENCE == "-":
        return
    (size, mine), (reference_size, theirs) = pixels(path), pixels(REFERENCE)
    assert size == reference_size, f"the screenshot is {size}, the reference {reference_size}"
    difference = numpy.abs(mine - theirs)
    mean = float(difference.mean())
    outliers = float((difference.max(axis=1) > 64).mean())
    covered = float((theirs.min(axis=1) < 200).mean())
    print(f"mean difference {mean:.3f} of 255, {outliers:.4%} of pixels differ by more than 64; "
          f"{covered:.1%} of the reference's pixels are not background")
    assert covered > 0.02, "the reference shows almost nothing"
    assert mean <= MEAN_TOLERANCE, f"the screenshot differs from {REFERENCE}: mean {mean:.3f}"
    assert outliers <= OUTLIER_SHARE, f"the screenshot differs from {REFERENCE}: {outliers:.4%}"


if __name__ == "__main__":
    main()
