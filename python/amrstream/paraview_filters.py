"""The algorithms of amrstream's ParaView plugin (amrstream_paraview.xml declares them and their
properties to ParaView): the filter "AMR Stream Tracer (amrstream)", streamlines through a
vtkOverlappingAMR (ParaView's FLASH, Enzo and AMReX readers make one) from the points of a second
input, reconstructed across levels as amrstream does; and the reader "amrstream AMR Reader" for
the formats ParaView lacks (ExaBricks .exa, Gerris text dumps) and any other amrstream reads.

ParaView creates them by name (amrstream.paraview_filters.AMRStreamTracer), so amrstream must be
importable in its Python: `python -m amrstream paraview` starts ParaView so."""

import os
import tempfile

from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase

import amrstream
from amrstream import vtk_amr

_DIRECTIONS = ("forward", "backward", "both")           # vtkStreamTracer's order
_INTEGRATORS = ("rk2", "rk4", "rk45", "euler")          # vtkStreamTracer's first three
_STEP_UNITS = ("arc", "cell", "time")
_INTERPOLANTS = ("tent", "linear")
_BACKENDS = ("auto", "cpu", "rayquery", "pipeline", "compute")


# The filter's properties (amrstream_paraview.xml), each setting a keyword of amrstream.trace():
# {property: (keyword, the property's value -> the keyword's, the keyword's default)}.
_PROPERTIES = {
    "Vectors": ("vector", lambda text: text or None, None),
    "FrameVelocity": ("frame_velocity", lambda text: text or None, None),
    "IntegrationDirection": ("direction", _DIRECTIONS.__getitem__, "both"),
    "IntegrationStepUnit": ("step_mode", _STEP_UNITS.__getitem__, "arc"),
    "InitialStepLength": ("step_size", lambda value: value or None, 0.25),
    "MaximumSteps": ("steps", int, 1000),
    "MaximumStreamlineLength": ("max_length", float, 0.0),
    "MaximumIntegrationTime": ("max_time", float, 0.0),
    "IntegratorType": ("integrator", _INTEGRATORS.__getitem__, "rk4"),
    "MaximumError": ("tolerance", float, 1e-4),
    "TerminalSpeed": ("terminal_speed", float, 1e-12),
    "Interpolant": ("interpolant", _INTERPOLANTS.__getitem__, "tent"),
    "Periodic": ("periodic", str, "auto"),
    "PointData": ("point_data", str, "all"),
    "ComputeVorticity": ("vorticity", bool, False),
    "Backend": ("backend", _BACKENDS.__getitem__, "auto"),
}


def seed_points(data):
    """The points of a vtkDataSet, or of every dataset in a composite one, as an (N, 3) array."""
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    if data is None:
        raise ValueError("the Seeds input is missing: connect a point or line source, or any "
                         "dataset whose points are the seeds")
    if data.IsA("vtkCompositeDataSet"):
        blocks = []
        iterator = data.NewIterator()
        iterator.InitTraversal()
        while not iterator.IsDoneWithTraversal():
            blocks.append(seed_points(iterator.GetCurrentDataObject()))
            iterator.GoToNextItem()
        return numpy.concatenate(blocks) if blocks else numpy.zeros((0, 3))
    points = data.GetPoints() if hasattr(data, "GetPoints") else None
    if points is None or points.GetNumberOfPoints() == 0:
        if hasattr(data, "GetNumberOfPoints") and data.GetNumberOfPoints() > 0:
            return numpy.array([data.GetPoint(i) for i in range(data.GetNumberOfPoints())])
        return numpy.zeros((0, 3))
    return vtk_to_numpy(points.GetData()).astype(numpy.float64)


def _report(text, error=False, source="AMR Stream Tracer (amrstream)"):
    """A warning or error in ParaView's Output Messages."""
    from vtkmodules.vtkCommonCore import vtkOutputWindow

    window = vtkOutputWindow.GetInstance()
    show = window.DisplayErrorText if error else window.DisplayWarningText
    show(f"{source}: {text}\n")


def _copy_traces(traces, output):
    """The .vtp `amrstream trace` writes, read back into `output` (arrays and FieldData)."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    with tempfile.TemporaryDirectory(prefix="amrstream-paraview-") as folder:
        path = os.path.join(folder, "traces.vtp")
        traces.to_vtp(path, compression="none")
        reader = vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        output.ShallowCopy(reader.GetOutput())


class AMRStreamTracer(VTKPythonAlgorithmBase):
    """Streamlines through cell-centred AMR data with amrstream's reconstruction across levels
    (ParaView's Stream Tracer holds each cell's vector constant). The output is the polydata
    `amrstream trace` writes: IntegrationTime, the vector, the point data, the lines' seeds,
    steps and ReasonForTermination, and the run's provenance as FieldData."""

    def __init__(self):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=2, nOutputPorts=1,
                                        outputType="vtkPolyData")
        self.settings = {keyword: default for keyword, _, default in _PROPERTIES.values()}
        self._dataset = None  # (the input, its modification time, its amrstream Dataset)

    def FillInputPortInformation(self, port, info):
        info.Set(self.INPUT_REQUIRED_DATA_TYPE(),
                 "vtkOverlappingAMR" if port == 0 else "vtkDataObject")
        return 1

    def RequestData(self, request, inInfoVec, outInfoVec):
        from vtkmodules.vtkCommonDataModel import vtkDataObject, vtkOverlappingAMR, vtkPolyData

        amr = vtkOverlappingAMR.GetData(inInfoVec[0], 0)
        try:
            seeds = seed_points(vtkDataObject.GetData(inInfoVec[1], 0))
            if len(seeds) == 0:
                raise ValueError("the Seed Source has no points")
            traces = amrstream.trace(
                self._dataset_of(amr), seeds,
                progress=lambda done, total: self.UpdateProgress(done / max(total, 1)),
                **self.settings)
        except (amrstream.InputError, amrstream.BackendError, ValueError) as error:
            _report(str(error), error=True)
            return 0
        _copy_traces(traces, vtkPolyData.GetData(outInfoVec, 0))
        return 1

    def _dataset_of(self, amr):
        """dataset_of(amr), kept while the input is unchanged (a property changed alone)."""
        if self._dataset is None or self._dataset[0] is not amr or \
                self._dataset[1] != amr.GetMTime():
            self._dataset = (amr, amr.GetMTime(), dataset_of(amr))
        return self._dataset[2]


def _setter(name):
    keyword, convert, _ = _PROPERTIES[name]

    def set_property(self, value):
        value = convert(value)
        if self.settings[keyword] != value:
            self.settings[keyword] = value
            self.Modified()

    set_property.__name__ = "Set" + name
    return set_property


for _name in _PROPERTIES:
    setattr(AMRStreamTracer, "Set" + _name, _setter(_name))


def dataset_of(amr):
    """An amrstream Dataset of a vtkOverlappingAMR's leaf cells, with what the amrstream
    reader's FieldData says of its source, periodicity and units."""
    unread = [level for level in range(amr.GetNumberOfLevels())
              if amr.GetNumberOfDataSets(level) > 0
              and all(amr.GetDataSet(level, i) is None
                      for i in range(amr.GetNumberOfDataSets(level)))]
    if unread:
        _report(f"the reader left out the blocks of levels {unread[0]} to {unread[-1]}: raise "
                "its Level to trace through them")
    cells = vtk_amr.leaf_cells(amr)
    described = vtk_amr.described(amr)
    described.setdefault("source", "ParaView vtkOverlappingAMR")
    return amrstream.from_arrays(format="vtkOverlappingAMR", **{**cells, **described})


class AmrstreamReader(VTKPythonAlgorithmBase):
    """Any file `amrstream trace` reads, as a vtkOverlappingAMR of its leaf cells in blocks of
    8^3, with its source, periodic axes and length unit as FieldData (which the AMR Stream
    Tracer uses)."""

    def __init__(self):
        VTKPythonAlgorithmBase.__init__(self, nInputPorts=0, nOutputPorts=1,
                                        outputType="vtkOverlappingAMR")
        self.file_name = None

    def SetFileName(self, name):
        if self.file_name != name:
            self.file_name = name
            self.Modified()

    def RequestData(self, request, inInfoVec, outInfoVec):
        from vtkmodules.vtkCommonDataModel import vtkOverlappingAMR

        try:
            if not self.file_name:
                raise ValueError("no file name given")
            amr = vtk_amr.overlapping_amr(amrstream.load(self.file_name))
        except (OSError, amrstream.InputError, ValueError) as error:
            _report(str(error), error=True, source="amrstream AMR Reader")
            return 0
        vtkOverlappingAMR.GetData(outInfoVec, 0).ShallowCopy(amr)
        return 1
