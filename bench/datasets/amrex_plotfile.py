#!/usr/bin/env python3
"""Writes a synthetic two-level AMReX plotfile (HyperCLaw-V1.1) for benchmarks of the AMReX
reader and of ranks reading their parts over data.

Level 0 is N^3 cells in boxes of B^3; level 1 (ratio 2) refines the middle half of the domain
along each axis, in boxes of B^3. Four float64 variables, component-major, x fastest:
x_velocity, y_velocity, z_velocity (a swirl about the z axis with a vertical wave) and density
(a Gaussian blob). Usage: amrex_plotfile.py OUT_DIR [--cells N] [--box B]."""

import argparse
import os

import numpy as np

NAMES = ["x_velocity", "y_velocity", "z_velocity", "density"]


def values(lo, hi, dx):
    """The variables at the cell centres of the box [lo, hi] (inclusive) of spacing dx."""
    axes = [(np.arange(lo[a], hi[a] + 1) + 0.5) * dx - 0.5 for a in range(3)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    r2 = x * x + y * y + z * z
    return [-y, x, 0.3 * np.sin(6.0 * x), np.exp(-8.0 * r2)]


def boxes(lo, hi, size):
    """Boxes of size^3 tiling [lo, hi) (inclusive bounds, x fastest)."""
    out = []
    for k in range(lo, hi, size):
        for j in range(lo, hi, size):
            for i in range(lo, hi, size):
                out.append(((i, j, k), (i + size - 1, j + size - 1, k + size - 1)))
    return out


def box_text(box):
    (a, b) = box
    return "((%d,%d,%d) (%d,%d,%d) (0,0,0))" % (a + b)


def write_level(out, level, level_boxes, dx):
    os.makedirs(os.path.join(out, "Level_%d" % level), exist_ok=True)
    offsets = []
    with open(os.path.join(out, "Level_%d" % level, "Cell_D_00000"), "wb") as data:
        for box in level_boxes:
            offsets.append(data.tell())
            # IEEE float64, little endian, as AMReX writes it.
            header = "FAB ((8, (64 11 52 0 1 12 0 1023)),(8, (8 7 6 5 4 3 2 1)))%s %d\n" % (
                box_text(box), len(NAMES))
            data.write(header.encode())
            for v in values(box[0], box[1], dx):
                data.write(np.ascontiguousarray(v, dtype="<f8").tobytes())
    with open(os.path.join(out, "Level_%d" % level, "Cell_H"), "w") as h:
        h.write("1\n1\n%d\n0\n(%d 0\n" % (len(NAMES), len(level_boxes)))
        for box in level_boxes:
            h.write(box_text(box) + "\n")
        h.write(")\n%d\n" % len(level_boxes))
        for offset in offsets:
            h.write("FabOnDisk: Cell_D_00000 %d\n" % offset)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("--cells", type=int, default=256, help="level-0 cells per axis")
    parser.add_argument("--box", type=int, default=32, help="cells per box side")
    a = parser.parse_args()
    n, b = a.cells, a.box
    if n % (2 * b):
        parser.error("--cells must be a multiple of twice --box")
    dx0, dx1 = 1.0 / n, 0.5 / n
    level0 = boxes(0, n, b)
    level1 = boxes(n // 2, n // 2 + n, b)  # the middle half, in level-1 cells
    os.makedirs(a.out, exist_ok=True)
    write_level(a.out, 0, level0, dx0)
    write_level(a.out, 1, level1, dx1)
    with open(os.path.join(a.out, "Header"), "w") as h:
        h.write("HyperCLaw-V1.1\n%d\n%s\n3\n0\n1\n" % (len(NAMES), "\n".join(NAMES)))
        h.write("0 0 0\n1 1 1\n2\n")
        h.write("((0,0,0) (%d,%d,%d) (0,0,0)) ((0,0,0) (%d,%d,%d) (0,0,0))\n"
                % ((n - 1,) * 3 + (2 * n - 1,) * 3))
        h.write("0 0\n%r %r %r\n%r %r %r\n0\n0\n" % ((dx0,) * 3 + (dx1,) * 3))
        for level, (level_boxes, dx) in enumerate([(level0, dx0), (level1, dx1)]):
            h.write("%d %d 0\n0\n" % (level, len(level_boxes)))
            for (lo, hi) in level_boxes:
                for axis in range(3):
                    h.write("%r %r\n" % (lo[axis] * dx, (hi[axis] + 1) * dx))
            h.write("Level_%d/Cell\n" % level)


if __name__ == "__main__":
    main()
