#!/bin/bash
# The whole command a user runs, every stage on the clock: the 72.8 M-cell, 7-level cloud traced
# from 2^20 seeds to their endpoints, a figure's run (4096 seeds in the densest cells, with their
# density) and `info`, each run twice (the second finds the kernels compiled), with each build
# given. Prints a table: the wall time the shell measured and, for builds with the stage clock,
# where it went (the summary's `wall` line).
#
#   bench/whole_command.sh [--dir DIR] [--cells N] [--backend B] NEW [OLD]
#
# NEW, OLD: amrstream executables (OLD's rows come first). DIR (default /dev/shm/amrstream-whole,
# a tmpfs: the page cache is warm for every run but the generator's) holds the cloud, made by NEW
# once. B: the GPU backend (default compute).
set -euo pipefail

dir=/dev/shm/amrstream-whole
cells=72800000
backend=compute
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --dir) dir=$2; shift 2 ;;
    --cells) cells=$2; shift 2 ;;
    --backend) backend=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 [--dir DIR] [--cells N] [--backend B] NEW [OLD]" >&2
  exit 2
fi
new=$(realpath "$1")
builds=("new=$new")
[[ $# -eq 2 ]] && builds=("old=$(realpath "$2")" "${builds[@]}")

mkdir -p "$dir"
cd "$dir"
if [[ ! -f cloud.exa ]]; then
  echo "generating the cloud ($cells cells) in $dir ..." >&2
  "$new" gen cloud --levels 7 --root-blocks 8 --target-cells "$cells" --out cloud > /dev/null
fi
echo "cloud: $(du -sh --apparent-size cloud.* | awk '{print $1}' | paste -sd+) in $dir"

commands=(
  "endpoints|trace cloud.exa --count 1048576 --backend $backend --endpoints-only --out endpoints.vtp"
  "figure|trace cloud.exa --count 4096 --seed-density dens --point-data dens --backend $backend --out figure.vtp"
  "info|info cloud.exa"
)

printf '| command | build | run | wall (s) | stages (s) |\n|---|---|---|---|---|\n'
for entry in "${commands[@]}"; do
  name=${entry%%|*}
  arguments=${entry#*|}
  for build in "${builds[@]}"; do
    label=${build%%=*}
    binary=${build#*=}
    for run in 1 2; do
      log=$(mktemp)
      start=$(date +%s%N)
      # shellcheck disable=SC2086
      if ! "$binary" $arguments > "$log" 2>&1; then
        echo "| $name | $label | $run | failed | $(tail -1 "$log") |"
        rm -f "$log"
        continue
      fi
      centiseconds=$((($(date +%s%N) - start) / 10000000))
      stages=$(grep '^wall ' "$log" | sed 's/^wall *[0-9.]* s: //' || true)
      printf '| %s | %s | %s | %d.%02d | %s |\n' "$name" "$label" "$run" $((centiseconds / 100)) \
        $((centiseconds % 100)) "${stages:-(no stage clock)}"
      rm -f "$log"
    done
  done
done
