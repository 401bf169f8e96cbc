"""Runs the amrstream command line and reads its .vtp traces."""

import re
import subprocess

import numpy as np
import vtk

from peer_vtk import polylines


def run(command):
    done = subprocess.run([str(c) for c in command], capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, command))} failed ({done.returncode}):\n"
                           f"{done.stdout}{done.stderr}")
    return done.stdout


def generate(amrstream, levels, root_blocks, target_cells, gen_seed, prefix):
    run([amrstream, "gen", "cloud", "--levels", levels, "--root-blocks", root_blocks,
         "--target-cells", target_cells, "--seed", gen_seed, "--out", prefix])
    return f"{prefix}.exa"


def write_density_seeds(amrstream, data, channel, count, seeds_path, scratch_vtp):
    run([amrstream, "trace", data, "--seed-density", channel, "--count", count,
         "--seeds-out", seeds_path, "--steps", 1, "--backend", "cpu", "--out", scratch_vtp])


def read_seeds(path):
    seeds = []
    with open(path) as lines:
        for line in lines:
            words = line.split("#", 1)[0].replace(",", " ").split()
            if words:
                seeds.append([float(w) for w in words])
    return np.array(seeds, dtype=np.float64).reshape(-1, 3)


def parse_summary(text):
    """Steps taken and tracing rate from `amrstream trace`'s summary."""
    steps = re.search(r"^steps\s+([\d,]+) taken", text, re.M)
    timing = re.search(r"^time\s+(\S+) s, (\S+) particle-steps/s", text, re.M)
    backend = re.search(r"^tracing\s+(.*)$", text, re.M)
    if not steps or not timing:
        raise RuntimeError(f"unexpected output of amrstream trace:\n{text}")
    return {
        "steps": int(steps.group(1).replace(",", "")),
        "printed_seconds": float(timing.group(1)),
        # the rate is printed from the unrounded time; the seconds only to 1 ms
        "rate": float(timing.group(2)),
        "tracing": backend.group(1) if backend else "",
    }


def trace(amrstream, data, seeds_path, step_size, steps, backend, vector, out_vtp, repeat=1):
    command = [amrstream, "trace", data, "--vector", ",".join(vector), "--seeds", seeds_path,
               "--step-mode", "arc", "--step-size", step_size, "--steps", steps,
               "--backend", backend, "--out", out_vtp]
    runs = [parse_summary(run(command)) for _ in range(repeat)]
    best = max(runs, key=lambda r: r["rate"])
    return {
        "method": f"amrstream {backend}",
        "command": " ".join(map(str, command)),
        "tracing": best["tracing"],
        "steps": best["steps"],
        "seconds": best["steps"] / best["rate"] if best["rate"] > 0 else best["printed_seconds"],
        "lines": read_vtp_lines(out_vtp),
    }


def read_vtp_lines(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    polydata = reader.GetOutput()
    if polydata.GetNumberOfPoints() == 0:
        raise RuntimeError(f"{path}: no traces")
    return polylines(polydata)
