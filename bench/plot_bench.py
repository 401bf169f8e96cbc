#!/usr/bin/python3
"""Plots `amrstream bench` results: particle-steps per second against particle count, log-log,
one line per backend and mode (solid: endpoints only, dashed: every step kept).

usage: plot_bench.py BENCH.json [MORE.json ...] --out PLOT.png

Several JSON files (say one from the GPU machine and one from lavapipe) go on one plot; each
line is labelled with its backend, mode and device.
"""
import argparse
import json
import sys

try:
    import matplotlib
except ImportError:
    sys.exit("plot_bench: needs matplotlib for /usr/bin/python3: sudo apt-get install python3-matplotlib")

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after choosing the backend)

STYLE = {"endpoints": "-", "history": "--"}
MARKER = {"compute": "o", "pipeline": "s", "rayquery": "^", "cpu": "D"}


def short_device(name):
    return name.split(" (")[0].split(",")[0]


def load(path):
    try:
        with open(path) as f:
            doc = json.load(f)
        return doc, doc["rows"]
    except (OSError, ValueError, KeyError) as e:
        sys.exit(f"plot_bench: {path}: not an amrstream bench JSON file ({e})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", nargs="+")
    parser.add_argument("--out", required=True)
    parser.add_argument("--title")
    args = parser.parse_args()

    fig, ax = plt.subplots(figsize=(8, 5.5), dpi=120)
    colours = {}
    datasets = []
    for path in args.json:
        doc, rows = load(path)
        d = doc["dataset"]
        datasets.append(f"{d['cells']:,} cells, {d['levels']} levels")
        lines = {}
        for row in rows:
            key = (row["backend"], row["mode"], short_device(row["device"]))
            lines.setdefault(key, []).append((row["particles"], row["steps_per_second"]))
        for (backend, mode, device), points in sorted(lines.items()):
            points.sort()
            colour = colours.setdefault((backend, device), f"C{len(colours) % 10}")
            ax.plot([p for p, _ in points], [r for _, r in points], color=colour,
                    linestyle=STYLE.get(mode, ":"), marker=MARKER.get(backend, "x"),
                    label=f"{backend} ({mode}) on {device}")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xlabel("particles")
    ax.set_ylabel("particle-steps per second")
    steps = doc["config"]["steps"]
    ax.set_title(args.title or f"amrstream bench: {'; '.join(sorted(set(datasets)))}, "
                 f"{steps} steps per particle", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    fig.savefig(args.out)
    print(f"plot_bench: wrote {args.out}")


if __name__ == "__main__":
    main()
