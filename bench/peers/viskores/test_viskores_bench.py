#!/usr/bin/env python3
"""Tests of viskores_bench on small synthetic grids (standard library only).

    python3 bench/peers/viskores/test_viskores_bench.py BUILD/viskores_bench [WORKDIR] [-- VISKORES ARGS]
    python3 bench/peers/viskores/test_viskores_bench.py BUILD/viskores_bench WORKDIR --perf 256 [-- ...]

Writes .vti files in amrstream's layout (appended raw data, UInt64 headers, offsets padded with
spaces, a FieldData block and a vtkValidPointMask) holding the rotation v = (-(y - cy), x - cx,
0.1) about the box's centre axis, and checks that
  - particles keep their distance to the axis and end where the exact rotation puts them,
  - particles that stay inside take exactly --steps steps, those leaving through the top about
    (top - z0) / (0.1 h) steps, and seeds outside the box take none,
  - the end points of ParticleAdvection equal the last points of the Streamline lines,
  - the JSON is valid and its particle-steps agree with the dump,
  - bad input (missing, truncated, compressed, wrong sizes, bad options) gives an error message
    and a non-zero exit, never a crash.
Arguments after `--` go to viskores_bench (for example --viskores-device=Cuda).
`--perf N` instead runs a benchmark-sized case (numpy needed): an N^3 rotation grid, 2^20 seeds,
rows of 2^16 and 2^20 particles (`--perf-particles LIST`), 1000 steps.
"""

import json
import math
import os
import struct
import subprocess
import sys

NX, NY, NZ = 32, 32, 32
ORIGIN = (0.5, -1.0, 2.0)
SPACING = (0.1, 0.1, 0.05)
CX = ORIGIN[0] + 0.5 * (NX - 1) * SPACING[0]
CY = ORIGIN[1] + 0.5 * (NY - 1) * SPACING[1]
ZTOP = ORIGIN[2] + (NZ - 1) * SPACING[2]
VZ = 0.1
STEP = 0.05
STEPS = 200


def field(x, y, z):
    return (-(y - CY), x - CX, VZ)


def vti_bytes(nx=NX, ny=NY, nz=NZ, vector_name="vel", header_type="UInt64", compressor=None,
              extent_nx=None, encoding="raw", fmt="appended", byte_order="LittleEndian",
              invalid=()):
    """amrstream's layout; the keyword arguments produce broken variants."""
    n = nx * ny * nz
    hb = 8 if header_type == "UInt64" else 4
    hpack = "<Q" if hb == 8 else "<I"
    vec = bytearray()
    dens = bytearray()
    mask = bytearray()
    invalid = set(invalid)
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                x = ORIGIN[0] + i * SPACING[0]
                y = ORIGIN[1] + j * SPACING[1]
                z = ORIGIN[2] + k * SPACING[2]
                idx = i + nx * (j + ny * k)
                if idx in invalid:
                    vec += struct.pack("<3f", 0.0, 0.0, 0.0)
                    mask.append(0)
                else:
                    vec += struct.pack("<3f", *field(x, y, z))
                    mask.append(1)
                dens += struct.pack("<f", x + y + z)
    blocks = [bytes(vec), bytes(dens), bytes(mask)]
    offsets = []
    data = bytearray()
    for b in blocks:
        offsets.append(len(data))
        data += struct.pack(hpack, len(b)) + b
    enx = nx if extent_nx is None else extent_nx
    ext = f"0 {enx - 1} 0 {ny - 1} 0 {nz - 1}"
    comp = f' compressor="{compressor}"' if compressor else ""
    head = (
        '<?xml version="1.0"?>\n'
        f'<VTKFile type="ImageData" version="1.0" byte_order="{byte_order}" '
        f'header_type="{header_type}"{comp}>\n'
        f'  <ImageData WholeExtent="{ext}" Origin="{ORIGIN[0]} {ORIGIN[1]} {ORIGIN[2]}" '
        f'Spacing="{SPACING[0]} {SPACING[1]} {SPACING[2]}">\n'
        '    <FieldData>\n'
        '      <DataArray type="Float64" Name="TimeValue" NumberOfTuples="1" format="ascii">0'
        '</DataArray>\n'
        '    </FieldData>\n'
        f'    <Piece Extent="{ext}">\n'
        f'      <PointData Vectors="{vector_name}" Scalars="dens">\n'
        f'        <DataArray type="Float32" Name="{vector_name}" NumberOfComponents="3" '
        f'format="{fmt}" offset="{offsets[0]:<12}"/>\n'
        f'        <DataArray type="Float32" Name="dens" NumberOfComponents="1" format="{fmt}" '
        f'offset="  {offsets[1]}  "   />\n'
        f'        <DataArray type="UInt8" Name="vtkValidPointMask" NumberOfComponents="1" '
        f'format="{fmt}" offset="{offsets[2]}"          />\n'
        '      </PointData>\n'
        '    </Piece>\n'
        '  </ImageData>\n'
        f'  <AppendedData encoding="{encoding}">\n'
        '   _')
    tail = b'\n  </AppendedData>\n</VTKFile>\n'
    return head.encode() + bytes(data) + tail


def seeds():
    """(x, y, z) seeds: a ring of radii inside, some low (stay inside), some high (leave through
    the top), and two outside the box."""
    out = []
    for r_i, r in enumerate((0.2, 0.5, 0.9, 1.3)):
        for a_i in range(8):
            ang = 2 * math.pi * a_i / 8 + 0.3 * r_i
            z = ORIGIN[2] + 0.05 + 0.02 * a_i          # low: 200 steps rise by 1.0 < 1.55-0.19
            if a_i % 4 == 3:
                z = ZTOP - 0.1 - 0.05 * r_i            # high: leaves through the top
            out.append((CX + r * math.cos(ang), CY + r * math.sin(ang), z))
    out.append((ORIGIN[0] - 1.0, CY, ORIGIN[2] + 0.5))   # outside in x
    out.append((CX, CY + 0.3, ZTOP + 0.5))               # outside in z
    return out


def exact_end(p, steps):
    t = steps * STEP
    dx, dy = p[0] - CX, p[1] - CY
    c, s = math.cos(t), math.sin(t)
    return (CX + c * dx - s * dy, CY + s * dx + c * dy, p[2] + VZ * t)


def run(cmd, **kw):
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


FAILURES = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        FAILURES.append(what)


def perf(exe, work, n, particles, extra):
    """A benchmark-sized run (needs numpy): an n^3 grid of the rotation on the unit cube, random
    seeds, rows of `particles`, 1000 steps of a quarter grid spacing."""
    import numpy as np
    h = 1.0 / (n - 1)
    ax = np.arange(n, dtype=np.float64) * h
    z, y, x = np.meshgrid(ax, ax, ax, indexing="ij")   # x fastest in C order
    vec = np.empty((n, n, n, 3), dtype="<f4")
    vec[..., 0] = -(y - 0.5)
    vec[..., 1] = x - 0.5
    vec[..., 2] = VZ
    del x, y, z
    vb = vec.tobytes()
    mask = np.ones(n * n * n, dtype=np.uint8).tobytes()
    head = (
        '<?xml version="1.0"?>\n'
        '<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian" header_type="UInt64">\n'
        f'  <ImageData WholeExtent="0 {n-1} 0 {n-1} 0 {n-1}" Origin="0 0 0" '
        f'Spacing="{h!r} {h!r} {h!r}">\n'
        f'    <Piece Extent="0 {n-1} 0 {n-1} 0 {n-1}">\n'
        '      <PointData Vectors="vel">\n'
        '        <DataArray type="Float32" Name="vel" NumberOfComponents="3" format="appended" '
        'offset="0"/>\n'
        '        <DataArray type="UInt8" Name="vtkValidPointMask" NumberOfComponents="1" '
        f'format="appended" offset="{8 + len(vb)}"/>\n'
        '      </PointData>\n    </Piece>\n  </ImageData>\n'
        '  <AppendedData encoding="raw">\n   _')
    grid = os.path.join(work, f"rot{n}.vti")
    with open(grid, "wb") as f:
        f.write(head.encode())
        f.write(struct.pack("<Q", len(vb)))
        f.write(vb)
        f.write(struct.pack("<Q", len(mask)))
        f.write(mask)
        f.write(b"\n  </AppendedData>\n</VTKFile>\n")
    del vb, vec
    rng = np.random.default_rng(1)
    count = max(int(c) for c in particles.split(","))
    # Within 0.4 of the axis and low enough to stay inside for 1000 steps: every line is full.
    rad = 0.4 * np.sqrt(rng.uniform(0, 1, size=count))
    ang = rng.uniform(0, 2 * np.pi, size=count)
    pts = np.stack([0.5 + rad * np.cos(ang), 0.5 + rad * np.sin(ang),
                    rng.uniform(0.05, 0.4, size=count)], axis=1)
    seeds = os.path.join(work, "seeds_perf.txt")
    np.savetxt(seeds, pts, fmt="%.17g")
    cmd = [exe, "--grid", grid, "--seeds", seeds, "--particles", particles, "--steps",
           "1000", "--step-size", repr(0.25 * h), "--repeats", "3",
           "--json", os.path.join(work, "perf.json")] + extra
    print(" ".join(cmd), flush=True)
    r = subprocess.run(cmd)
    check(r.returncode == 0, f"perf run on {n}^3")
    return 1 if FAILURES else 0


def main():
    argv = sys.argv[1:]
    extra = []
    if "--" in argv:
        extra = argv[argv.index("--") + 1:]
        argv = argv[:argv.index("--")]
    perf_n, perf_particles = 0, "65536,1048576"
    if "--perf" in argv:
        i = argv.index("--perf")
        perf_n = int(argv[i + 1])
        del argv[i:i + 2]
    if "--perf-particles" in argv:
        i = argv.index("--perf-particles")
        perf_particles = argv[i + 1]
        del argv[i:i + 2]
    if not argv:
        print(__doc__)
        return 2
    exe = os.path.abspath(argv[0])
    work = os.path.abspath(argv[1] if len(argv) > 1 else "/tmp/vkbench-test")
    os.makedirs(work, exist_ok=True)
    if perf_n:
        return perf(exe, work, perf_n, perf_particles, extra)

    grid = os.path.join(work, "rot.vti")
    invalid_idx = [0, 1, NX * NY * NZ - 1]
    with open(grid, "wb") as f:
        f.write(vti_bytes(invalid=invalid_idx))
    seed_list = seeds()
    seed_file = os.path.join(work, "seeds.txt")
    with open(seed_file, "w") as f:
        f.write("# x y z, as amrstream --seeds-out writes them\n")
        for p in seed_list:
            f.write("%.17g %.17g %.17g\n" % p)
    n_all = len(seed_list)
    counts = [16, n_all]

    # ---- the good run --------------------------------------------------------------------------
    jpath = os.path.join(work, "out.json")
    dump = os.path.join(work, "dump")
    for order in ("given", "spatial"):
        cmd = [exe, "--grid", grid, "--seeds", seed_file, "--particles",
               ",".join(map(str, counts)), "--steps", str(STEPS), "--step-size", str(STEP),
               "--repeats", "2", "--json", jpath, "--dump", dump, "--seed-order", order] + extra
        r = run(cmd)
        print(r.stdout)
        if r.returncode != 0:
            print(r.stderr)
        check(r.returncode == 0, f"good grid runs (seed order {order})")
        if r.returncode != 0:
            continue
        check(r.stdout.splitlines()[0].startswith("device     Viskores"),
              "first line names the device")
        check("invalid points (vtkValidPointMask = 0): 3" in r.stdout, "3 invalid points reported")
        with open(jpath) as f:
            js = json.load(f)
        check(js["grid"]["dims"] == [NX, NY, NZ], "JSON grid dims")
        check(len(js["rows"]) == 2 * len(counts), "JSON has endpoints and history rows")

        for n in counts:
            used = seed_list[:n]
            lines = []
            with open(f"{dump}-{n}-history.txt") as f:
                for line in f:
                    if line.startswith("#"):
                        continue
                    v = line.split()
                    lines.append((int(v[0]), tuple(map(float, v[1:4])), tuple(map(float, v[4:7]))))
            ends = []
            with open(f"{dump}-{n}-endpoints.txt") as f:
                for line in f:
                    if not line.startswith("#"):
                        ends.append(tuple(map(float, line.split())))
            inside = [p for p in used
                      if ORIGIN[0] <= p[0] <= ORIGIN[0] + (NX - 1) * SPACING[0]
                      and ORIGIN[1] <= p[1] <= ORIGIN[1] + (NY - 1) * SPACING[1]
                      and ORIGIN[2] <= p[2] <= ZTOP]
            check(len(lines) == len(inside), f"n={n}: one line per seed inside the box "
                  f"({len(lines)} lines, {len(inside)} inside)")
            check(len(ends) == len(lines), f"n={n}: as many end points as lines")
            # Match lines to seeds by their first point.
            worst_r, worst_exit_r, worst_end, bad_steps, total = 0.0, -1.0, 0.0, [], 0
            for (np_, first, last) in lines:
                seed = min(inside, key=lambda p: sum((a - b) ** 2 for a, b in zip(p, first)))
                dseed = math.dist(seed, first)
                if dseed > 1e-5:
                    bad_steps.append(("seed not found", first))
                    continue
                steps = np_ - 1
                total += steps
                r0 = math.hypot(seed[0] - CX, seed[1] - CY)
                r1 = math.hypot(last[0] - CX, last[1] - CY)
                rise = ZTOP - seed[2]
                if VZ * STEPS * STEP < rise - 1e-6:           # stays inside
                    worst_r = max(worst_r, abs(r1 - r0))
                    if steps != STEPS:
                        bad_steps.append((steps, seed))
                    worst_end = max(worst_end, math.dist(last, exact_end(seed, STEPS)))
                else:                                          # leaves through the top
                    expect = rise / (VZ * STEP)
                    if not (math.floor(expect) <= steps <= math.ceil(expect) + 1):
                        bad_steps.append((steps, expect, seed))
                    # Viskores ends such a line with an Euler "push-out" step: bisection to the
                    # boundary, then one Euler step of up to h past it, which moves off the
                    # circle by up to r h^2 / 2.
                    worst_exit_r = max(worst_exit_r, abs(r1 - r0) - r0 * STEP ** 2 / 2)
                    check(last[2] >= ZTOP - 1e-5 and last[2] <= ZTOP + VZ * STEP + 1e-4,
                          f"n={n}: line leaving at the top ends just past z={ZTOP:.3f} "
                          f"(z={last[2]:.6f}, {steps} steps, {expect:.2f} expected)")
            check(not bad_steps, f"n={n}: step counts as expected {bad_steps[:3]}")
            check(worst_r < 2e-5, f"n={n}: lines inside keep their distance to the axis "
                  f"(worst change {worst_r:.2e})")
            check(worst_exit_r < 2e-5, f"n={n}: lines leaving through the top keep it but for "
                  f"the last (Euler) step (worst excess {worst_exit_r:.2e})")
            check(worst_end < 5e-5, f"n={n}: end points match the exact rotation "
                  f"(worst {worst_end:.2e})")
            # ParticleAdvection end points vs. Streamline last points (as sets).
            a = sorted(ends)
            b = sorted(l[2] for l in lines)
            diff = max((math.dist(p, q) for p, q in zip(a, b)), default=0.0)
            check(len(a) == len(b) and diff < 1e-5,
                  f"n={n}: ParticleAdvection end points == Streamline last points "
                  f"(max {diff:.2e})")
            rows = [r_ for r_ in js["rows"] if r_["particles"] == n]
            check(all(r_["steps"] == total for r_ in rows),
                  f"n={n}: JSON particle-steps {[r_['steps'] for r_ in rows]} == dump {total}")
            check(all(r_["seeds_traced"] == sum(1 for l in lines if l[0] > 1) for r_ in rows),
                  f"n={n}: seeds traced")
            check(all(r_["full_lines"] == sum(1 for l in lines if l[0] == STEPS + 1)
                      for r_ in rows), f"n={n}: full-length lines")

    # ---- --normalize and the UInt32 header -----------------------------------------------------
    g32 = os.path.join(work, "rot32.vti")
    with open(g32, "wb") as f:
        f.write(vti_bytes(header_type="UInt32"))
    r = run([exe, "--grid", g32, "--seeds", seed_file, "--particles", "8", "--steps", "10",
             "--step-size", "0.01", "--repeats", "1", "--normalize"] + extra)
    check(r.returncode == 0 and "normalised" in r.stdout, "UInt32 header and --normalize run")

    # ---- error paths ---------------------------------------------------------------------------
    good = vti_bytes()
    cases = {
        "missing": None,
        "truncated_data": good[: len(good) // 2],
        "truncated_header": good[:300],
        "truncated_after_vector": good[: good.index(b"_") + 1 + 8 + NX * NY * NZ * 12 + 20],
        "empty": b"",
        "compressed": vti_bytes(compressor="vtkZLibDataCompressor"),
        "wrong_sizes": vti_bytes(extent_nx=NX + 1),
        "base64": vti_bytes(encoding="base64"),
        "binary_format": vti_bytes(fmt="binary"),
        "big_endian": vti_bytes(byte_order="BigEndian"),
        "not_xml": b"hello world\n" * 10,
        "polydata": good.replace(b'type="ImageData"', b'type="PolyData"'),
        "garbled_offset": good.replace(b'offset="0', b'offset="x0', 1),
    }
    base = [exe, "--seeds", seed_file, "--particles", "8", "--steps", "10", "--step-size", "0.01",
            "--repeats", "1"] + extra
    for name, content in cases.items():
        path = os.path.join(work, f"bad_{name}.vti")
        if content is None:
            if os.path.exists(path):
                os.remove(path)
        else:
            with open(path, "wb") as f:
                f.write(content)
        r = run(base + ["--grid", path])
        msg = (r.stderr.strip().splitlines() or [""])[-1]
        check(0 < r.returncode < 128 and path in r.stderr,
              f"bad grid '{name}': exit {r.returncode}, {msg}")

    # Bad options and seeds.
    bad_seeds = os.path.join(work, "bad_seeds.txt")
    with open(bad_seeds, "w") as f:
        f.write("1 2 3\n4 five 6\n")
    few_seeds = os.path.join(work, "few_seeds.txt")
    with open(few_seeds, "w") as f:
        f.write("# only one\n%.17g %.17g %.17g\n" % seed_list[0])
    opt_cases = {
        "no arguments": [],
        "no seeds file": ["--grid", grid, "--seeds", os.path.join(work, "nope.txt"),
                          "--particles", "8", "--steps", "10", "--step-size", "0.01"],
        "malformed seeds": ["--grid", grid, "--seeds", bad_seeds, "--particles", "1",
                            "--steps", "10", "--step-size", "0.01"],
        "too few seeds": ["--grid", grid, "--seeds", few_seeds, "--particles", "2",
                          "--steps", "10", "--step-size", "0.01"],
        "bad vector": ["--grid", grid, "--seeds", seed_file, "--particles", "2", "--steps", "10",
                       "--step-size", "0.01", "--vector", "nothere"],
        "scalar as vector": ["--grid", grid, "--seeds", seed_file, "--particles", "2",
                             "--steps", "10", "--step-size", "0.01", "--vector", "dens"],
        "bad steps": ["--grid", grid, "--seeds", seed_file, "--particles", "2", "--steps", "x",
                      "--step-size", "0.01"],
        "zero particles": ["--grid", grid, "--seeds", seed_file, "--particles", "0",
                           "--steps", "10", "--step-size", "0.01"],
        "negative step": ["--grid", grid, "--seeds", seed_file, "--particles", "2",
                          "--steps", "10", "--step-size", "-1"],
        "missing value": ["--grid", grid, "--seeds"],
        "unknown option": ["--grid", grid, "--bogus"],
        "unwritable json": ["--grid", grid, "--seeds", seed_file, "--particles", "2",
                            "--steps", "10", "--step-size", "0.01", "--repeats", "1",
                            "--json", "/nonexistent-dir/x.json"],
    }
    for name, args in opt_cases.items():
        r = run([exe] + args + extra)
        msg = (r.stderr.strip().splitlines() or [""])[-1]
        check(0 < r.returncode < 128 and "error" in r.stderr,
              f"{name}: exit {r.returncode}, {msg}")

    # All seeds outside the grid: no lines, zero steps, no crash.
    out_seeds = os.path.join(work, "outside_seeds.txt")
    with open(out_seeds, "w") as f:
        f.write("100 100 100\n-100 0 0\n")
    r = run([exe, "--grid", grid, "--seeds", out_seeds, "--particles", "2", "--steps", "10",
             "--step-size", "0.01", "--repeats", "1"] + extra)
    check(r.returncode == 0 and " 0 inside the grid, 0 traced" in r.stdout,
          f"all seeds outside: exit {r.returncode}, no lines")

    print(f"\n{len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
