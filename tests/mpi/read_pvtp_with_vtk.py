"""Reads a .pvtp with VTK's vtkXMLPPolyDataReader (as ParaView does), or a .vtp with
vtkXMLPolyDataReader, and prints its polylines, points and point arrays:
"lines points name,name,..."."""
import sys

import vtk

parallel = sys.argv[1].endswith(".pvtp")
reader = vtk.vtkXMLPPolyDataReader() if parallel else vtk.vtkXMLPolyDataReader()
reader.SetFileName(sys.argv[1])
reader.Update()
data = reader.GetOutput()
names = [data.GetPointData().GetArrayName(i) for i in range(data.GetPointData().GetNumberOfArrays())]
print(data.GetNumberOfLines(), data.GetNumberOfPoints(), ",".join(names))
