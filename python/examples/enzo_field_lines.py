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

VECTOR = ("x-velocity", "y-velocity", "z-velocity")
ds = amrstream.from_yt(yt.load(path), vector=VECTOR, fields=["Density"])
print(ds)

# The gas moves with a bulk flow of about (0.6, 0.6, 0.6): streamlines of the velocity relative
# to the dense core show the collapse. The core's velocity comes from numpy, weighted by density.
density = ds.field("Density")
core = density >= np.quantile(density, 0.999)
core_velocity = [float(np.average(ds.field(name)[core], weights=density[core])) for name in VECTOR]

seeds = amrstream.seeds_densest(ds, "Density", 128, percentile=99.5, seed=7)
start = time.perf_counter()
lines = amrstream.trace(ds, seeds, vector=VECTOR, frame_velocity=core_velocity, steps=4000,
                        max_length=0.04)  # both directions
print(f"{lines}: {lines.steps.sum():,} steps in {time.perf_counter() - start:.2f} s")

density = lines.point_data["Density"]
segments, colours = [], []
for i in range(len(lines)):
    first, last = int(lines.offsets[i]), int(lines.offsets[i + 1])
    for piece in lines.pieces(i):  # cut where the line crosses a periodic face
        segments.append(piece[:, :2])
        colours.append(density[first:last].mean())
fig, ax = plt.subplots(figsize=(6, 5))
collection = LineCollection(segments, array=np.array(colours), cmap="magma", norm=LogNorm(),
                            linewidths=0.6)
ax.add_collection(collection)
ax.autoscale()
ax.set_aspect("equal")
ax.set_xlabel(f"x [{ds.length_unit}]")
ax.set_ylabel(f"y [{ds.length_unit}]")
fig.colorbar(collection, label="mean Density along the line (code units)")
ax.set_title(f"{len(lines)} streamlines of the velocity in the core's frame")
fig.savefig(f"{out}_matplotlib.png", dpi=110, bbox_inches="tight")

# The default camera looks at the lines side on and frames them.
image = lines.render(width=800, height=500, colour_by="Density", colour_scale="log",
                     colour_map="magma", axes=True, frames=8)
plt.imsave(f"{out}_render.png", image)
print("wrote", lines.to_vtp(f"{out}.vtp"), "polylines and points to", f"{out}.vtp")
