#!/bin/bash
# The pathline measurements of docs/benchmarks.md. Makes a swirl series (`gen swirl`, refinement
# following a feature the flow carries) of SNAPSHOTS snapshots of CELLS cells, 0.02 apart, with
# NEW; then, for each build and backend, `pathlines` of PARTICLES particles (dt 0.002, the default
# tenth of the interval), beside the same number of streamlines of the first snapshot with the same
# steps in time and history (`trace --step-mode time --direction forward`), and a baseline of one
# particle whose run time is that of reading and building the series alone. Prints a table of
# each run's tracing time, particle-steps/s, the whole run and its ratio to the baseline.
#
#   bench/pathlines_series.sh [--dir DIR] [--cells N] [--snapshots S] [--particles P]
#                             [--backends "compute pipeline cpu"] NEW [OLD]
#
# NEW, OLD: amrstream executables (OLD's rows first). DIR (default /dev/shm/amrstream-pathlines).
set -euo pipefail

dir=/dev/shm/amrstream-pathlines
cells=10000000
snapshots=4
particles=1048576
backends="compute pipeline cpu"
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --dir) dir=$2; shift 2 ;;
    --cells) cells=$2; shift 2 ;;
    --snapshots) snapshots=$2; shift 2 ;;
    --particles) particles=$2; shift 2 ;;
    --backends) backends=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 [--dir DIR] [--cells N] [--snapshots S] [--particles P] [--backends B] NEW [OLD]" >&2
  exit 2
fi
new=$(realpath "$1")
builds=("new=$new")
[[ $# -eq 2 ]] && builds=("old=$(realpath "$2")" "${builds[@]}")

mkdir -p "$dir"
rm -f "$dir"/swirl_* "$dir"/*.vtp
"$new" gen swirl --levels 7 --root-blocks 8 --target-cells "$cells" --series "$snapshots" \
  --interval 0.02 --out "$dir/swirl" | grep '^generated' | tail -1
steps=$(( (snapshots - 1) * 10 ))
seeds="--seed-box 0.2,0.2,0.3,0.8,0.8,0.7 --point-data none"
echo "series: $snapshots snapshots of $cells cells in $dir ($(du -sh "$dir" | cut -f1)); $particles particles x $steps steps"

# The tracing seconds and particle-steps/s of a summary's `time` line, and the shell's wall.
field() { grep -oE "$1" <<< "$2" | head -1 | grep -oE '[0-9.e+-]+' | head -1; }
run() {  # label build args...
  local label=$1 exe=$2
  shift 2
  local start end log wall
  start=$(date +%s%N)
  log=$("$exe" "$@" 2>&1) || { echo "| $label | failed: $(tail -1 <<< "$log") |"; return; }
  end=$(date +%s%N)
  wall=$(awk -v n=$(( end - start )) 'BEGIN { printf "%.2f", n / 1e9 }')
  local line tracing rate
  line=$(grep -E '^time' <<< "$log")
  if [[ $line == *"s tracing"* ]]; then  # trace's summary
    tracing=$(field '[0-9.]+ s tracing' "$line")
  else
    tracing=$(field 'tracing [0-9.]+ s' "$line")
  fi
  rate=$(field '[0-9.e+]+ particle-steps/s' "$line")
  echo "| $label | $tracing | $rate | $wall | $(awk -v w="$wall" -v b="${baseline:-0}" 'BEGIN { if (b > 0) printf "%.2f", w / b }') |"
}

echo
echo "| build, backend, run | tracing (s) | particle-steps/s | wall (s) | x baseline |"
echo "|---|---|---|---|---|"
for build in "${builds[@]}"; do
  name=${build%%=*} exe=${build#*=}
  baseline=
  start=$(date +%s%N)
  "$exe" pathlines "$dir/swirl_*.exa" $seeds --count 1 --backend cpu --out "$dir/one.vtp" \
    > /dev/null 2>&1
  baseline=$(awk -v n=$(( $(date +%s%N) - start )) 'BEGIN { printf "%.2f", n / 1e9 }')
  echo "| $name, baseline: 1 particle (reading and building) | | | $baseline | 1.00 |"
  for b in $backends; do
    run "$name, $b, pathlines" "$exe" pathlines "$dir/swirl_*.exa" $seeds --count "$particles" \
      --backend "$b" --compression lz4 --out "$dir/paths.vtp"
    run "$name, $b, streamlines of one snapshot (trace --step-mode time)" "$exe" trace \
      "$dir/swirl_0000.exa" $seeds --count "$particles" --direction forward --step-mode time \
      --step-size 0.002 --steps "$steps" --backend "$b" --compression lz4 --out "$dir/lines.vtp"
    rm -f "$dir"/*.vtp
  done
done
