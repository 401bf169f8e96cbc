#!/bin/bash
# The streamed-history measurements of docs/benchmarks.md: `trace` with history on the 72.8 M-cell
# cloud, per backend and point data, the .vtp written to tmpfs in each compression, both
# directions with vorticity, and 2^20 seeds to disk. Prints the summary lines that matter.
# Usage: bench/streamed_trace.sh AMRSTREAM [WORK_DIR]   (about 4 minutes on an H200)
set -u
A=$1
dir=${2:-/tmp}
shm=/dev/shm
"$A" gen cloud --levels 7 --root-blocks 8 --target-cells 72800000 --out "$dir/cloud72" | tail -1
S="--seed-density dens --seed-percentile 90 --count 65536 --steps 1000"
keep='^(steps|time|rounds|output|memory)'
for b in compute pipeline; do
  for pd in none dens dens,magx,magy,magz; do
    echo "== $b, forward, point data $pd, zlib"
    "$A" trace "$dir/cloud72.exa" --backend "$b" $S --direction forward --point-data "$pd" \
      --out "$shm/t.vtp" 2>&1 | grep -E "$keep"
    echo "bytes $(stat -c %s "$shm/t.vtp")"; rm -f "$shm/t.vtp"
  done
done
for c in none lz4; do
  echo "== compute, forward, dens, $c"
  "$A" trace "$dir/cloud72.exa" --backend compute $S --direction forward --compression "$c" \
    --out "$shm/t.vtp" 2>&1 | grep -E "$keep"
  echo "bytes $(stat -c %s "$shm/t.vtp")"; rm -f "$shm/t.vtp"
done
echo "== compute, both directions, dens, vorticity"
"$A" trace "$dir/cloud72.exa" --backend compute $S --vorticity --out "$shm/t.vtp" 2>&1 | grep -E "$keep"
rm -f "$shm/t.vtp"
echo "== compute, 2^20 seeds x 1000 steps, forward, dens, zlib, to disk"
"$A" trace "$dir/cloud72.exa" --backend compute --seed-density dens --count 1048576 --steps 1000 \
  --direction forward --out "$dir/big.vtp" 2>&1 | grep -E "$keep"
echo "bytes $(stat -c %s "$dir/big.vtp")"; rm -f "$dir/big.vtp"
