#!/usr/bin/env bash
# amrstream vs Viskores on one GPU: build Viskores (CUDA), build viskores_bench against it, make
# the dataset, the seeds and the uniform resample with amrstream, and run both benchmarks.
# Meant to run ON the GPU machine, from the repository root. See README.md in this folder.
#
#   bench/peers/viskores/run_viskores_peer.sh build TARBALL   # unpack, configure, start ninja in
#                                                             # the background (returns at once)
#   bench/peers/viskores/run_viskores_peer.sh wait [SECONDS]  # poll the build (default 540 s);
#                                                             # exit 0 built, 1 failed, 2 running
#   bench/peers/viskores/run_viskores_peer.sh status          # one line: built / running / failed
#   bench/peers/viskores/run_viskores_peer.sh bench [AMRSTREAM]   # the comparison (results in $OUT)
#   bench/peers/viskores/run_viskores_peer.sh selftest        # viskores_bench's tests on the GPU,
#                                                             # then a PERF_DIMS^3 synthetic run [512]
#
# A CUDA build of Viskores takes 6 to 8 minutes with 16 cores (477 s on an H200, 2026-11-26),
# too close to one 10-minute device call to share it with anything else: run `build` and `wait`
# in one call, then `bench` in the next (within the machine's 30 s idle time; /tmp survives only
# while it stays warm). .devkit/ is git-ignored: carry it (or pass another amrstream binary).
#
# Environment (defaults in brackets):
#   VKPEER_WORK     work directory [/tmp/vkpeer]: src/, viskores-build/, vkbench-build/, data
#   OUT             results: amrstream.json, viskores.json (viskores-spatial.json), run.log
#                   [$VKPEER_WORK/out]
#   AMRSTREAM       the amrstream binary [.devkit/bin/amrstream]; also the 2nd argument of bench
#   VKPEER_CUDA     ON: the CUDA build of Viskores; OFF: serial only (for testing the script) [ON]
#   VISKORES_DEVICE the device viskores_bench is forced to [Cuda, or Serial with VKPEER_CUDA=OFF]
#   JOBS            parallel build jobs [nproc]
#   CMAKE_CUDA_ARCHITECTURES [90]
# and the benchmark settings marked below (PARTICLES, STEPS, REPEATS, STEP_FRACTION, ...).
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
WORK="${VKPEER_WORK:-/tmp/vkpeer}"
OUT="${OUT:-$WORK/out}"
CUDA="${VKPEER_CUDA:-ON}"
JOBS="${JOBS:-$(nproc)}"
CUDA_ARCH="${CMAKE_CUDA_ARCHITECTURES:-90}"
if [[ "$CUDA" == ON ]]; then DEFAULT_DEVICE=Cuda; else DEFAULT_DEVICE=Serial; fi
VISKORES_DEVICE="${VISKORES_DEVICE:-$DEFAULT_DEVICE}"

VK_SRC="$WORK/src/viskores"
VK_BUILD="$WORK/viskores-build"
VK_LOG="$WORK/viskores-build.log"
VK_RC="$WORK/viskores-build.rc"
VK_PID="$WORK/viskores-build.pid"
BENCH_BUILD="$WORK/vkbench-build"
BENCH_EXE="$BENCH_BUILD/viskores_bench"

# ---- benchmark settings: the lead adjusts these ----------------------------------------------
# The dataset (amrstream gen cloud) and where it is written (DATA.exa and its companions).
DATA="${DATA:-/tmp/cloud72}"
GEN_ARGS="${GEN_ARGS:---levels 7 --root-blocks 8 --target-cells 72800000}"
# Seeds: the paper's (random points in the densest cells), written once and used by both tools.
SEED_COUNT="${SEED_COUNT:-1048576}"
SEED_ARGS="${SEED_ARGS:---seed-density dens --seed-percentile 90}"
# The uniform point grid for Viskores (amrstream resample; assumed options, see README.md).
RESAMPLE_DIMS="${RESAMPLE_DIMS:-512,512,512}"
RESAMPLE_ARGS="${RESAMPLE_ARGS:---compression none --point-data none}"
# The benchmark itself.
PARTICLES="${PARTICLES:-65536,1048576}"
STEPS="${STEPS:-1000}"
REPEATS="${REPEATS:-3}"
AMRSTREAM_BENCH_ARGS="${AMRSTREAM_BENCH_ARGS:---backends compute,pipeline --mode both}"
# Viskores's step is a fixed time step dt = STEP_FRACTION x the smallest grid spacing, unless
# STEP_SIZE is set. (amrstream bench's default step mode `cell` moves h x cell width x |v|.)
STEP_FRACTION="${STEP_FRACTION:-0.25}"
STEP_SIZE="${STEP_SIZE:-}"
VISKORES_BENCH_ARGS="${VISKORES_BENCH_ARGS:---mode both}"
# Seed orders for Viskores: the first writes viskores.json, any other viskores-ORDER.json.
# (On a synthetic 512^3 grid Viskores ran ~25% slower with Morton-sorted seeds than in file
# order, so both are run; amrstream bench sorts them by default.)
VISKORES_SEED_ORDERS="${VISKORES_SEED_ORDERS:-given spatial}"
# -----------------------------------------------------------------------------------------------

die() { echo "run_viskores_peer.sh: $*" >&2; exit 1; }
log() { echo "[$(date +%H:%M:%S)] $*"; }

find_nvcc() {
  if [[ "$CUDA" == ON ]] && ! command -v nvcc >/dev/null 2>&1; then
    for d in /usr/local/cuda/bin /usr/local/cuda-*/bin; do
      if [[ -x "$d/nvcc" ]]; then export PATH="$d:$PATH"; break; fi
    done
    command -v nvcc >/dev/null 2>&1 || die "nvcc not found (needed for the CUDA build of Viskores)"
  fi
}

viskores_dir() { echo "$VK_BUILD/lib/cmake/viskores-1.2"; }

build_state() {
  if [[ -f "$VK_RC" ]]; then
    if [[ "$(cat "$VK_RC")" == 0 ]]; then echo built; else echo "failed (rc $(cat "$VK_RC"))"; fi
  elif [[ -f "$VK_PID" ]] && kill -0 "$(cat "$VK_PID")" 2>/dev/null; then
    echo running
  elif [[ -f "$VK_PID" ]]; then
    echo "died (no exit status; see $VK_LOG)"
  else
    echo "not started"
  fi
}

cmd_build() {
  local tarball="${1:-}"
  mkdir -p "$WORK"
  local state; state="$(build_state)"
  if [[ "$state" == built || "$state" == running ]]; then
    log "Viskores build: $state ($VK_BUILD)"; return 0
  fi
  if [[ ! -f "$VK_SRC/CMakeLists.txt" ]]; then
    [[ -n "$tarball" ]] || die "usage: $0 build VISKORES_TARBALL (viskores-1.2-src.tar.xz)"
    [[ -f "$tarball" ]] || die "$tarball: no such file"
    mkdir -p "$WORK/src"
    tar -xf "$tarball" -C "$WORK/src"
    [[ -f "$VK_SRC/CMakeLists.txt" ]] || die "$tarball did not unpack to viskores/"
  fi
  find_nvcc
  local devflags=()
  if [[ "$CUDA" == ON ]]; then
    devflags=(-DViskores_ENABLE_CUDA=ON "-DCMAKE_CUDA_ARCHITECTURES=$CUDA_ARCH")
  else
    devflags=(-DViskores_ENABLE_CUDA=OFF -DViskores_ENABLE_TBB=OFF -DViskores_ENABLE_OPENMP=OFF)
  fi
  rm -f "$VK_RC" "$VK_PID"
  log "configuring Viskores in $VK_BUILD (CUDA $CUDA)"
  cmake -S "$VK_SRC" -B "$VK_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release "${devflags[@]}" \
    -DViskores_ENABLE_TESTING=OFF -DViskores_ENABLE_RENDERING=OFF \
    -DViskores_ENABLE_EXAMPLES=OFF -DViskores_ENABLE_BENCHMARKS=OFF \
    -DViskores_ENABLE_TUTORIALS=OFF -DViskores_ENABLE_DOCUMENTATION=OFF \
    -DViskores_BUILD_ALL_LIBRARIES=OFF -DViskores_MODULE_ENABLE_viskores_filter_flow=YES \
    -DViskores_ENABLE_LOGGING=OFF >"$WORK/viskores-configure.log" 2>&1 \
    || { tail -30 "$WORK/viskores-configure.log" >&2; die "configuring Viskores failed"; }
  log "starting ninja -j $JOBS in the background (log $VK_LOG)"
  # setsid + nohup: the build survives the end of this shell (and of the device call).
  setsid nohup bash -c "start=\$(date +%s); ninja -C '$VK_BUILD' -j '$JOBS' >'$VK_LOG' 2>&1; rc=\$?; \
echo \"build seconds \$(( \$(date +%s) - start ))\" >>'$VK_LOG'; echo \$rc >'$VK_RC'" \
    </dev/null >/dev/null 2>&1 &
  echo $! >"$VK_PID"
  log "build started (pid $(cat "$VK_PID")); poll with: $0 wait"
}

cmd_wait() {
  local limit="${1:-540}" waited=0
  while true; do
    local state; state="$(build_state)"
    case "$state" in
      built)
        log "Viskores built: $(tail -1 "$VK_LOG")"; return 0 ;;
      running)
        if (( waited >= limit )); then
          log "still building after ${waited}s: $(tail -1 "$VK_LOG" 2>/dev/null | cut -c1-120)"
          return 2
        fi
        sleep 5; waited=$((waited + 5)) ;;
      *)
        log "Viskores build $state"; tail -40 "$VK_LOG" 2>/dev/null || true; return 1 ;;
    esac
  done
}

cmd_status() {
  local state; state="$(build_state)"
  echo "Viskores build: $state${VK_LOG:+; last line: $(tail -1 "$VK_LOG" 2>/dev/null | cut -c1-120)}"
}

build_bench() {
  [[ "$(build_state)" == built ]] || die "Viskores is not built ($(build_state)); run build and wait"
  log "building viskores_bench in $BENCH_BUILD"
  cmake -S "$HERE" -B "$BENCH_BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    "-DViskores_DIR=$(viskores_dir)" >"$WORK/vkbench-configure.log" 2>&1 \
    || { tail -30 "$WORK/vkbench-configure.log" >&2; die "configuring viskores_bench failed"; }
  cmake --build "$BENCH_BUILD" -j "$JOBS" >"$WORK/vkbench-build.log" 2>&1 \
    || { tail -40 "$WORK/vkbench-build.log" >&2; die "building viskores_bench failed"; }
}

# The smallest Spacing of a .vti header.
min_spacing() {
  head -c 4096 "$1" | LC_ALL=C tr "\n" " " | LC_ALL=C sed -n 's/.*<ImageData[^>]*Spacing="\([^"]*\)".*/\1/p' \
    | awk '{ m = $1; for (i = 2; i <= NF; i++) if ($i < m) m = $i; if (NF == 3) printf "%.17g\n", m }'
}

cmd_bench() {
  local amr="${1:-${AMRSTREAM:-.devkit/bin/amrstream}}"
  [[ -x "$amr" ]] || die "$amr: not an executable (the amrstream binary; argument 2 or \$AMRSTREAM)"
  mkdir -p "$OUT"
  # Everything goes to one log ($OUT/run.log): a device call returns at most 8 files.
  local runlog="$OUT/run.log"
  : >"$runlog"
  build_bench
  {
    echo "date: $(date -Is)"
    echo "host: $(hostname)"
    echo "gpu: $(nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>/dev/null || echo none)"
    echo "amrstream: $amr"
    echo "viskores: $(viskores_dir) (CUDA $CUDA, device $VISKORES_DEVICE)"
  } | tee -a "$runlog"

  # 1. The dataset.
  if [[ ! -f "$DATA.exa" ]]; then
    log "amrstream gen cloud $GEN_ARGS --out $DATA" | tee -a "$runlog"
    # shellcheck disable=SC2086
    "$amr" gen cloud $GEN_ARGS --out "$DATA" 2>&1 | tee -a "$runlog"
  fi
  # 2. The seeds, written once (17 significant digits) and given to both tools.
  local seeds="$WORK/seeds.txt"
  if [[ ! -s "$seeds" ]]; then
    log "amrstream trace: $SEED_COUNT seeds -> $seeds" | tee -a "$runlog"
    # shellcheck disable=SC2086
    "$amr" trace "$DATA.exa" $SEED_ARGS --count "$SEED_COUNT" --steps 0 --endpoints-only \
      --direction forward --point-data none --backend cpu \
      --seeds-out "$WORK/seeds.part.txt" --out "$WORK/seeds.vtp" 2>&1 | tee -a "$runlog"
    mv "$WORK/seeds.part.txt" "$seeds"  # only a complete file is reused
  fi
  # 3. The uniform point grid for Viskores.
  local grid="$WORK/grid.vti"
  if [[ ! -s "$grid" ]]; then
    log "amrstream resample --dims $RESAMPLE_DIMS -> $grid" | tee -a "$runlog"
    # shellcheck disable=SC2086
    "$amr" resample "$DATA.exa" --dims "$RESAMPLE_DIMS" $RESAMPLE_ARGS \
      --out "$WORK/grid.part.vti" 2>&1 | tee -a "$runlog"
    mv "$WORK/grid.part.vti" "$grid"
  fi
  local h="$STEP_SIZE"
  if [[ -z "$h" ]]; then
    local dx; dx="$(min_spacing "$grid")"
    [[ -n "$dx" ]] || die "$grid: cannot read Spacing from its header"
    h="$(awk -v f="$STEP_FRACTION" -v d="$dx" 'BEGIN { printf "%.9g\n", f * d }')"
    log "Viskores step size: $STEP_FRACTION x spacing $dx = $h" | tee -a "$runlog"
  fi

  # 4. amrstream.
  log "amrstream bench" | tee -a "$runlog"
  # shellcheck disable=SC2086
  "$amr" bench "$DATA.exa" $AMRSTREAM_BENCH_ARGS --seeds "$seeds" --particles "$PARTICLES" \
    --steps "$STEPS" --repeats "$REPEATS" --json "$OUT/amrstream.json" 2>&1 | tee -a "$runlog"
  # 5. Viskores, once per seed order.
  local first=1 order json
  for order in $VISKORES_SEED_ORDERS; do
    if (( first )); then json="$OUT/viskores.json"; else json="$OUT/viskores-$order.json"; fi
    first=0
    log "viskores_bench --seed-order $order" | tee -a "$runlog"
    # shellcheck disable=SC2086
    "$BENCH_EXE" --grid "$grid" --seeds "$seeds" --particles "$PARTICLES" --steps "$STEPS" \
      --step-size "$h" --repeats "$REPEATS" --seed-order "$order" $VISKORES_BENCH_ARGS \
      --json "$json" "--viskores-device=$VISKORES_DEVICE" 2>&1 | tee -a "$runlog"
  done
  log "results in $OUT" | tee -a "$runlog"
}

cmd_selftest() {
  build_bench
  mkdir -p "$OUT"
  local rc=0
  python3 "$HERE/test_viskores_bench.py" "$BENCH_EXE" "$WORK/selftest" \
    -- "--viskores-device=$VISKORES_DEVICE" 2>&1 | tee "$OUT/selftest.log" || rc=$?
  # A benchmark-sized synthetic case (PERF_DIMS^3 rotation grid; 0 to skip; needs numpy).
  if [[ "${PERF_DIMS:-512}" != 0 ]] && python3 -c 'import numpy' 2>/dev/null; then
    python3 "$HERE/test_viskores_bench.py" "$BENCH_EXE" "$WORK/selftest" --perf "${PERF_DIMS:-512}" \
      --perf-particles "$PARTICLES" -- "--viskores-device=$VISKORES_DEVICE" 2>&1 \
      | tee "$OUT/selftest-perf.log" || rc=$?
    cp "$WORK/selftest/perf.json" "$OUT/selftest-perf.json" 2>/dev/null || true
  fi
  return "$rc"
}

sub="${1:-}"
[[ $# -gt 0 ]] && shift
case "$sub" in
  build) cmd_build "$@" ;;
  wait) cmd_wait "$@" ;;
  status) cmd_status ;;
  bench) cmd_bench "$@" ;;
  selftest) cmd_selftest ;;
  *) sed -n '2,/^set -euo/p' "$0" | grep '^#' | sed 's/^# \{0,1\}//'
     if [[ -z "$sub" ]]; then exit 2; fi
     die "unknown subcommand '$sub'" ;;
esac
