"""yt's Streamlines on the block hierarchy of amr_blocks.

yt's level 0 is our coarsest level. Each 8^3 block (leaf or ancestor) becomes one grid.
"""

import time

import numpy as np
import yt
from yt.visualization.api import Streamlines


def to_yt(blocks, vector):
    grids = []
    for level in reversed(blocks.levels):  # yt wants parents before their children
        for i, corner in enumerate(level.corners):
            grid = {
                "left_edge": blocks.to_physical(corner),
                "right_edge": blocks.to_physical(corner + level.block_width),
                "level": blocks.top - level.level,
                "dimensions": np.array([8, 8, 8]),
            }
            for name in vector:
                grid[name] = level.values[name][i]  # indexed [x, y, z] as yt expects
            grids.append(grid)
    lower, upper = blocks.domain
    # yt computes vertex-centred data from ghost zones and refuses to read outside a
    # non-periodic domain, so the domain stays periodic (it only changes the outermost half cell).
    root_cells = (blocks.upper - blocks.lower) // blocks.levels[blocks.top].width
    return yt.load_amr_grids(grids, root_cells, bbox=np.stack([lower, upper], axis=1),
                             length_unit=1.0, refine_by=2)


def points_taken(line):
    """Points yt wrote: its array is zero-filled after a trace left the domain."""
    unused = np.flatnonzero(np.all(line[1:] == 0.0, axis=1))
    return len(line) if unused.size == 0 else int(unused[0]) + 1


def trace(blocks, seeds, step, steps, vector):
    """Forward streamlines of at most `steps` RK4 steps of physical length `step`."""
    yt.set_log_level("error")
    yt.config.ytcfg["yt", "suppress_stream_logging"] = True
    started = time.perf_counter()
    ds = to_yt(blocks, vector)
    # yt makes int(length / dx) + 1 points and then uses dx = length / points: this pair
    # gives steps + 1 points and a step of exactly `step`.
    streamlines = Streamlines(ds, np.asarray(seeds, dtype=np.float64), *vector,
                              dx=step * (steps + 1) / (steps + 0.5), length=step * (steps + 1))
    assert streamlines.steps == steps + 1 and np.isclose(streamlines.dx, step)
    setup = time.perf_counter() - started

    started = time.perf_counter()
    streamlines.integrate_through_volume()
    seconds = time.perf_counter() - started

    lines = {}
    for seed, line in enumerate(np.asarray(streamlines.streamlines)):
        lines[seed] = line[:points_taken(line)]
    return {
        "method": "yt Streamlines",
        "seconds": seconds,
        "setup_seconds": setup,
        "steps": sum(len(line) - 1 for line in lines.values()),
        "lines": lines,
    }
