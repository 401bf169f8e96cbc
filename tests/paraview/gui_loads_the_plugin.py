"""The ParaView GUI, started by `python -m amrstream paraview --script=THIS --exit`, has loaded the
plugin: its reader and filter trace the Gerris sample and the lines are shown. Prints 'the GUI
traced N points' (CTest looks for it); the data folder comes from $AMRSTREAM_SHARED_DATA."""
import os

from paraview import simple

gerris = os.path.join(os.environ["AMRSTREAM_SHARED_DATA"], "gerris-ring", "ring-end.txt")
if not os.path.exists(gerris):
    print(f"real data {gerris} is absent: skipped")
else:
    reader = simple.amrstreamAMRReader(FileName=gerris)
    seeds = simple.Line(Point1=[-0.3, -0.2, -0.1], Point2=[0.3, 0.2, 0.1], Resolution=15)
    lines = simple.AMRStreamTraceramrstream(Input=reader, SeedSource=seeds, Backend="cpu")
    simple.Show(lines)
    simple.Render()
    print(f"the GUI traced {lines.GetDataInformation().GetNumberOfPoints()} points")
