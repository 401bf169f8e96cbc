"""The ParaView plugin's AMR Stream Tracer equals `amrstream trace` bit for bit on the CPU backend:
on the real Enzo and AMReX samples read by ParaView's own readers, and on the FLASH and Gerris
samples read by the plugin's amrstream AMR Reader, from the same seeds (a ParaView Line source's points,
written for the CLI's --seeds). Run by pvpython:

    pvpython trace_like_the_cli.py CLI DATA OUT

CLI is the amrstream binary, DATA the folder of the real data sets, OUT a scratch folder. Exits
non-zero naming the first difference; prints what it compared. amrstream must be importable (the
ctest wrapper sets PYTHONPATH)."""

import ast
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import numpy
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

import amrstream
from amrstream import paraview_filters, vtk_amr

CLI, DATA, OUT = sys.argv[1:4]
PLUGIN = os.path.join(os.path.dirname(amrstream.__file__), "paraview_plugin",
                      "amrstream_paraview.xml")
# FieldData the plugin cannot know as the CLI does (ParaView's readers do not pass them on).
FILE_ONLY = {"Input", "InputFormat", "Seeds", "SimulationTime", "TimeUnit", "LengthUnit"}


def plugin_proxy(name):
    """The constructor of one of the plugin's proxies in paraview.simple, loading the plugin
    unless ParaView did (`python -m amrstream pvpython` starts it so)."""
    if not hasattr(simple, name):
        simple.LoadPlugin(PLUGIN, ns=vars(simple))
    return getattr(simple, name)


def read_vtp(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def arrays(attributes):
    return {attributes.GetArrayName(i): vtk_to_numpy(attributes.GetArray(i))
            for i in range(attributes.GetNumberOfArrays())}


def field_data(polydata):
    data = polydata.GetFieldData()
    found = {}
    for i in range(data.GetNumberOfArrays()):
        array = data.GetAbstractArray(i)
        found[array.GetName()] = [array.GetVariantValue(j).ToString()
                                  for j in range(array.GetNumberOfValues())]
    return found


def assert_same(case, plugin_path, cli_path):
    plugin, cli = read_vtp(plugin_path), read_vtp(cli_path)
    assert cli.GetNumberOfLines() > 0, f"{case}: the CLI traced no lines"
    assert plugin.GetNumberOfPoints() == cli.GetNumberOfPoints(), (
        f"{case}: {plugin.GetNumberOfPoints()} points, the CLI {cli.GetNumberOfPoints()}")
    assert numpy.array_equal(vtk_to_numpy(plugin.GetPoints().GetData()),
                             vtk_to_numpy(cli.GetPoints().GetData())), f"{case}: points differ"
    assert numpy.array_equal(vtk_to_numpy(plugin.GetLines().GetData()),
                             vtk_to_numpy(cli.GetLines().GetData())), f"{case}: lines differ"
    for kind in ("GetPointData", "GetCellData"):
        mine, theirs = arrays(getattr(plugin, kind)()), arrays(getattr(cli, kind)())
        assert sorted(mine) == sorted(theirs), f"{case}: {kind} arrays {sorted(mine)} vs {sorted(theirs)}"
        for name in theirs:
            assert mine[name].dtype == theirs[name].dtype, f"{case}: {name} type differs"
            assert numpy.array_equal(mine[name], theirs[name], equal_nan=True), (
                f"{case}: {name} differs")
    mine, theirs = field_data(plugin), field_data(cli)
    for name, value in theirs.items():
        if name not in FILE_ONLY:
            assert mine.get(name) == value, f"{case}: FieldData {name}: {mine.get(name)} vs {value}"
    print(f"{case}: {cli.GetNumberOfLines()} lines, {cli.GetNumberOfPoints()} points, "
          f"{len(arrays(cli.GetPointData()))} point arrays: equal to the CLI's")


def trace_both(case, reader, data_path, point1, point2, plugin_settings, cli_options):
    """Traces with the plugin and with the CLI from a Line source's 16 points."""
    line = simple.Line(Point1=point1, Point2=point2, Resolution=15)
    line.UpdatePipeline()
    seeds = vtk_to_numpy(line.GetClientSideObject().GetOutput().GetPoints().GetData())
    seeds_path = os.path.join(OUT, f"{case}_seeds.txt")
    with open(seeds_path, "w") as file:
        for point in seeds.astype(numpy.float64):
            file.write(" ".join(repr(float(x)) for x in point) + "\n")
    tracer = plugin_proxy("AMRStreamTraceramrstream")(Input=reader, SeedSource=line,
                                                      Backend="cpu", **plugin_settings)
    tracer.UpdatePipeline()
    plugin_path = os.path.join(OUT, f"{case}_plugin.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(plugin_path)
    writer.SetInputData(tracer.GetClientSideObject().GetOutputDataObject(0))
    assert writer.Write() == 1, f"{case}: writing {plugin_path} failed"
    cli_path = os.path.join(OUT, f"{case}_cli.vtp")
    subprocess.run([CLI, "trace", data_path, "--seeds", seeds_path, "--backend", "cpu",
                    "--out", cli_path, *cli_options], check=True, stdout=subprocess.DEVNULL)
    assert_same(case, plugin_path, cli_path)


def check_property_defaults():
    """The plugin's property defaults are amrstream.trace()'s (the library's settings'; where
    trace's is None, the dataset's own: prepare()'s)."""
    library = {}
    for function in (amrstream._amrstream.prepare, amrstream._amrstream.trace):
        first = function.__doc__.splitlines()[0]
        for name, value in re.findall(r"(\w+): (?:[^=,\[]|\[[^\]]*\])+ = ('[^']*'|[^,)]+)",
                                      first):
            if ast.literal_eval(value) is not None or name not in library:
                library[name] = ast.literal_eval(value)
    proxy = next(element for element in ElementTree.parse(PLUGIN).iter("SourceProxy")
                 if element.get("name") == "AMRStreamTracerAmrstream")
    for element in proxy:
        name = element.get("name")
        if name not in paraview_filters._PROPERTIES:
            continue
        keyword, convert, default = paraview_filters._PROPERTIES[name]
        text = element.get("default_values", "")
        value = convert(int(text) if element.tag == "IntVectorProperty" else
                        float(text) if element.tag == "DoubleVectorProperty" else text)
        assert value == default, f"{name}: the XML's default gives {value!r}, the filter's {default!r}"
        if keyword in library and keyword != "step_size":  # step_size's default depends on mode
            assert value == library[keyword] or (
                isinstance(value, float) and abs(value - library[keyword]) <= 1e-9 * abs(value)), (
                f"{name}: the plugin's default {value!r}, amrstream.trace's {library[keyword]!r}")
    print(f"{len(paraview_filters._PROPERTIES)} properties: defaults as amrstream.trace's")


def check_leaf_cells_of_paraviews_enzo_reader(reader, path):
    """vtk_amr.leaf_cells of ParaView's Enzo reader: the cells and values amrstream.load reads."""
    reader.UpdatePipeline()
    cells = vtk_amr.leaf_cells(reader.GetClientSideObject().GetOutputDataObject(0))
    dataset = amrstream.load(path)

    def order(corners, levels):
        return numpy.lexsort((levels, corners[:, 2], corners[:, 1], corners[:, 0]))

    mine = order(cells["corners"], cells["levels"])
    theirs = order(dataset.corners, dataset.levels)
    assert len(mine) == len(theirs) == dataset.cell_count
    assert numpy.array_equal(cells["corners"][mine], dataset.corners[theirs])
    assert numpy.array_equal(cells["levels"][mine], dataset.levels[theirs])
    for name in dataset.field_names:
        assert numpy.array_equal(cells["fields"][name][mine].astype(numpy.float32),
                                 dataset.field(name)[theirs]), name
    print(f"ParaView's Enzo reader: {dataset.cell_count} leaf cells, as amrstream.load reads them")


def check_leaf_cells_of_a_gaussian_pulse(dimension):
    """vtk_amr.leaf_cells of VTK's AMR Gaussian pulse (2D and 3D): every leaf cell's corner, level
    and width put its centre where the source's own Centroid array says; the leaves tile the
    domain once; 2D data become a slab as thick as the coarsest leaf, finer cells repeated."""
    source = simple.AMRGaussianPulseSource(Dimension=dimension)
    source.UpdatePipeline()
    cells = vtk_amr.leaf_cells(source.GetClientSideObject().GetOutputDataObject(0))
    finest = max(cells["levels"])
    widths = numpy.left_shift(1, finest - cells["levels"])[:, None] * numpy.array(
        cells["finest_width"])
    centres = numpy.array(cells["origin"]) + (cells["corners"] + 0.5 * numpy.left_shift(
        1, finest - cells["levels"])[:, None]) * numpy.array(cells["finest_width"])
    axes = range(dimension)
    for axis, suffix in zip(axes, "XYZ"):
        assert numpy.allclose(centres[:, axis], cells["fields"]["Centroid_" + suffix],
                              rtol=0, atol=1e-12), f"{dimension}D: centres along {suffix}"
    dataset = amrstream.from_arrays(**cells)
    extent = numpy.array(dataset.domain_right_edge) - numpy.array(dataset.domain_left_edge)
    assert numpy.isclose(numpy.prod(widths, axis=1).sum(), numpy.prod(extent)), "the tiling"
    if dimension == 2:
        coarsest = widths[:, 0].max()
        assert numpy.isclose(extent[2], coarsest), "the slab's thickness"
    print(f"{dimension}D Gaussian pulse: {len(cells['levels'])} leaf cells where its centroids "
          "say, tiling the domain once")


def main():
    if not os.path.isdir(DATA):
        print(f"real data {DATA} is absent: skipped")
        sys.exit(77)
    os.makedirs(OUT, exist_ok=True)
    check_property_defaults()
    check_leaf_cells_of_a_gaussian_pulse(2)
    check_leaf_cells_of_a_gaussian_pulse(3)

    enzo = os.path.join(DATA, "enzo-moving7", "DD0010", "moving7_0010")
    reader = simple.EnzoReader(FileNames=[enzo + ".hierarchy"])
    reader.CellArrayStatus = reader.CellArrayStatus.Available
    reader.ConvertToCGS = 0  # the file's code units, as the CLI reads them
    reader.Level = 100       # every level (ParaView loads two by default)
    check_leaf_cells_of_paraviews_enzo_reader(reader, enzo)
    trace_both("enzo", reader, enzo, [0.6, 0.62, 0.64], [0.8, 0.79, 0.78],
               {"Periodic": "x,y,z", "MaximumSteps": 400}, ["--steps", "400"])

    amrex = os.path.join(DATA, "amrex-pelelmex-3d", "example_plt_3d")
    reader = simple.AMReXBoxLibGridReader(FileNames=[amrex])
    reader.CellArrayStatus = ["x_velocity", "y_velocity", "z_velocity", "density", "temp"]
    reader.Level = 100
    trace_both("amrex", reader, amrex, [0.002, 0.003, 0.004], [0.014, 0.013, 0.012],
               {"Periodic": "none", "IntegratorType": "Runge-Kutta 4-5"},
               ["--periodic", "none", "--point-data", "density,temp", "--integrator", "rk45"])

    # ParaView 5.11's FLASH reader makes no blocks of this 2D file ("Inconsistent types of
    # vtkUniformGrid"); the plugin's reader reads it as the CLI does (a slab). It holds no vector
    # field: three of its scalars exercise the path.
    flash = os.path.join(DATA, "flash-2d-nanowire", "nanowire_arrayhdf5_plt_cnt_0100")
    reader = plugin_proxy("amrstreamAMRReader")(FileName=flash)
    trace_both("flash", reader, flash, [-5e-5, 5e-4, 3.9e-7], [5e-5, 1.5e-3, 3.9e-7],
               {"Vectors": "tele,tion,depo", "MaximumSteps": 300},
               ["--vector", "tele,tion,depo", "--steps", "300"])

    gerris = os.path.join(DATA, "gerris-ring", "ring-end.txt")
    reader = plugin_proxy("amrstreamAMRReader")(FileName=gerris)
    trace_both("gerris", reader, gerris, [-0.3, -0.2, -0.1], [0.3, 0.2, 0.1],
               {"IntegrationDirection": "FORWARD", "Interpolant": "linear"},
               ["--direction", "forward", "--interpolant", "linear"])


if __name__ == "__main__":
    main()
