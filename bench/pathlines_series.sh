#!/bin/bash
# The pathline measurements of docs/benchmarks.md: a swirl series (`gen swirl`, refinement
# following a feature the flow carries) of SNAPSHOTS snapshots of CELLS cells each, then
# `pathlines` with PARTICLES particles on each backend, and a baseline with one particle whose
# run time is that of reading and building the series alone. Prints the summary lines.
# Usage: bench/pathlines_series.sh AMRSTREAM [WORK_DIR] [CELLS] [SNAPSHOTS] [PARTICLES] [BACKENDS]
set -u
A=$1
dir=${2:-/tmp}
cells=${3:-10000000}
snapshots=${4:-10}
particles=${5:-1048576}
backends=${6:-"compute pipeline cpu"}
rm -f "$dir"/swirl_*
start=$(date +%s%N)
"$A" gen swirl --levels 7 --root-blocks 8 --target-cells "$cells" --series "$snapshots" \
  --interval 0.02 --out "$dir/swirl" | grep '^generated' | tail -1
echo "generated and wrote $snapshots snapshots in $(( ($(date +%s%N) - start) / 1000000 )) ms"
du -sh "$dir" | tail -1
S="--seed-box 0.2,0.2,0.3,0.8,0.8,0.7 --point-data none"
keep='^(series|stepping|particles|time|samples|output|memory|tracing)'
echo "== baseline: one particle (reading and building the series)"
"$A" pathlines "$dir/swirl_*.exa" $S --count 1 --backend cpu --out "$dir/one.vtp" 2>&1 | grep -E "$keep"
for b in $backends; do
  echo "== $b, $particles particles"
  "$A" pathlines "$dir/swirl_*.exa" $S --count "$particles" --backend "$b" \
    --compression lz4 --out "$dir/paths.vtp" 2>&1 | grep -E "$keep"
  rm -f "$dir/paths.vtp"
done
