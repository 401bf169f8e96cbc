"""Regenerates docs/images/slice_vs_yt_enzo.png and docs/images/slice_flash2d.png.

slice_vs_yt_enzo.png: yt SlicePlots of the Enzo moving7 sample across z through the density
maximum (400-pixel buffers, the velocity less the core's), left with yt's
annotate_line_integral_convolution and annotate_streamlines, right with amrstream's
annotate_amrstream_lic and annotate_amrstream_lines. Top: 0.1 code_length wide, over the density;
bottom: 0.04 wide, the LIC alone (opaque grey).

slice_flash2d.png: `amrstream slice` of the FLASH 2D nanowire sample's density.

Run it with the interpreter that has yt, with the built package on the path:
    PYTHONPATH=build/python /usr/bin/python3 docs/images/make_slice_vs_yt.py
"""

import argparse
import io
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import yt  # noqa: E402
from mpl_toolkits.axes_grid1 import ImageGrid  # noqa: E402
from PIL import Image  # noqa: E402

import amrstream  # noqa: E402,F401  (registers annotate_amrstream_lines and _lic with yt)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
ENZO = "/work/shared/data/real/enzo-moving7/DD0010/moving7_0010"
FLASH = "/work/shared/data/real/flash-2d-nanowire/nanowire_arrayhdf5_plt_cnt_0100"
CLI = os.path.join(ROOT, "build", "src", "cli", "amrstream")

DENSITY = ("enzo", "Density")
VELOCITY = ("x-velocity", "y-velocity", "z-velocity")
PIXELS = 400        # the plots' buffers, and the LICs' pixels
LIC_REACH = 16      # the LIC kernel's reach each way, in pixels, on both sides
LINE_DENSITY = 0.7  # streamplot's density; amrstream's lines lie 1/(30 density) of the width apart
YT_LIC_LIM = (0.5, 0.77)  # about the 2nd and 98th percentiles of yt's LIC here, as amrstream's


def slice_vs_yt(path: str, out: str) -> None:
    ds = yt.load(path)
    _, centre = ds.find_max(DENSITY)
    core = ds.sphere(centre, (0.005, "code_length"))
    frame = [core.quantities.weighted_average_quantity(("enzo", name), DENSITY)
             for name in VELOCITY]  # the core's velocity (code_velocity)
    for name, v0 in zip(VELOCITY, frame):  # for yt: the velocity less the core's
        ds.add_field(("gas", "core_v" + name[0]), units=str(v0.units), sampling_type="cell",
                     function=lambda field, data, name=name, v0=v0: data["enzo", name] - v0)
    in_plane = (("gas", "core_vx"), ("gas", "core_vy"))
    frame = [float(v) for v in frame]

    def plot(width: float, by: str, alone: bool) -> yt.AxisAlignedSlicePlot:
        """A SlicePlot `width` wide with `by`'s (yt's or amrstream's) LIC over the density
        and its lines, or with its LIC `alone` (opaque grey)."""
        p = yt.SlicePlot(ds, "z", DENSITY, center=centre, width=(width, "code_length"),
                         buff_size=(PIXELS, PIXELS))
        p.set_cmap(DENSITY, "viridis")
        p.set_font_size(13)
        lic = {"const_alpha": True, "alpha": 1.0, "cmap": "gray"} if alone else {}
        if by == "amrstream":
            p.annotate_amrstream_lic(vector=VELOCITY, frame_velocity=frame,
                                     lic_length=LIC_REACH * width / PIXELS, **lic)
            if not alone:
                p.annotate_amrstream_lines(vector=VELOCITY, frame_velocity=frame,
                                           density=LINE_DENSITY)
        else:
            p.annotate_line_integral_convolution(*in_plane, kernellen=2 * LIC_REACH,
                                                 lim=YT_LIC_LIM, **lic)
            if not alone:
                p.annotate_streamlines(*in_plane, density=LINE_DENSITY, color="white")
        return p

    panels = [(plot(0.1, "yt", False), "(a) yt: annotate_line_integral_convolution\n"
               "+ annotate_streamlines"),
              (plot(0.1, "amrstream", False), "(b) amrstream: annotate_amrstream_lic\n"
               "+ annotate_amrstream_lines"),
              (plot(0.04, "yt", True), "(c) yt's LIC alone,\n0.04 code_length wide"),
              (plot(0.04, "amrstream", True), "(d) amrstream's LIC alone,\n"
               "0.04 code_length wide")]
    figure = plt.figure(figsize=(10, 10))  # 120 dpi: axes of about the buffers' 400 pixels
    grids = [ImageGrid(figure, (0.08, 0.55 - 0.47 * row, 0.84, 0.34), nrows_ncols=(1, 2),
                       axes_pad=1.0, label_mode="all", cbar_location="right",
                       cbar_mode="single", cbar_size="5%", cbar_pad="2%")
             for row in range(2)]  # top: (a), (b) and the density's colour bar; bottom: (c), (d)
    for k, (p, title) in enumerate(panels):
        grid = grids[k // 2]
        drawn = p.plots[DENSITY]
        drawn.figure, drawn.axes, drawn.cax = figure, grid[k % 2].axes, grid.cbar_axes[0]
        if k >= 2:
            p.hide_colorbar()
        p.render()
        grid[k % 2].axes.set_title(title, fontsize=12)
    grids[1].cbar_axes[0].set_visible(False)
    image = io.BytesIO()
    figure.savefig(image, dpi=120, bbox_inches="tight")
    plt.close(figure)
    # 256 colours (libimagequant): much the same look in 0.46 MB instead of 1.2 MB of RGB.
    Image.open(image).convert("RGB").quantize(256, method=Image.Quantize.LIBIMAGEQUANT).save(
        out, optimize=True)


def slice_flash2d(cli: str, path: str, out: str) -> None:
    subprocess.run([cli, "slice", path, "--no-lines", "--background", "dens", "--colour-scale",
                    "log", "--width", "240", "--window", "-1e-4,7e-4,1e-4,1.7e-3",
                    "--out", out], check=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--enzo", default=ENZO, help="the Enzo moving7 parameter file")
    parser.add_argument("--flash", default=FLASH, help="the FLASH 2D nanowire plotfile")
    parser.add_argument("--cli", default=CLI, help="the amrstream command")
    parser.add_argument("--out", default=HERE, help="the folder the PNGs go to")
    args = parser.parse_args()
    yt.set_log_level("error")
    slice_vs_yt(args.enzo, os.path.join(args.out, "slice_vs_yt_enzo.png"))
    slice_flash2d(args.cli, args.flash, os.path.join(args.out, "slice_flash2d.png"))


if __name__ == "__main__":
    main()
