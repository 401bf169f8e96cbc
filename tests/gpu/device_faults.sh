#!/bin/sh
# Device faults end a run with a clear error and nothing written, and the CPU backend still works:
# out of device memory (AMRSTREAM_DEVICE_MEMORY_LIMIT makes allocations past it fail as the
# driver's VK_ERROR_OUT_OF_DEVICE_MEMORY would) on every GPU backend, and no Vulkan driver at all.
# Usage: device_faults.sh AMRSTREAM WORK_DIR
set -eu
amrstream=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir"
fail() { echo "$*" >&2; exit 1; }
expect_failure() {  # NAME PATTERN COMMAND...
  name=$1 pattern=$2; shift 2
  if "$@" > "$dir/$name.out" 2> "$dir/$name.err"; then fail "$name: exited 0"; fi
  grep -q "$pattern" "$dir/$name.err" || { cat "$dir/$name.err" >&2; fail "$name: no '$pattern'"; }
  [ -z "$(ls -A "$dir/out")" ] || { ls -la "$dir/out" >&2; fail "$name: left files behind"; }
  echo "$name: $(tail -n 1 "$dir/$name.err")"
}
mkdir -p "$dir/out"
trace="trace builtin:cloud --count 64 --steps 100 --out $dir/out/traces.vtp"
for backend in rayquery pipeline compute; do
  expect_failure "oom-$backend" "out of device memory allocating" \
    env AMRSTREAM_DEVICE_MEMORY_LIMIT=64K "$amrstream" $trace --backend "$backend"
done
expect_failure no-driver "no Vulkan driver found" \
  env VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json \
  "$amrstream" $trace --backend compute
expect_failure bad-limit "AMRSTREAM_DEVICE_MEMORY_LIMIT='lots' is not a size" \
  env AMRSTREAM_DEVICE_MEMORY_LIMIT=lots "$amrstream" $trace --backend compute

# The same run on the CPU backend (and `auto`, which falls back to it without a driver) succeeds.
env AMRSTREAM_DEVICE_MEMORY_LIMIT=64K "$amrstream" $trace --backend cpu > "$dir/cpu.out"
[ -s "$dir/out/traces.vtp" ] || fail "the CPU backend wrote nothing"
rm "$dir/out/traces.vtp"
env VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json \
  "$amrstream" $trace --backend auto > "$dir/auto.out"
grep -q "^tracing    on the CPU reference" "$dir/auto.out" || fail "auto did not fall back to the CPU"
[ -s "$dir/out/traces.vtp" ] || fail "auto wrote nothing"
echo "cpu and auto: traced and wrote $(wc -c < "$dir/out/traces.vtp") bytes"
