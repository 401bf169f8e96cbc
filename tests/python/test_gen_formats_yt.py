"""`amrstream gen --format flash|amrex` writes files yt reads as the same cells and values as the
ExaBricks files of the same cloud: the same cell count, cell volume and, cell for cell by
position, every channel's values."""
import subprocess
from pathlib import Path

import numpy as np
import pytest

yt = pytest.importorskip("yt")

REPO = Path(__file__).resolve().parents[2]
BINARY = REPO / "build" / "src" / "cli" / "amrstream"
SIZE = ["--levels", "3", "--root-blocks", "2", "--target-cells", "40000"]


def gen(tmp_path, fmt):
    subprocess.run([str(BINARY), "gen", "cloud", *SIZE, "--format", fmt, "--out",
                    str(tmp_path / fmt)], check=True, capture_output=True)


def exa_cells(tmp_path):
    """Cell centres (finest-cell units, sorted rows) and channel values of the .exa files."""
    config = dict(line.split(None, 1) for line in (tmp_path / "exa.exa").read_text().splitlines()
                  if line and not line.startswith("#") and len(line.split()) > 1)
    cells = np.fromfile(tmp_path / "exa.cells", dtype="<i4").reshape(-1, 4)
    width = 2.0 ** cells[:, 3]
    centres = cells[:, :3] + 0.5 * width[:, None]
    spacing = np.array([float(v) for v in config["spacing"].split()])
    origin = np.array([float(v) for v in config["origin"].split()])
    values = {name: np.fromfile(tmp_path / f"exa.{name}.scalars", dtype="<f4")
              for name in ("dens", "magx", "magy", "magz")}
    return origin + centres * spacing, width ** 3 * np.prod(spacing), values


def by_position(positions):
    return np.lexsort(np.round(positions.T, 9)[::-1])


@pytest.mark.skipif(not BINARY.exists(), reason="amrstream not built")
@pytest.mark.parametrize("fmt,path,frontend", [("flash", "flash.h5", "flash"),
                                               ("amrex", "amrex.plt", "boxlib")])
def test_yt_reads_the_cells_and_values_of_the_exa_route(tmp_path, fmt, path, frontend):
    yt.set_log_level(50)
    gen(tmp_path, "exa")
    gen(tmp_path, fmt)
    positions, volumes, values = exa_cells(tmp_path)
    ad = yt.load(str(tmp_path / path)).all_data()
    theirs = np.stack([ad["index", a].d for a in "xyz"], axis=1)
    assert len(theirs) == len(positions)
    assert np.isclose(ad["index", "cell_volume"].d.sum(), volumes.sum(), rtol=1e-12)
    ours, yts = by_position(positions), by_position(theirs)
    np.testing.assert_allclose(theirs[yts], positions[ours], rtol=0, atol=1e-9)
    for name, channel in values.items():
        np.testing.assert_array_equal(ad[frontend, name].d[yts], channel[ours])
