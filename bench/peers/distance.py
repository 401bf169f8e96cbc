"""Distance between two traces of one seed, compared at equal arc length.

Plain Python (no numpy), so that the unit test runs under any python3.
"""

import bisect
import math


def arc_lengths(points):
    """Cumulative arc length at each point of a polyline."""
    lengths = [0.0]
    for a, b in zip(points, points[1:]):
        lengths.append(lengths[-1] + math.dist(a, b))
    return lengths


def point_at(points, lengths, s):
    """The point at arc length s along the polyline (linear between its points)."""
    i = min(max(bisect.bisect_right(lengths, s) - 1, 0), len(points) - 2)
    span = lengths[i + 1] - lengths[i]
    t = 0.0 if span == 0 else (s - lengths[i]) / span
    return [p + t * (q - p) for p, q in zip(points[i], points[i + 1])]


def curve_distances(a, b, delta):
    """Distances between polylines a and b at s = 0, delta, 2 delta, ... up to the shorter length.

    Returns (distances, common length). A line with a single point has length 0 and gives the
    distance between the two first points.
    """
    a = [[float(c) for c in p] for p in a]
    b = [[float(c) for c in p] for p in b]
    if not a or not b:
        return [], 0.0
    if len(a) == 1 or len(b) == 1:
        return [math.dist(a[0], b[0])], 0.0
    la, lb = arc_lengths(a), arc_lengths(b)
    common = min(la[-1], lb[-1])
    count = int(math.floor(common / delta)) + 1
    distances = [math.dist(point_at(a, la, k * delta), point_at(b, lb, k * delta))
                 for k in range(count)]
    return distances, common


def median(values):
    ordered = sorted(values)
    n = len(ordered)
    if n == 0:
        return float("nan")
    return ordered[n // 2] if n % 2 else 0.5 * (ordered[n // 2 - 1] + ordered[n // 2])


def compare_traces(ours, theirs, delta):
    """Summary over all seeds: ours and theirs map a seed index to its polyline.

    Seeds missing from either side are counted in 'missing'. Distances are in the units of the
    points; delta is the sampling interval (and the unit of the '_cells' values).
    """
    everything, commons, missing = [], [], 0
    for seed, line in ours.items():
        if seed not in theirs:
            missing += 1
            continue
        distances, common = curve_distances(line, theirs[seed], delta)
        everything.extend(distances)
        commons.append(common)
    missing += sum(1 for seed in theirs if seed not in ours)
    result = {
        "compared_seeds": len(commons),
        "missing_seeds": missing,
        "samples": len(everything),
        "median_distance": median(everything),
        "max_distance": max(everything) if everything else float("nan"),
        "mean_common_length": sum(commons) / len(commons) if commons else float("nan"),
    }
    for key in ("median_distance", "max_distance", "mean_common_length"):
        result[key + "_cells"] = result[key] / delta
    return result
