"""2D AMReX plotfiles and 2D Enzo outputs, written here on two levels with a planar rotation,
are read natively as 2D: traced along circles in the plane z = 0 (round once, the radius within
0.5 %), and each cell's value equals what yt reads from the same file at that cell's centre."""
import numpy as np
import pytest

import amrstream

ROOT = 16  # root cells per axis over [0, 1]^2; level 1 refines root cells 4..11 on both axes
FINE_LO, FINE_HI = 8, 23  # level-1 index range


def rotation(x, y):
    return -(y - 0.5), x - 0.5


def level_cells(level):
    """Cell index ranges (lo, hi inclusive) and widths of the two levels."""
    return ((0, ROOT - 1), 1.0 / ROOT) if level == 0 else ((FINE_LO, FINE_HI), 0.5 / ROOT)


def centres(level):
    (lo, hi), dx = level_cells(level)
    i = np.arange(lo, hi + 1)
    x, y = np.meshgrid((i + 0.5) * dx, (i + 0.5) * dx, indexing="xy")  # x fastest
    return x.ravel(), y.ravel()


def write_amrex_2d(directory):
    directory.mkdir()
    header = ["HyperCLaw-V1.1", "2", "velx", "vely", "2", "0.0", "1", "0 0", "1 1", "2",
              f"((0,0) ({ROOT - 1},{ROOT - 1}) (0,0)) ((0,0) ({2 * ROOT - 1},{2 * ROOT - 1}) (0,0))",
              "0 0", f"{1 / ROOT} {1 / ROOT}", f"{0.5 / ROOT} {0.5 / ROOT}", "0", "0"]
    for level in (0, 1):
        (lo, hi), dx = level_cells(level)
        header += [f"{level} 1 0.0", "0", f"{lo * dx} {(hi + 1) * dx}",
                   f"{lo * dx} {(hi + 1) * dx}", f"Level_{level}/Cell"]
        box = f"(({lo},{lo}) ({hi},{hi}) (0,0))"
        x, y = centres(level)
        values = np.concatenate(rotation(x, y)).astype("<f8")
        fab = (b"FAB ((8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1)))"
               + box.encode() + b" 2\n" + values.tobytes())
        level_dir = directory / f"Level_{level}"
        level_dir.mkdir()
        (level_dir / "Cell_D_00000").write_bytes(fab)
        (level_dir / "Cell_H").write_text(
            f"1\n1\n2\n0\n(1 0\n{box}\n)\n1\nFabOnDisk: Cell_D_00000 0\n")
    (directory / "Header").write_text("\n".join(header) + "\n")
    return directory


def write_enzo_2d(directory):
    h5py = pytest.importorskip("h5py")
    directory.mkdir()
    (directory / "sim").write_text(
        "InitialTime = 0\nTopGridRank = 2\nTopGridDimensions = 16 16\nRefineBy = 2\n"
        "DomainLeftEdge = 0 0\nDomainRightEdge = 1 1\n"
        "LeftFaceBoundaryCondition = 3 3\nRightFaceBoundaryCondition = 3 3\nComovingCoordinates = 0\n"
        "VersionNumber = 2.6\nLengthUnits = 1\nTimeUnits = 1\nDensityUnits = 1\nGamma = 1.6667\n"
        "MassUnits = 1\nNumberOfParticles = 0\nHydroMethod = 0\nMultiSpecies = 0\n"
        "DualEnergyFormalism = 0\n")
    hierarchy = []
    with h5py.File(directory / "sim.cpu0000", "w") as out:
        for level in (0, 1):
            (lo, hi), dx = level_cells(level)
            n = hi - lo + 1
            hierarchy += [f"Grid = {level + 1}", "GridRank = 2",  # two numbers a list, as Enzo
                          f"GridDimension = {n + 6} {n + 6}", "GridStartIndex = 3 3",
                          f"GridEndIndex = {n + 2} {n + 2}", f"GridLeftEdge = {lo * dx} {lo * dx}",
                          f"GridRightEdge = {(hi + 1) * dx} {(hi + 1) * dx}",
                          "NumberOfBaryonFields = 2", "BaryonFileName = sim.cpu0000",
                          "NumberOfParticles = 0",
                          f"Pointer: Grid[{level + 1}]->NextGridThisLevel = 0",
                          f"Pointer: Grid[{level + 1}]->NextGridNextLevel = {2 if level == 0 else 0}",
                          ""]
            vx, vy = rotation(*centres(level))
            group = out.create_group(f"Grid{level + 1:08d}")
            group["x-velocity"] = vx.reshape(n, n)
            group["y-velocity"] = vy.reshape(n, n)
    (directory / "sim.hierarchy").write_text("\n".join(hierarchy))
    return directory / "sim"


WRITERS = {"amrex": (write_amrex_2d, "velx,vely"), "enzo": (write_enzo_2d, "x-velocity,y-velocity")}


@pytest.mark.parametrize("kind", sorted(WRITERS))
def test_a_2d_file_is_traced_along_circles_in_its_plane(tmp_path, kind):
    write, vector = WRITERS[kind]
    ds = amrstream.load(str(write(tmp_path / kind)))
    assert ds.dimensions == 2
    seeds = np.array([[0.5 + r, 0.5, 0.01] for r in (0.1, 0.2, 0.3)])
    traces = amrstream.trace(ds, seeds, vector=vector, interpolant="linear", steps=400,
                             step_size=0.5)
    assert np.all(traces.points[:, 2] == 0.0)
    assert np.all(traces.vectors[:, 2] == 0.0)
    for line in range(len(traces)):
        points = traces[line]
        radius = np.hypot(points[:, 0] - 0.5, points[:, 1] - 0.5)
        assert np.ptp(np.arctan2(points[:, 1] - 0.5, points[:, 0] - 0.5)) > 6.0  # all the way round
        np.testing.assert_allclose(radius, radius[0], rtol=5e-3)  # crossing levels, as in 3D


@pytest.mark.parametrize("kind", sorted(WRITERS))
def test_every_cell_holds_what_yt_reads_there(tmp_path, kind):
    yt = pytest.importorskip("yt")
    write, vector = WRITERS[kind]
    path = write(tmp_path / kind)
    ds = amrstream.load(str(path))
    internal = ds.levels.max() - ds.levels  # 0 the finest, as the corners count cells
    centre = np.asarray(ds.origin) + (ds.corners + 0.5 * (1 << internal)[:, None]) * np.asarray(
        ds.finest_width)
    reference = yt.load(str(path))
    everything = reference.all_data()
    yt_xy = np.column_stack([everything["index", "x"].d, everything["index", "y"].d])
    for name in vector.split(","):
        field = next(f for f in reference.field_list if f[1] == name)
        ours = dict(zip(map(tuple, np.round(centre[:, :2], 12)), ds.field(name)))
        assert len(ours) == len(yt_xy)  # one cell of ours per leaf of yt's (each repeated in z)
        for xy, value in zip(np.round(yt_xy, 12), everything[field].d):
            assert ours[tuple(xy)] == pytest.approx(value, rel=1e-6), (name, xy)
