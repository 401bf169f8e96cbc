"""Tests of python/amrstream/yt_cells.py against data read without yt.

Real data sets come from ../shared/data/real (or $AMRSTREAM_SHARED_DATA, the folder that holds
enzo-moving7/ and amrex-pelelmex-3d/); tests that need them skip when it is absent.
"""

import importlib.util
import re
from pathlib import Path

import numpy as np
import pytest

from shared_data import real_data

import yt  # noqa: E402  (Debian's python3-yt; the yt adapter needs it)
yt.set_log_level(40)

REPO = Path(__file__).resolve().parents[2]


def _load_adapter():
    # By path: amrstream/__init__.py imports the compiled extension, which may not be built.
    spec = importlib.util.spec_from_file_location("yt_cells", REPO / "python" / "amrstream" / "yt_cells.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


yt_cells = _load_adapter()

ENZO_VECTOR = ("x-velocity", "y-velocity", "z-velocity")


# ---------------------------------------------------------------- checks shared by the tests

def assert_exact_tiling(cells, max_level, domain_dimensions):
    """Leaf cells are aligned dyadic cubes, pairwise disjoint, inside the domain, filling it.

    Two aligned dyadic cubes either are disjoint or one holds the other, so disjointness is
    checked by looking up each finer cell's enclosing cube at every coarser level among the
    leaf cells of that level. Disjoint cubes inside the domain whose volumes add up to the
    domain's volume fill it.
    """
    corners, levels = cells["corners"], cells["levels"].astype(np.int64)
    extent = np.asarray(domain_dimensions, dtype=np.int64) << max_level
    span = (np.int64(1) << (max_level - levels))[:, None]

    assert np.all(corners % span == 0), "a cell's corner is not a multiple of its size"
    assert np.all(corners >= 0) and np.all(corners + span <= extent), "a cell leaves the domain"

    def keys(points):
        return (points[:, 0] * extent[1] + points[:, 1]) * extent[2] + points[:, 2]

    for level in np.unique(levels):
        level_keys = keys(corners[levels == level])
        assert len(np.unique(level_keys)) == len(level_keys), f"level {level} repeats a cell"
        coarse_span = np.int64(1) << (max_level - level)
        finer = corners[levels > level]
        enclosing = finer // coarse_span * coarse_span
        inside = np.isin(keys(enclosing), level_keys)
        assert not inside.any(), f"{inside.sum()} finer leaf cells lie inside level-{level} leaf cells"

    volume = sum(int(s) ** 3 for s in span[:, 0])
    assert volume == int(np.prod(extent)), "leaf cells do not fill the domain"


def leaf_counts_from_boxes(starts, dims, levels):
    """Leaf cells per level of boxes given in their own level's integer index (refinement 2)."""
    counts = {}
    for box in range(len(levels)):
        covered = np.zeros(dims[box], dtype=bool)
        for finer in np.flatnonzero(levels > levels[box]):
            factor = 2 ** int(levels[finer] - levels[box])
            low = starts[finer] // factor - starts[box]
            high = -(-(starts[finer] + dims[finer]) // factor) - starts[box]
            low, high = np.maximum(low, 0), np.minimum(high, dims[box])
            if np.all(high > low):
                covered[low[0]:high[0], low[1]:high[1], low[2]:high[2]] = True
        level = int(levels[box])
        counts[level] = counts.get(level, 0) + int((~covered).sum())
    return {level: count for level, count in counts.items() if count}


def adapter_counts(cells):
    levels, counts = np.unique(cells["levels"], return_counts=True)
    return {int(level): int(count) for level, count in zip(levels, counts)}


# ---------------------------------------------------------------- Enzo moving7, read without yt

def enzo_parameter(parameter_file, name):
    match = re.search(rf"^{name}\s*=\s*(.*)$", parameter_file.read_text(), re.MULTILINE)
    return np.array(match.group(1).split(), dtype=float)


def enzo_grid_table_from_harrays(parameter_file):
    import h5py

    with h5py.File(f"{parameter_file}.harrays", "r") as table:
        return {
            "left": table["LeftEdges"][...],
            "dims": table["ActiveDimensions"][...].astype(np.int64),
            "level": table["Level"][...].astype(np.int64),
            "cpu": table["Processor"][...].astype(np.int64),
        }


def enzo_grid_table_from_hierarchy(parameter_file):
    """The same table from the text .hierarchy; levels follow from the cell widths."""
    text = Path(f"{parameter_file}.hierarchy").read_text()

    def column(name, dtype):
        return np.array([line.split() for line in re.findall(rf"^{name}\s*=\s*(.*)$", text, re.MULTILINE)],
                        dtype=dtype)

    left, right = column("GridLeftEdge", float), column("GridRightEdge", float)
    dims = column("GridEndIndex", np.int64) - column("GridStartIndex", np.int64) + 1
    domain_width = enzo_parameter(parameter_file, "DomainRightEdge") - enzo_parameter(parameter_file, "DomainLeftEdge")
    root_dx = domain_width / enzo_parameter(parameter_file, "TopGridDimensions")
    level = np.rint(np.log2(root_dx[0] / ((right - left)[:, 0] / dims[:, 0]))).astype(np.int64)
    return {"left": left, "dims": dims, "level": level}


def enzo_grid_table(parameter_file):
    try:
        return enzo_grid_table_from_harrays(parameter_file)
    except ImportError:
        return enzo_grid_table_from_hierarchy(parameter_file)


def enzo_level_starts(parameter_file, table):
    """Each grid's first cell as an integer index on its own level's lattice."""
    domain_left = enzo_parameter(parameter_file, "DomainLeftEdge")
    domain_width = enzo_parameter(parameter_file, "DomainRightEdge") - domain_left
    root_dx = domain_width / enzo_parameter(parameter_file, "TopGridDimensions")
    level_dx = root_dx[None, :] / 2.0 ** table["level"][:, None]
    return np.rint((table["left"] - domain_left) / level_dx).astype(np.int64)


@pytest.fixture(scope="module")
def enzo_file():
    return real_data("enzo-moving7/DD0010/moving7_0010")


@pytest.fixture(scope="module")
def enzo_ds(enzo_file):
    return yt.load(str(enzo_file))


@pytest.fixture(scope="module")
def enzo_cells(enzo_ds):
    return yt_cells.leaf_cells_from_yt(enzo_ds, vector=ENZO_VECTOR, fields=["Density"])


def test_enzo_metadata(enzo_ds, enzo_cells):
    assert enzo_ds.index.max_level == 7
    assert enzo_cells["corners"].dtype == np.int64 and enzo_cells["corners"].shape[1] == 3
    assert enzo_cells["levels"].dtype == np.int32
    assert list(enzo_cells["fields"]) == ["x-velocity", "y-velocity", "z-velocity", "Density"]
    for values in enzo_cells["fields"].values():
        assert values.dtype == np.float32 and values.flags.c_contiguous
        assert values.shape == enzo_cells["levels"].shape
    assert enzo_cells["field_units"]["x-velocity"] == "code_velocity"
    np.testing.assert_array_equal(enzo_cells["origin"], [0.0, 0.0, 0.0])
    np.testing.assert_array_equal(enzo_cells["finest_width"], [1 / 2048] * 3)
    assert enzo_cells["periodic"] == (True, True, True)
    assert enzo_cells["time"] == pytest.approx(0.81751317119117, rel=1e-12)
    assert re.fullmatch(r"code units \(1 = [0-9.e+]+ s\)", enzo_cells["time_unit"])
    assert re.fullmatch(r"code units \(1 = [0-9.e+]+ cm\)", enzo_cells["length_unit"])
    assert enzo_cells["format"] == "yt:EnzoDataset"
    assert enzo_cells["source"].endswith("moving7_0010")


def test_enzo_leaf_cells_tile_the_domain(enzo_ds, enzo_cells):
    assert_exact_tiling(enzo_cells, enzo_ds.index.max_level, enzo_ds.domain_dimensions)


def test_enzo_leaf_counts_match_the_grid_table(enzo_file, enzo_cells):
    table = enzo_grid_table(enzo_file)
    expected = leaf_counts_from_boxes(enzo_level_starts(enzo_file, table), table["dims"], table["level"])
    assert adapter_counts(enzo_cells) == expected
    assert sum(expected.values()) == 27077


def test_enzo_text_and_hdf5_grid_tables_agree(enzo_file):
    pytest.importorskip("h5py", reason="h5py is absent: only the text .hierarchy can be read")
    from_hdf5, from_text = enzo_grid_table_from_harrays(enzo_file), enzo_grid_table_from_hierarchy(enzo_file)
    for key in ("left", "dims", "level"):
        np.testing.assert_array_equal(from_hdf5[key], from_text[key])


def test_enzo_values_match_the_hdf5_file(enzo_file, enzo_ds, enzo_cells):
    h5py = pytest.importorskip("h5py", reason="h5py is absent: the Enzo field file cannot be read without yt")
    table = enzo_grid_table_from_harrays(enzo_file)
    starts = enzo_level_starts(enzo_file, table)
    max_level = enzo_ds.index.max_level
    default_vector = yt_cells.leaf_cells_from_yt(enzo_ds)

    assert np.all(table["cpu"] == 0), "this data set has one field file"
    data = h5py.File(f"{enzo_file}.cpu0000", "r")

    rng = np.random.default_rng(7)
    sample = rng.choice(len(enzo_cells["levels"]), size=400, replace=False)
    compared = 0
    for cell in sample:
        level = int(enzo_cells["levels"][cell])
        index = enzo_cells["corners"][cell] // 2 ** (max_level - level)
        owners = [g for g in np.flatnonzero(table["level"] == level)
                  if np.all(index >= starts[g]) and np.all(index < starts[g] + table["dims"][g])]
        assert len(owners) == 1, f"cell {cell} lies in grids {owners}"
        i, j, k = index - starts[owners[0]]
        group = data[f"Grid{owners[0] + 1:08d}"]  # HDF5 shape (nz, ny, nx), groups count from 1
        for name in ("x-velocity", "y-velocity", "z-velocity", "Density"):
            assert enzo_cells["fields"][name][cell] == group[name][k, j, i], (name, cell)
        for axis, name in zip("xyz", ENZO_VECTOR):
            np.testing.assert_allclose(default_vector["fields"][f"velocity_{axis}"][cell],
                                       group[name][k, j, i], rtol=1e-6)
        compared += 1
    data.close()
    assert compared == 400
    assert len(np.unique(enzo_cells["levels"][sample])) >= 6, "the sample should reach most levels"


# ---------------------------------------------------------------- AMReX plotfile, read without yt

def amrex_header(plotfile):
    """Variable names, dx per level and each level's boxes (integer lo, size) from Header."""
    lines = iter((plotfile / "Header").read_text().splitlines())
    next(lines)  # version
    names = [next(lines).strip() for _ in range(int(next(lines)))]
    dim = int(next(lines))
    next(lines)  # time
    finest_level = int(next(lines))
    prob_lo = np.array(next(lines).split(), dtype=float)
    for _ in range(4):  # prob_hi, ref ratios, domain boxes, steps
        next(lines)
    dx = [np.array(next(lines).split(), dtype=float) for _ in range(finest_level + 1)]
    next(lines), next(lines)  # coordinate system, boundary width
    boxes = []
    for level in range(finest_level + 1):
        level_number, box_count = (int(word) for word in next(lines).split()[:2])
        assert level_number == level
        next(lines)  # step
        for _ in range(box_count):
            edges = np.array([next(lines).split() for _ in range(dim)], dtype=float)
            low = np.rint((edges[:, 0] - prob_lo) / dx[level]).astype(np.int64)
            high = np.rint((edges[:, 1] - prob_lo) / dx[level]).astype(np.int64)
            boxes.append((level, low, high - low))
        next(lines)  # Level_l/Cell
    return names, boxes


def amrex_fab_values(plotfile, level, component):
    """{lower corner: (nx,ny,nz) values} of one component for every FAB of a level."""
    fabs = {}
    cell_h = (plotfile / f"Level_{level}" / "Cell_H").read_text()
    for data_file, offset in re.findall(r"FabOnDisk: (\S+) (\d+)", cell_h):
        with open(plotfile / f"Level_{level}" / data_file, "rb") as stream:
            stream.seek(int(offset))
            header = stream.readline().decode()
            assert "(8, (8 7 6 5 4 3 2 1))" in header, f"not little-endian float64: {header}"
            low, high = (np.array(m.split(","), dtype=np.int64)
                         for m in re.search(r"\(\((\S+)\) \((\S+)\) \(", header).groups())
            shape = high - low + 1
            ncomp = int(header.split()[-1])
            block = np.fromfile(stream, dtype="<f8", count=ncomp * int(np.prod(shape)))
        fabs[tuple(low)] = block.reshape(ncomp, *shape[::-1])[component].transpose()
    return fabs


@pytest.fixture(scope="module")
def amrex_plotfile():
    return real_data("amrex-pelelmex-3d/example_plt_3d")


@pytest.fixture(scope="module")
def amrex_ds(amrex_plotfile):
    return yt.load(str(amrex_plotfile))


@pytest.fixture(scope="module")
def amrex_cells(amrex_ds):
    return yt_cells.leaf_cells_from_yt(amrex_ds, fields=["density"])


def test_amrex_leaf_cells_tile_the_domain(amrex_ds, amrex_cells):
    assert amrex_ds.index.max_level == 2
    assert_exact_tiling(amrex_cells, amrex_ds.index.max_level, amrex_ds.domain_dimensions)
    assert amrex_cells["periodic"] == (False, False, False)
    np.testing.assert_allclose(amrex_cells["finest_width"], [0.0005] * 3, rtol=1e-12)


def test_amrex_leaf_counts_match_the_header(amrex_plotfile, amrex_cells):
    _, boxes = amrex_header(amrex_plotfile)
    levels = np.array([level for level, _, _ in boxes])
    starts = np.array([low for _, low, _ in boxes])
    dims = np.array([size for _, _, size in boxes])
    expected = leaf_counts_from_boxes(starts, dims, levels)
    assert expected == {2: 32 ** 3}, "the README says levels 0 and 1 are covered entirely"
    assert adapter_counts(amrex_cells) == expected


def test_amrex_values_match_the_fabs(amrex_plotfile, amrex_cells):
    names, _ = amrex_header(amrex_plotfile)
    for name in ("y_velocity", "z_velocity", "density"):
        fabs = amrex_fab_values(amrex_plotfile, 2, names.index(name))
        adapter_name = {"y_velocity": "velocity_y", "z_velocity": "velocity_z"}.get(name, name)
        expected = np.empty(len(amrex_cells["levels"]), dtype=np.float64)
        for low, values in fabs.items():
            inside = np.all((amrex_cells["corners"] >= low) & (amrex_cells["corners"] < np.add(low, values.shape)), axis=1)
            i, j, k = (amrex_cells["corners"][inside] - low).T
            expected[inside] = values[i, j, k]
        np.testing.assert_array_equal(amrex_cells["fields"][adapter_name], expected.astype(np.float32))


# ---------------------------------------------------------------- a synthetic dataset with known answers

def synthetic_grid(left, right, level, dims):
    """A grid whose velocity is the cell centre and whose density is the level."""
    left, right, dims = np.asarray(left, float), np.asarray(right, float), np.asarray(dims)
    centres = [left[a] + (np.arange(dims[a]) + 0.5) * (right[a] - left[a]) / dims[a] for a in range(3)]
    x, y, z = np.meshgrid(*centres, indexing="ij")
    return {"left_edge": left, "right_edge": right, "level": level, "dimensions": dims,
            "velocity_x": (x, "code_velocity"), "velocity_y": (y, "code_velocity"),
            "velocity_z": (z, "code_velocity"),
            "density": (np.full(dims, float(level)), "code_mass/code_length**3")}


def synthetic_dataset(refine_by=2):
    bbox = np.array([[-1.0, 1.0], [0.0, 2.0], [10.0, 12.0]])
    grids = [synthetic_grid(bbox[:, 0], bbox[:, 1], 0, [4, 4, 4]),
             synthetic_grid([0.0, 0.5, 10.0], [1.0, 1.5, 11.0], 1, [4, 4, 4]),
             synthetic_grid([0.5, 1.0, 10.5], [1.0, 1.5, 11.0], 2, [4, 4, 4])]
    if refine_by != 2:
        grids = grids[:2]
        grids[1] = synthetic_grid([0.0, 0.5, 10.0], [0.5, 1.0, 10.5], 1, [4, 4, 4])
    return yt.load_amr_grids(grids, [4, 4, 4], bbox=bbox, sim_time=2.5, time_unit=(3.0, "s"),
                             length_unit=(2.0, "km"), periodicity=(True, False, True), refine_by=refine_by)


def test_synthetic_cells_sit_where_their_values_say():
    ds = synthetic_dataset()
    cells = yt_cells.leaf_cells_from_yt(ds, fields=["density"])
    assert adapter_counts(cells) == {0: 64 - 8, 1: 64 - 8, 2: 64}
    assert_exact_tiling(cells, ds.index.max_level, ds.domain_dimensions)
    span = 2.0 ** (ds.index.max_level - cells["levels"])
    centres = cells["origin"] + (cells["corners"] + span[:, None] / 2) * cells["finest_width"]
    velocity = np.stack([cells["fields"][f"velocity_{axis}"] for axis in "xyz"], axis=1)
    np.testing.assert_array_equal(velocity, centres.astype(np.float32))
    np.testing.assert_array_equal(cells["fields"]["density"], cells["levels"].astype(np.float32))
    np.testing.assert_array_equal(cells["origin"], [-1.0, 0.0, 10.0])
    np.testing.assert_array_equal(cells["finest_width"], [0.125] * 3)
    assert cells["periodic"] == (True, False, True)
    assert cells["time"] == 2.5
    assert cells["time_unit"] == "code units (1 = 3 s)"
    assert cells["length_unit"] == "code units (1 = 2e+05 cm)"


def synthetic_planar_dataset():
    """A 2D dataset of 3 levels: 8x8 root cells on [-1, 1] x [0, 2], a level-1 and a level-2 grid."""
    bbox = np.array([[-1.0, 1.0], [0.0, 2.0], [0.0, 1.0]])
    grids = [synthetic_grid([-1.0, 0.0, 0.0], [1.0, 2.0, 1.0], 0, [8, 8, 1]),
             synthetic_grid([0.0, 0.5, 0.0], [1.0, 1.5, 1.0], 1, [8, 8, 1]),
             synthetic_grid([0.5, 1.0, 0.0], [1.0, 1.5, 1.0], 2, [8, 8, 1])]
    return yt.load_amr_grids(grids, [8, 8, 1], bbox=bbox, periodicity=(True, False, True))


def test_planar_cells_become_a_slab_as_load_makes_of_2d_flash():
    """Each 2D leaf cell is repeated along z up to the coarsest leaf's width; the slab is tiled
    once; values are the 2D cell's."""
    ds = synthetic_planar_dataset()
    assert ds.dimensionality == 2
    cells = yt_cells.leaf_cells_from_yt(ds, fields=["density"])
    max_level = ds.index.max_level
    assert max_level == 2
    leaves = {0: 64 - 16, 1: 64 - 16, 2: 64}  # 2D leaves per level
    # Level l repeats 2**l times: the coarsest leaves (level 0) set the slab's thickness.
    assert adapter_counts(cells) == {level: n * 2**level for level, n in leaves.items()}
    np.testing.assert_array_equal(cells["finest_width"], [0.0625, 0.0625, 0.0625])
    # The slab, 4 finest cells thick, across z = 0 as load() puts a 2D FLASH file's.
    np.testing.assert_array_equal(cells["origin"], [-1.0, 0.0, -0.125])
    assert cells["dimensions"] == 2
    assert cells["periodic"] == (True, False, False)
    # The slab is one root cell (4 finest cells) thick and tiled exactly once.
    assert_exact_tiling(cells, max_level, [8, 8, 1])
    span = 2.0 ** (max_level - cells["levels"])
    centres = cells["origin"] + (cells["corners"] + span[:, None] / 2) * cells["finest_width"]
    np.testing.assert_array_equal(cells["fields"]["velocity_x"], centres[:, 0].astype(np.float32))
    np.testing.assert_array_equal(cells["fields"]["velocity_y"], centres[:, 1].astype(np.float32))
    np.testing.assert_array_equal(cells["fields"]["density"], cells["levels"].astype(np.float32))


# ---------------------------------------------------------------- what the adapter refuses

@pytest.mark.parametrize("request_kind", ["vector", "fields"])
def test_unknown_field_is_named(enzo_ds, request_kind):
    arguments = ({"vector": ("x-velocity", "y-velocity", "no_such_field")} if request_kind == "vector"
                 else {"vector": ENZO_VECTOR, "fields": ["no_such_field"]})
    with pytest.raises(ValueError, match="no_such_field") as error:
        yt_cells.leaf_cells_from_yt(enzo_ds, **arguments)
    assert "('enzo', 'x-velocity')" in str(error.value), "the message should list the fields"


def test_particle_field_is_refused(enzo_ds):
    with pytest.raises(ValueError, match="particle"):
        yt_cells.leaf_cells_from_yt(enzo_ds, vector=ENZO_VECTOR, fields=[("all", "particle_mass")])


def test_vector_needs_three_components(enzo_ds):
    with pytest.raises(ValueError, match="three fields"):
        yt_cells.leaf_cells_from_yt(enzo_ds, vector=("x-velocity", "y-velocity"))


def test_1d_dataset_is_refused():
    ones = np.ones((8, 1, 1))
    ds = yt.load_uniform_grid({name: ones for name in ("velocity_x", "velocity_y", "velocity_z")},
                              [8, 1, 1])
    assert ds.dimensionality == 1
    with pytest.raises(ValueError, match="2D and 3D data; yt dataset .* is 1D"):
        yt_cells.leaf_cells_from_yt(ds)


def test_refinement_other_than_2_is_refused():
    with pytest.raises(ValueError, match="needs refinement by 2 between levels; this dataset refines by 4"):
        yt_cells.leaf_cells_from_yt(synthetic_dataset(refine_by=4))


def test_octree_dataset_is_refused():
    ds = yt.load_octree(octree_mask=np.array([1] + [0] * 8, dtype=np.uint8),
                        data={("gas", "density"): np.ones(8)}, bbox=np.array([[0.0, 1.0]] * 3))
    with pytest.raises(TypeError, match="not made of grid patches"):
        yt_cells.leaf_cells_from_yt(ds, vector=("density", "density", "density"))
