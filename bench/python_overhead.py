"""Python's overhead against the command line: the same trace of N seeds through the same
dataset, end to end (load, structure, trace, .vtp) and the trace call alone.

    /usr/bin/python3 bench/python_overhead.py --amrstream build/src/cli/amrstream \
        [--input builtin:cloud] [--seeds 65536] [--steps 200] [--backend compute] [--repeats 3]

Needs the module on PYTHONPATH (build/python) or installed. Prints a table and the ratios.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

import amrstream


def cli_run(exe, input_, seeds_file, steps, backend, out):
    start = time.perf_counter()
    result = subprocess.run([exe, "trace", input_, "--seeds", seeds_file, "--steps", str(steps),
                             "--backend", backend, "--direction", "both", "--out", out],
                            capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    tracing = float(re.search(r"^time\s+([0-9.]+) s tracing", result.stdout, re.M).group(1))
    setup = re.search(r"device setup ([0-9.]+) s", result.stdout)
    return wall, tracing, float(setup.group(1)) if setup else 0.0


def python_run(input_, seeds, steps, backend, out):
    start = time.perf_counter()
    ds = amrstream.load(input_)
    call = time.perf_counter()
    lines = amrstream.trace(ds, seeds, steps=steps, backend=backend, direction="both")
    call = time.perf_counter() - call
    lines.to_vtp(out)
    wall = time.perf_counter() - start
    return wall, lines.trace_seconds, lines.setup_seconds, call


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--amrstream", required=True)
    parser.add_argument("--input", default="builtin:cloud")
    parser.add_argument("--seeds", type=int, default=65536)
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--backend", default="compute")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()

    ds = amrstream.load(args.input)
    seeds = amrstream.seeds_random(ds, args.seeds, seed=5)
    with tempfile.TemporaryDirectory() as tmp:
        seeds_file = os.path.join(tmp, "seeds.txt")
        np.savetxt(seeds_file, seeds, fmt="%.17g")
        seeds = np.loadtxt(seeds_file)  # both read the same decimal seeds
        cli, py = [], []
        for _ in range(args.repeats):  # alternate, so drifts of the machine hit both
            cli.append(cli_run(args.amrstream, args.input, seeds_file, args.steps, args.backend,
                               os.path.join(tmp, "cli.vtp")))
            py.append(python_run(args.input, seeds, args.steps, args.backend,
                                 os.path.join(tmp, "py.vtp")))
    cli_wall, cli_trace, cli_setup = (min(r[i] for r in cli) for i in range(3))
    py_wall, py_trace, py_setup, py_call = (min(r[i] for r in py) for i in range(4))
    print(f"{args.input}, {args.seeds:,} seeds x {args.steps} steps, both directions, "
          f"backend {args.backend}; best of {args.repeats}")
    print(f"{'':34}{'command line':>14}{'Python':>10}{'ratio':>8}")
    print(f"{'end to end (load .. .vtp), s':34}{cli_wall:14.3f}{py_wall:10.3f}"
          f"{py_wall / cli_wall:8.3f}")
    print(f"{'device setup + tracing, s':34}{cli_setup + cli_trace:14.3f}"
          f"{py_setup + py_trace:10.3f}{(py_setup + py_trace) / (cli_setup + cli_trace):8.3f}")
    print(f"{'trace() call (structure, setup, tracing, result), s':34}{'':14}{py_call:10.3f}")


if __name__ == "__main__":
    sys.exit(main())
