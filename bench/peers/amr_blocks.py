"""Reads an ExaBricks (.exa) dataset and rebuilds its octree of 8^3-cell blocks.

Cells are grouped into aligned 8^3 blocks of their level. Every level gets its leaf blocks plus
the ancestors of finer blocks; an ancestor's cells hold the average of their 8 children
(restriction, finest level first). Levels are numbered as in amrstream: 0 is the finest.
"""

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

BLOCK = 8


class DatasetError(Exception):
    pass


@dataclass
class Level:
    level: int              # 0 = finest
    width: int              # cell width in finest cells (2^level)
    corners: np.ndarray     # (n, 3) int64 block lower corners, finest-cell units
    refined: np.ndarray     # (n,) bool: True for ancestors (cells covered by finer blocks)
    values: dict = field(default_factory=dict)  # name -> (n, 8, 8, 8) float64 indexed [b, x, y, z]

    @property
    def block_width(self):
        return BLOCK * self.width


@dataclass
class AmrBlocks:
    levels: list            # Level per level, index = level (0 finest)
    origin: np.ndarray      # physical position of cell-unit (0, 0, 0)
    spacing: np.ndarray     # physical size of one finest cell per axis
    lower: np.ndarray       # domain lower corner, finest-cell units
    upper: np.ndarray       # domain upper corner, finest-cell units
    channels: list
    cell_count: int

    @property
    def top(self):
        return len(self.levels) - 1

    def to_physical(self, cell_units):
        return self.origin + self.spacing * np.asarray(cell_units, dtype=np.float64)

    @property
    def domain(self):
        return self.to_physical(self.lower), self.to_physical(self.upper)


def read_config(path):
    path = Path(path)
    config = {"cells": None, "scalars": {}, "origin": np.zeros(3), "spacing": np.ones(3)}
    for number, raw in enumerate(path.read_text().splitlines(), 1):
        words = raw.split("#", 1)[0].split()
        if not words:
            continue
        where = f"{path}:{number}"
        key, args = words[0], words[1:]
        if key == "cells" and len(args) == 1:
            config["cells"] = path.parent / args[0]
        elif key == "scalar" and len(args) == 2:
            config["scalars"][args[0]] = path.parent / args[1]
        elif key in ("origin", "spacing") and len(args) == 3:
            try:
                config[key] = np.array([float(a) for a in args])
            except ValueError:
                raise DatasetError(f"{where}: '{key}' needs three numbers") from None
        elif key == "bricks":
            pass
        else:
            raise DatasetError(f"{where}: bad directive '{raw.strip()}'")
    if config["cells"] is None:
        raise DatasetError(f"{path}: no 'cells' line")
    if np.any(config["spacing"] <= 0):
        raise DatasetError(f"{path}: spacing must be positive")
    return config


def read_cells(path):
    data = np.fromfile(path, dtype="<i4")
    if data.size % 4:
        raise DatasetError(f"{path}: size {data.size * 4} bytes is not a multiple of 16")
    cells = data.reshape(-1, 4).astype(np.int64)
    if cells.size == 0:
        raise DatasetError(f"{path}: no cells")
    if np.any(cells[:, 3] < 0) or np.any(cells[:, 3] > 30):
        raise DatasetError(f"{path}: level outside 0..30")
    return cells[:, :3], cells[:, 3]


def read_scalars(path, count):
    values = np.fromfile(path, dtype="<f4")
    if values.size != count:
        raise DatasetError(f"{path}: {values.size} values for {count} cells "
                           f"(expected {4 * count} bytes)")
    if not np.all(np.isfinite(values)):
        raise DatasetError(f"{path}: NaN or Inf values")
    return values.astype(np.float64)


def _leaf_blocks(cells_path, lvl, lower, channels):
    """Leaf blocks of one level: corners (n, 3) and values name -> (n, 8, 8, 8)."""
    width = 1 << lvl
    span = BLOCK * width
    if np.any(lower % width):
        raise DatasetError(f"{cells_path}: level-{lvl} cells not aligned to their width {width}")
    block_corner = (lower // span) * span
    local = (lower - block_corner) // width
    corners, block = np.unique(block_corner, axis=0, return_inverse=True)
    block = block.reshape(-1)
    slot = block * BLOCK**3 + (local[:, 0] * BLOCK + local[:, 1]) * BLOCK + local[:, 2]
    counts = np.bincount(block, minlength=len(corners))
    if np.any(counts != BLOCK**3) or np.unique(slot).size != slot.size:
        where = ""
        if np.any(counts != BLOCK**3):
            where = f" (block at {tuple(corners[np.argmax(counts != BLOCK**3)])})"
        raise DatasetError(f"{cells_path}: level-{lvl} cells do not form complete aligned "
                           f"{BLOCK}^3 blocks{where}")
    values = {}
    for name, channel in channels.items():
        grid = np.empty(len(corners) * BLOCK**3)
        grid[slot] = channel
        values[name] = grid.reshape(-1, BLOCK, BLOCK, BLOCK)
    return corners, values


def _parents(level_blocks):
    span = 2 * level_blocks.block_width
    return (level_blocks.corners // span) * span


def load(exa_path):
    config = read_config(exa_path)
    cells_path = config["cells"]
    lower, level = read_cells(cells_path)
    if level.min() != 0:
        raise DatasetError(f"{cells_path}: no level-0 (finest) cells")
    channels = {name: read_scalars(p, len(level)) for name, p in config["scalars"].items()}

    levels = []
    for lvl in range(int(level.max()) + 1):
        mask = level == lvl
        corners, values = _leaf_blocks(cells_path, lvl, lower[mask],
                                       {name: c[mask] for name, c in channels.items()})
        refined = np.zeros(len(corners), dtype=bool)
        if levels:
            parents = np.unique(_parents(levels[-1]), axis=0)
            corners = np.concatenate([corners, parents])
            if np.unique(corners, axis=0).shape[0] != len(corners):
                raise DatasetError(f"{cells_path}: level-{lvl} cells overlap finer cells")
            refined = np.concatenate([refined, np.ones(len(parents), dtype=bool)])
            values = {name: np.concatenate([v, np.full((len(parents),) + v.shape[1:], np.nan)])
                      for name, v in values.items()}
        order = np.lexsort(corners.T[::-1])
        levels.append(Level(lvl, 1 << lvl, corners[order], refined[order],
                            {name: v[order] for name, v in values.items()}))
        if lvl > 0:
            _restrict(levels[-2], levels[-1], cells_path)

    top = len(levels) - 1
    root = levels[top]
    lo = root.corners.min(axis=0)
    hi = root.corners.max(axis=0) + root.block_width
    tiles = np.prod((hi - lo) // root.block_width)
    if tiles != len(root.corners):
        raise DatasetError(f"{cells_path}: the level-{top} blocks ({len(root.corners)}) do not "
                           f"tile their bounding box ({tiles} blocks)")
    return AmrBlocks(levels, config["origin"], config["spacing"], lo, hi,
                     list(channels), len(level))


def _restrict(fine, coarse, cells_path):
    """Fills the refined blocks of `coarse` with averages of their children in `fine`."""
    parent_corner = _parents(fine)
    parent = _find_rows(coarse.corners, parent_corner)
    octant = (fine.corners - parent_corner) // fine.block_width
    children = np.bincount(parent, minlength=len(coarse.corners))
    if np.any(children[coarse.refined] != 8):
        bad = coarse.corners[coarse.refined][np.argmax(children[coarse.refined] != 8)]
        raise DatasetError(f"{cells_path}: the level-{coarse.level} block at {tuple(bad)} is "
                           f"only partly refined: not an octree of {BLOCK}^3 blocks")
    half = BLOCK // 2
    for name, v in fine.values.items():
        n = len(v)
        averaged = v.reshape(n, half, 2, half, 2, half, 2).mean(axis=(2, 4, 6))
        target = coarse.values[name]
        for ox in range(2):
            for oy in range(2):
                for oz in range(2):
                    sel = np.all(octant == (ox, oy, oz), axis=1)
                    target[parent[sel], ox * half:(ox + 1) * half, oy * half:(oy + 1) * half,
                           oz * half:(oz + 1) * half] = averaged[sel]


def _find_rows(table, rows):
    """Index in the (n, 3) `table` of each of `rows` (all present)."""
    index = {tuple(row): i for i, row in enumerate(table.tolist())}
    return np.array([index[tuple(row)] for row in rows.tolist()], dtype=np.int64)
