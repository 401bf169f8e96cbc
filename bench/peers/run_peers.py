#!/usr/bin/env python3
"""Traces the same seeds through the same AMR dataset with amrstream, yt and VTK.

Prints particle-steps per second of each and how far each one's traces are from amrstream's,
and writes the numbers to OUT_DIR/peers.json. See README.md beside this file.
"""

import argparse
import importlib
import json
import os
import platform
import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SYSTEM_PYTHON = "/usr/bin/python3"
MODULES = ("numpy", "yt", "vtk")
PACKAGES = ("python3-yt", "python3-vtk9", "python3-numpy")


def progress(message):
    print(f"[peers] {message}", file=sys.stderr, flush=True)


def missing_modules():
    missing = []
    for name in MODULES:
        try:
            importlib.import_module(name)
        except ImportError:
            missing.append(name)
    return missing


def system_python_has_modules():
    if not os.path.exists(SYSTEM_PYTHON):
        return False
    check = subprocess.run([SYSTEM_PYTHON, "-c", "import " + ", ".join(MODULES)],
                           capture_output=True)
    return check.returncode == 0


def apt_install():
    root = [] if os.geteuid() == 0 else ["sudo", "-n"]
    apt = root + ["env", "DEBIAN_FRONTEND=noninteractive", "apt-get"]
    progress(f"installing {' '.join(PACKAGES)} with apt-get")
    quiet = {"stdout": sys.stderr}  # keep stdout for the table
    if subprocess.run(apt + ["install", "-y", *PACKAGES], **quiet).returncode != 0:
        subprocess.run(apt + ["update"], **quiet)
        subprocess.run(apt + ["install", "-y", *PACKAGES], **quiet)


def ensure_packages():
    """Makes numpy, yt and vtk importable, installing Debian's packages when needed.

    Debian's packages install for /usr/bin/python3 only: an interpreter such as pyenv's or a
    virtual environment's does not see them, so the script then re-runs itself under it.
    """
    missing = missing_modules()
    if not missing:
        return
    if not system_python_has_modules():
        apt_install()
    if os.path.realpath(sys.executable) == os.path.realpath(SYSTEM_PYTHON):
        importlib.invalidate_caches()
        missing = missing_modules()
    elif system_python_has_modules():
        progress(f"{sys.executable} lacks {', '.join(missing)}: re-running under {SYSTEM_PYTHON}")
        os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON, *sys.argv])
    if missing:
        sys.exit(f"run_peers: cannot import {', '.join(missing)} even after "
                 f"'apt-get install {' '.join(PACKAGES)}'")


def parse_args():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default_binary = REPO / "build/src/cli/amrstream"
    parser.add_argument("--amrstream", default=str(default_binary) if default_binary.exists()
                        else shutil.which("amrstream") or "amrstream")
    parser.add_argument("--levels", type=int, default=4)
    parser.add_argument("--root-blocks", type=int, default=2)
    parser.add_argument("--target-cells", type=int, default=200000)
    parser.add_argument("--gen-seed", type=int, default=1)
    parser.add_argument("--data", help="an existing .exa dataset instead of generating one")
    parser.add_argument("--seeds-file", help="existing seeds (x y z per line, physical)")
    parser.add_argument("--seeds", type=int, default=64, help="seed count for --seed-density")
    parser.add_argument("--seed-density", default="dens", help="scalar of the paper's seeding")
    parser.add_argument("--vector", default="magx,magy,magz")
    parser.add_argument("--steps", type=int, default=500)
    parser.add_argument("--step-size", type=float, default=0.25,
                        help="H: our arc step is H x the local finest cell width; the peers' "
                             "step is H x the dataset's finest cell width")
    parser.add_argument("--backends", default="cpu",
                        help="amrstream backends, comma separated; the first is the reference")
    parser.add_argument("--repeat", type=int, default=3,
                        help="runs of amrstream and VTK (the fastest counts); yt runs once")
    parser.add_argument("--image-max-cells", type=int, default=1 << 24,
                        help="largest finest-resolution grid for the VTK image variant")
    parser.add_argument("--no-yt", action="store_true")
    parser.add_argument("--out-dir", default="peers-out")
    return parser.parse_args()


def prepare_inputs(args, out_dir):
    import ours
    if args.data:
        data = args.data
    else:
        progress(f"generating cloud: {args.levels} levels, {args.root_blocks}^3 root blocks, "
                 f"<= {args.target_cells} cells")
        data = ours.generate(args.amrstream, args.levels, args.root_blocks, args.target_cells,
                             args.gen_seed, out_dir / "cloud")
    seeds = args.seeds_file
    if not seeds:
        seeds = out_dir / "seeds.txt"
        ours.write_density_seeds(args.amrstream, data, args.seed_density, args.seeds, seeds,
                                 out_dir / "seeding.vtp")
    return str(data), str(seeds)


def fmt(value, spec):
    width = spec.split(".")[0]
    return format("-", width) if value is None else format(value, spec)


def print_table(rows):
    header = (f"{'method':<24}{'seeds':>6}{'steps':>9}{'seconds':>10}{'steps/s':>10}"
              f"{'ours/this':>10}{'median':>8}{'max':>8}{'common':>8}")
    print(header)
    print(f"{'':<24}{'':>6}{'taken':>9}{'':>10}{'':>10}{'':>10}"
          f"{'d/cell':>8}{'d/cell':>8}{'cells':>8}")
    for row in rows:
        d = row.get("distance") or {}
        print(f"{row['method']:<24}{row['lines']:>6}{row['steps']:>9}"
              f"{row['seconds']:>10.4f}{row['rate']:>10.3g}{fmt(row.get('ratio'), '>10.3g')}"
              f"{fmt(d.get('median_distance_cells'), '>8.3f')}"
              f"{fmt(d.get('max_distance_cells'), '>8.2f')}"
              f"{fmt(d.get('mean_common_length_cells'), '>8.1f')}")


def main():
    args = parse_args()
    ensure_packages()
    sys.path.insert(0, str(HERE))
    import numpy
    import yt

    import amr_blocks
    import distance
    import ours
    import peer_vtk

    out_dir = Path(args.out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    vector = args.vector.split(",")
    data, seeds_path = prepare_inputs(args, out_dir)
    blocks = amr_blocks.load(data)
    seeds = ours.read_seeds(seeds_path)
    cell = float(blocks.spacing.min())
    step = args.step_size * cell
    progress(f"{data}: {blocks.cell_count} cells, {len(blocks.levels)} levels, finest cell "
             f"{cell:g}; {len(seeds)} seeds, <= {args.steps} steps of {step:g} for the peers")

    results = []
    for backend in args.backends.split(","):
        progress(f"amrstream --backend {backend}")
        results.append(ours.trace(args.amrstream, data, seeds_path, args.step_size, args.steps,
                                  backend, vector, out_dir / f"ours-{backend}.vtp", args.repeat))
    if not args.no_yt:
        import peer_yt
        progress(f"yt: building grids and bricks, then up to {len(seeds) * args.steps} steps "
                 f"(about 5e4 steps/s)")
        results.append(peer_yt.trace(blocks, seeds, step, args.steps, vector))
    progress("VTK: vtkOverlappingAMR")
    results.append(peer_vtk.trace_amr(blocks, seeds, step, args.steps, vector, args.repeat))
    finest = peer_vtk.finest_cell_count(blocks)
    if finest <= args.image_max_cells:
        progress(f"VTK: vtkImageData of {finest} finest cells")
        results.append(peer_vtk.trace_image(blocks, seeds, step, args.steps, vector,
                                            args.repeat))
    else:
        progress(f"VTK image variant skipped: {finest} finest cells > --image-max-cells")

    reference = results[0]
    progress("comparing traces")
    for result in results:
        result["lines_traced"] = len(result["lines"])
        result["traced_length"] = sum(distance.arc_lengths(line.tolist())[-1]
                                      for line in result["lines"].values())
        result["rate"] = result["steps"] / result["seconds"] if result["seconds"] > 0 else 0.0
        result["ratio"] = reference["rate"] / result["rate"] if result["rate"] > 0 else None
        if result is not reference:
            result["distance"] = distance.compare_traces(reference["lines"], result["lines"],
                                                         cell)
    rows = [{**r, "lines": r["lines_traced"]} for r in results]
    print_table(rows)
    print(f"d: distance to {reference['method']} at equal arc length, in finest cells "
          f"({cell:g}); common: mean length compared")

    report = {
        "command": " ".join([Path(sys.executable).name, *sys.argv]),
        "versions": {"python": platform.python_version(), "numpy": numpy.__version__,
                     "yt": yt.__version__, "vtk": peer_vtk.version()},
        "dataset": {
            "data": data, "seeds_file": seeds_path, "cells": blocks.cell_count,
            "levels": len(blocks.levels), "finest_cell": cell,
            "domain": [list(map(float, corner)) for corner in blocks.domain],
            "generated": None if args.data else {
                "levels": args.levels, "root_blocks": args.root_blocks,
                "target_cells": args.target_cells, "gen_seed": args.gen_seed},
        },
        "seeds": len(seeds),
        "steps": args.steps,
        "step_size_cells": args.step_size,
        "peer_step": step,
        "reference": reference["method"],
        "methods": [{k: v for k, v in r.items() if k != "lines"} for r in results],
    }
    (out_dir / "peers.json").write_text(json.dumps(report, indent=2) + "\n")
    progress(f"wrote {out_dir / 'peers.json'}")


if __name__ == "__main__":
    main()
