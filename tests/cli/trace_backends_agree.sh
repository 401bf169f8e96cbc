#!/bin/sh
# `amrstream trace builtin:cloud --backend X` for every GPU backend gives the same steps taken and
# the same termination reasons as `--backend cpu`, with the Vulkan validation layer on and no
# validation error (amrstream fails when the layer reports one); and that the points kept on the
# device until they are written (--trace-store device) make the same file, byte for byte, as the
# points collected in host memory. With --cpu-tail the CPU finishes the lines a GPU round leaves
# (here all 8 after the first 1000 steps) from their states, with the host's values kept though
# `trace` frees them otherwise: the same steps and reasons again.
# Usage: trace_backends_agree.sh AMRSTREAM WORK_DIR
set -eu
amrstream=$1 dir=$2
mkdir -p "$dir"
summary() {
  AMRSTREAM_VALIDATION=1 "$amrstream" trace builtin:cloud --backend "$1" --steps 1000 --count 128 \
    --out "$dir/$1.vtp" > "$dir/$1.txt"
  grep -E '^(steps|reasons) ' "$dir/$1.txt"
}
# With vorticity, and every array uncompressed.
kept() {
  AMRSTREAM_VALIDATION=1 "$amrstream" trace builtin:cloud --backend "$1" --steps 3000 --count 64 \
    --vorticity --compression none --trace-store "$2" --out "$dir/$1-$2.vtp" > "$dir/$1-$2.txt"
}
tail_summary() {
  AMRSTREAM_VALIDATION=1 "$amrstream" trace builtin:abc --backend "$1" --steps 3000 --count 4 \
    --endpoints-only --cpu-tail 16 --out "$dir/$1-tail.vtp" > "$dir/$1-tail.txt"
  grep -E '^(steps|reasons) ' "$dir/$1-tail.txt"
}
expected=$(summary cpu)
echo "cpu: $expected"
expected_tail=$(tail_summary cpu)
for backend in rayquery pipeline compute; do
  got=$(summary "$backend")
  echo "$backend: $got"
  grep -q "^tracing    backend $backend on" "$dir/$backend.txt" || { echo "$backend did not run on the GPU" >&2; exit 1; }
  [ "$got" = "$expected" ] || { echo "$backend differs from cpu" >&2; exit 1; }
  kept "$backend" host
  kept "$backend" device
  grep -q "^points     kept on the device" "$dir/$backend-device.txt" ||
    { echo "$backend did not keep the points on the device" >&2; exit 1; }
  cmp "$dir/$backend-host.vtp" "$dir/$backend-device.vtp" ||
    { echo "$backend: the points kept on the device make another file" >&2; exit 1; }
  echo "$backend: the same file from the device's points and from host memory"
  got_tail=$(tail_summary "$backend")
  grep -q "^cpu tail   8 lines finished on the CPU" "$dir/$backend-tail.txt" ||
    { echo "$backend: the CPU did not finish the last lines" >&2; exit 1; }
  [ "$got_tail" = "$expected_tail" ] || { echo "$backend with --cpu-tail differs from cpu" >&2; exit 1; }
  echo "$backend: the CPU finished the last lines as it traces them"
done
