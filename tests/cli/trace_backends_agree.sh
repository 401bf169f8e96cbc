#!/bin/sh
# `amrstream trace builtin:cloud --backend X` for every GPU backend gives the same steps taken and
# the same termination reasons as `--backend cpu`, with the Vulkan validation layer on and no
# validation error (amrstream fails when the layer reports one).
# Usage: trace_backends_agree.sh AMRSTREAM WORK_DIR
set -eu
amrstream=$1 dir=$2
mkdir -p "$dir"
summary() {
  AMRSTREAM_VALIDATION=1 "$amrstream" trace builtin:cloud --backend "$1" --steps 1000 --count 128 \
    --out "$dir/$1.vtp" > "$dir/$1.txt"
  grep -E '^(steps|reasons) ' "$dir/$1.txt"
}
expected=$(summary cpu)
echo "cpu: $expected"
for backend in rayquery pipeline compute; do
  got=$(summary "$backend")
  echo "$backend: $got"
  grep -q "^tracing    backend $backend on" "$dir/$backend.txt" || { echo "$backend did not run on the GPU" >&2; exit 1; }
  [ "$got" = "$expected" ] || { echo "$backend differs from cpu" >&2; exit 1; }
done
