#!/usr/bin/env bash
# Builds the libFuzzer harnesses of the input readers (fuzz/, docs/reliability.md "Fuzzing") in
# build-fuzz/ with clang, AddressSanitizer and UndefinedBehaviorSanitizer, then runs each one for
# SECONDS seconds, one after the other, starting from its seed corpus fuzz/corpus/NAME. Reports
# per harness the executions, executions per second, and the files of any crash, leak, timeout
# or out-of-memory it found (build-fuzz/fuzz-runs/NAME/). New interesting inputs are kept in
# build-fuzz/fuzz-runs/NAME/corpus, never in fuzz/corpus: add a minimised crash input there by
# hand once it is fixed, so that the replay tests cover it.
#
# Usage: scripts/fuzz.sh [SECONDS] [HARNESS...]   (default 60 s; all of exa flash enzo amrex
#        gerris vtp seeds). Environment: JOBS (build jobs, default nproc).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(exa flash enzo amrex gerris vtp seeds)
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
build="$root/build-fuzz"

command -v clang++ >/dev/null || { echo "fuzz: clang++ is missing (scripts/install_deps.sh)" >&2; exit 1; }
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DAMRSTREAM_SANITIZE=ON -DAMRSTREAM_FUZZ=ON -DAMRSTREAM_BUILD_TESTS=OFF >/dev/null
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build "$build" -j "$jobs" --target "${targets[@]}"

summary=()
found=0
for h in "${harnesses[@]}"; do
  work="$build/fuzz-runs/$h"
  mkdir -p "$work/corpus"
  echo "== fuzz_$h for ${seconds}s"
  # -rss_limit_mb / -malloc_limit_mb: a reader that allocates what a header claims is a bug.
  ASAN_OPTIONS=abort_on_error=1:detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz/fuzz_$h" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$work/" \
    "$work/corpus" "$root/fuzz/corpus/$h" >"$work/log" 2>&1 || true
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/log" | tail -1)
  crashes=$(find "$work" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'leak-*' -o \
    -name 'timeout-*' -o -name 'oom-*' -o -name 'slow-unit-*' \) | sort)
  summary+=("$(printf '%-7s %10s executions %7s exec/s  %s' "$h" "${runs:-?}" "${rate:-?}" \
    "$( [ -n "$crashes" ] && echo "FOUND: $(echo "$crashes" | wc -l) file(s)" || echo "no crash")")")
  if [ -n "$crashes" ]; then
    found=1
    echo "$crashes"
    grep -m1 -E "ERROR: |runtime error|==[0-9]+==" "$work/log" || true
  fi
done
echo "== summary (${seconds}s per harness; logs and findings in $build/fuzz-runs/)"
printf '%s\n' "${summary[@]}"
exit $found
