"""Streamlines through the collapsing core of a real Enzo run, loaded with yt.

    /usr/bin/python3 enzo_field_lines.py PATH/TO/DD0010/moving7_0010 [OUT_PREFIX]

Writes OUT_PREFIX_matplotlib.png (the lines projected on the x-y plane, coloured by density),
OUT_PREFIX_render.png (amrstream's tube renderer) and OUT_PREFIX.vtp (for ParaView).
"""

import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import yt
from matplotlib.collections import LineCollection
from matplotlib.colors import LogNorm

import amrstream

path = sys.argv[1]
out = sys.argv[2] if len(sys.argv) > 2 else "enzo"
yt.set_log_level(40)

ds = amrstream.from_yt(yt.load(path), vector=("x-velocity", "y-velocity", "z-velocity"),
                       fields=["Density"])
print(ds)

# The gas moves with a bulk flow of about (0.6, 0.6, 0.6): streamlines of the velocity relative
# to the dense core show the collapse. numpy in, a new Dataset out (the same cells).
density = ds.field("Density")
core = density >= np.quantile(density, 0.999)
relative = {}
for axis, name in zip("xyz", ("x-velocity", "y-velocity", "z-velocity")):
    v = ds.field(name)
    relative["v" + axis] = v - np.average(v[core], weights=density[core])
relative["Density"] = density
relative["log10 Density"] = np.log10(density)
frame = amrstream.from_arrays(ds.corners, ds.levels, relative, origin=ds.origin,
                              finest_width=ds.finest_width, periodic=ds.periodic,
                              source=ds.source + " (core frame)")

seeds = amrstream.seeds_densest(frame, "Density", 128, percentile=99.5, seed=7)
start = time.perf_counter()
lines = amrstream.trace(frame, seeds, steps=4000, max_length=0.04)  # both directions
print(f"{lines}: {lines.steps.sum():,} steps in {time.perf_counter() - start:.2f} s")

density = lines.point_data["Density"]
segments, colours = [], []
for i, points in enumerate(lines):
    first = int(lines.offsets[i])
    segments.append(points[:, :2])
    colours.append(density[first:first + len(points)].mean())
fig, ax = plt.subplots(figsize=(6, 5))
collection = LineCollection(segments, array=np.array(colours), cmap="magma", norm=LogNorm(),
                            linewidths=0.6)
ax.add_collection(collection)
ax.autoscale()
ax.set_aspect("equal")
ax.set_xlabel("x (code length)")
ax.set_ylabel("y (code length)")
fig.colorbar(collection, label="mean Density along the line (code units)")
ax.set_title(f"{len(lines)} streamlines of the velocity in the core's frame")
fig.savefig(f"{out}_matplotlib.png", dpi=110, bbox_inches="tight")

low, high = lines.points.min(axis=0), lines.points.max(axis=0)
image = lines.render(width=800, height=500, colour_by="log10 Density", colour_map="magma",
                     tube_radius=0.15, view_box=(*low, *high), camera=(30, 20, 1.4), frames=8)
plt.imsave(f"{out}_render.png", image)
print("wrote", lines.to_vtp(f"{out}.vtp"), "polylines and points to", f"{out}.vtp")
