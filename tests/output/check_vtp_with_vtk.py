#!/usr/bin/python3
"""Checks that VTK itself reads a .vtp written by amrstream.

Run with Debian's /usr/bin/python3 (python3-vtk9):

  check_vtp_with_vtk.py FILE --points N --lines M \
      [--point-array NAME:COMPONENTS]... [--cell-array NAME:COMPONENTS]... \
      [--line-lengths 3,2,5,2] [--repeated-lines 1,...] [--scalars NAME] [--vectors NAME] \
      [--speed-of NAME] [--seed-ids] [--both-directions SEEDS] [--field-text NAME=VALUE]... \
      [--points-type Float32|Float64] [--points-file POINTS]

Fails (exit 1, one line per problem) when vtkXMLPolyDataReader reports an error or warning,
when the counts differ, when an array is missing or has other components, when a line has fewer
than 2 points, and, with --line-lengths, when the lines (walked with GetCellPoints) have other
lengths; with --repeated-lines, when those lines are not 2 copies of one point (coordinates and
every point array equal); with --speed-of, when the point array "Speed" is not the magnitude of
that vector array, with --seed-ids, when the cell array SeedIds is not 0 .. lines-1, and with
--both-directions SEEDS, when the lines are not vtkStreamTracer's BOTH layout: SeedIds 0 .. SEEDS-1
for the forward lines (IntegrationTime >= 0), then again for the backward ones (<= 0), each line
starting at IntegrationTime 0; with --field-text, when the FieldData string array NAME does not
hold VALUE; with --points-type, when VTK holds the points in another type; with --points-file,
when the points are not exactly those of POINTS, one "x y z" line each.

Lines of 0 or 1 point are reported without asking VTK for their points: vtkPolyData refuses to
build its cell map for them ("Invalid cell size for lines") and VTK 9.1 then crashes in
GetCellPoints.
"""

import argparse
import math
import sys

try:
    import vtk
except ImportError as error:
    sys.exit(f"check_vtp_with_vtk: cannot import vtk ({error}); "
             "run scripts/install_deps.sh (python3-vtk9) and use /usr/bin/python3")


POINT_TYPES = {"Float32": vtk.VTK_FLOAT, "Float64": vtk.VTK_DOUBLE}


def array_spec(text):
    name, _, components = text.rpartition(":")
    if not name or not components.isdigit():
        raise argparse.ArgumentTypeError(f"expected NAME:COMPONENTS, got {text!r}")
    return name, int(components)


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--points", type=int, required=True)
    parser.add_argument("--lines", type=int, required=True)
    parser.add_argument("--point-array", type=array_spec, action="append", default=[])
    parser.add_argument("--cell-array", type=array_spec, action="append", default=[])
    parser.add_argument("--line-lengths", help="comma-separated point count of each line")
    parser.add_argument("--repeated-lines",
                        help="comma-separated indices of lines that repeat a single point")
    parser.add_argument("--scalars", help="expected active point scalars")
    parser.add_argument("--vectors", help="expected active point vectors")
    parser.add_argument("--speed-of", help="vector array whose magnitude Speed must be")
    parser.add_argument("--seed-ids", action="store_true",
                        help="cell array SeedIds must be 0, 1, ... lines-1")
    parser.add_argument("--field-text", action="append", default=[], metavar="NAME=VALUE",
                        help="a FieldData string array and its value")
    parser.add_argument("--both-directions", type=int, metavar="SEEDS",
                        help="lines are SEEDS forward lines, then SEEDS backward ones")
    parser.add_argument("--points-type", choices=sorted(POINT_TYPES),
                        help="the type VTK must hold the points in")
    parser.add_argument("--points-file", help="the exact points, one 'x y z' line each")
    return parser.parse_args()


class Messages:
    """Collects errors and warnings VTK reports, from observers and from its output window."""

    def __init__(self):
        self.reported = []
        self.window = vtk.vtkStringOutputWindow()
        vtk.vtkOutputWindow.SetInstance(self.window)

    def observe(self, vtk_object):
        for event in ("ErrorEvent", "WarningEvent"):
            vtk_object.AddObserver(event, self._on_event)

    def _on_event(self, caller, event):
        self.reported.append(f"{event} from {caller.GetClassName()}")

    def all(self):
        text = self.window.GetOutput().strip()
        return self.reported + ([text] if text else [])


def check_repeated(output, first_line, line):
    """Problems unless line `line` holds two copies of one point, point data included."""
    if line >= output.GetNumberOfLines():
        return [f"no line {line} to check for a repeated point"]
    ids = vtk.vtkIdList()
    output.GetCellPoints(first_line + line, ids)
    if ids.GetNumberOfIds() != 2:
        return [f"line {line} has {ids.GetNumberOfIds()} points, expected a repeated point (2)"]
    a, b = ids.GetId(0), ids.GetId(1)
    problems = []
    if output.GetPoint(a) != output.GetPoint(b):
        problems.append(f"line {line} joins {output.GetPoint(a)} and {output.GetPoint(b)}, "
                        "expected one point twice")
    point_data = output.GetPointData()
    for i in range(point_data.GetNumberOfArrays()):
        array = point_data.GetArray(i)
        if array.GetTuple(a) != array.GetTuple(b):
            problems.append(f"line {line}: {array.GetName()} {array.GetTuple(a)} and "
                            f"{array.GetTuple(b)} differ at the repeated point")
    return problems


def check_both_directions(output, seeds):
    problems = []
    seed_ids = output.GetCellData().GetArray("SeedIds")
    times = output.GetPointData().GetArray("IntegrationTime")
    if seed_ids is None or times is None:
        return ["no SeedIds or IntegrationTime to check the directions with"]
    values = [int(seed_ids.GetValue(i)) for i in range(seed_ids.GetNumberOfTuples())]
    if values != list(range(seeds)) * 2:
        problems.append(f"SeedIds {values[:20]}, expected 0 .. {seeds - 1} twice")
    ids = vtk.vtkIdList()
    first_line = output.GetNumberOfVerts()
    for line in range(min(len(values), 2 * seeds)):
        output.GetCellPoints(first_line + line, ids)
        line_times = [times.GetValue(ids.GetId(k)) for k in range(ids.GetNumberOfIds())]
        backward = line >= seeds
        if line_times[0] != 0.0 or any((t > 0.0) if backward else (t < 0.0) for t in line_times):
            problems.append(f"line {line} ({'backward' if backward else 'forward'}) has "
                            f"IntegrationTime {line_times[:5]}...")
            break
    return problems


def check_points(output, points_type, points_file):
    problems = []
    points = output.GetPoints()
    if points_type is not None:
        found = points.GetData().GetDataTypeAsString() if points is not None else None
        if points is None or points.GetDataType() != POINT_TYPES[points_type]:
            problems.append(f"points held as {found!r}, expected {points_type}")
    if points_file is not None:
        with open(points_file) as lines:
            expected = [tuple(float(v) for v in line.split()) for line in lines if line.strip()]
        found = [output.GetPoint(i) for i in range(output.GetNumberOfPoints())]
        if len(found) != len(expected):
            problems.append(f"{len(found)} points, {points_file} has {len(expected)}")
        for i, (point, wanted) in enumerate(zip(found, expected)):
            if point != wanted:
                problems.append(f"point {i} is {point!r}, expected {wanted!r}")
                break
    return problems


def check(args):
    problems = []
    messages = Messages()
    reader = vtk.vtkXMLPolyDataReader()
    messages.observe(reader)
    if not reader.CanReadFile(args.file):
        return [f"vtkXMLPolyDataReader cannot read {args.file}"] + messages.all()
    reader.SetFileName(args.file)
    reader.Update()
    if reader.GetErrorCode() != 0:
        problems.append(f"reader error code {reader.GetErrorCode()}")
    output = reader.GetOutput()
    if output is None:
        return problems + ["reader produced no output"] + messages.all()

    if output.GetNumberOfPoints() != args.points:
        problems.append(f"{output.GetNumberOfPoints()} points, expected {args.points}")
    if output.GetNumberOfLines() != args.lines:
        problems.append(f"{output.GetNumberOfLines()} lines, expected {args.lines}")
    if output.GetNumberOfCells() != args.lines:
        problems.append(f"{output.GetNumberOfCells()} cells, expected {args.lines} lines only")

    for label, data, specs in (("point", output.GetPointData(), args.point_array),
                               ("cell", output.GetCellData(), args.cell_array)):
        expected_tuples = args.points if label == "point" else args.lines
        for name, components in specs:
            array = data.GetArray(name)
            if array is None:
                problems.append(f"no {label} array {name!r}")
                continue
            if array.GetNumberOfComponents() != components:
                problems.append(f"{label} array {name!r} has {array.GetNumberOfComponents()} "
                                f"components, expected {components}")
            if array.GetNumberOfTuples() != expected_tuples:
                problems.append(f"{label} array {name!r} has {array.GetNumberOfTuples()} "
                                f"tuples, expected {expected_tuples}")

    point_data = output.GetPointData()
    if args.scalars is not None:
        active = point_data.GetScalars()
        if active is None or active.GetName() != args.scalars:
            problems.append(f"active scalars {active and active.GetName()!r}, "
                            f"expected {args.scalars!r}")
    if args.vectors is not None:
        active = point_data.GetVectors()
        if active is None or active.GetName() != args.vectors:
            problems.append(f"active vectors {active and active.GetName()!r}, "
                            f"expected {args.vectors!r}")

    # The cell array itself, which needs no cell map.
    lines = output.GetLines()
    ids = vtk.vtkIdList()
    raw_lengths = []
    lines.InitTraversal()
    while lines.GetNextCell(ids):
        raw_lengths.append(ids.GetNumberOfIds())
    short = [i for i, n in enumerate(raw_lengths) if n < 2]
    if short:
        problems.append(f"lines {short[:20]} have fewer than 2 points, which VTK cannot use")
    else:
        # Through the cell map, as filters and ParaView see the cells (lines follow the verts).
        first_line = output.GetNumberOfVerts()
        lengths = []
        for cell in range(first_line, first_line + output.GetNumberOfLines()):
            output.GetCellPoints(cell, ids)
            lengths.append(ids.GetNumberOfIds())
        if lengths != raw_lengths:
            problems.append(f"GetCellPoints gives lengths {lengths}, the lines hold {raw_lengths}")
        if args.line_lengths is not None:
            expected = [int(n) for n in args.line_lengths.split(",") if n]
            if lengths != expected:
                problems.append(f"line lengths {lengths}, expected {expected}")
        if args.repeated_lines is not None:
            for line in (int(n) for n in args.repeated_lines.split(",") if n):
                problems += check_repeated(output, first_line, line)

    if args.speed_of is not None:
        speed, vectors = point_data.GetArray("Speed"), point_data.GetArray(args.speed_of)
        if speed is None or vectors is None:
            problems.append(f"cannot compare Speed with {args.speed_of!r}: array missing")
        else:
            for i in range(min(speed.GetNumberOfTuples(), vectors.GetNumberOfTuples())):
                magnitude = math.sqrt(sum(c * c for c in vectors.GetTuple3(i)))
                if not math.isclose(speed.GetValue(i), magnitude, rel_tol=1e-6, abs_tol=1e-30):
                    problems.append(f"Speed[{i}] = {speed.GetValue(i)}, |{args.speed_of}| = "
                                    f"{magnitude}")
                    break
    if args.seed_ids:
        seed_ids = output.GetCellData().GetArray("SeedIds")
        values = [] if seed_ids is None else [int(seed_ids.GetValue(i))
                                              for i in range(seed_ids.GetNumberOfTuples())]
        if values != list(range(args.lines)):
            problems.append(f"SeedIds {values[:20]}, expected 0 .. {args.lines - 1}")
    if args.both_directions is not None:
        problems += check_both_directions(output, args.both_directions)
    problems += check_points(output, args.points_type, args.points_file)
    for spec in args.field_text:
        name, _, value = spec.partition("=")
        field = output.GetFieldData().GetAbstractArray(name)
        found = field.GetValue(0) if field is not None and field.IsA("vtkStringArray") else None
        if found != value:
            problems.append(f"FieldData {name!r} is {found!r}, expected {value!r}")
    # Last, so that errors VTK reports while building its cell map are included.
    return problems + [f"VTK reported: {m}" for m in messages.all()]


def main():
    args = parse_arguments()
    problems = check(args)
    if problems:
        for problem in problems:
            print(f"check_vtp_with_vtk: {args.file}: {problem}", file=sys.stderr)
        return 1
    print(f"check_vtp_with_vtk: {args.file}: OK, VTK {vtk.vtkVersion.GetVTKVersion()} reads "
          f"{args.points} points, {args.lines} lines and the expected arrays")
    return 0


if __name__ == "__main__":
    sys.exit(main())
