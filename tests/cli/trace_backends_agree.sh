#!/bin/sh
# `amrstream trace builtin:cloud --backend X` for every GPU backend gives the same steps taken and
# the same termination reasons as `--backend cpu`, with the Vulkan validation layer on and no
# validation error (amrstream fails when the layer reports one); and that the points kept on the
# device until they are written (--trace-store device) make the same file, byte for byte, as the
# points collected in host memory.
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
expected=$(summary cpu)
echo "cpu: $expected"
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
done
