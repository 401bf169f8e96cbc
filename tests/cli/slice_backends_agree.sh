#!/bin/sh
# `amrstream slice --lic --backend X` for every GPU backend draws the same figure, byte for byte,
# as `--backend cpu` (on lavapipe, whose float arithmetic rounds as the CPU's does), across an axis
# and off axis, with the Vulkan validation layer on and no validation error (amrstream fails when
# the layer reports one).
# Usage: slice_backends_agree.sh AMRSTREAM WORK_DIR
set -eu
amrstream=$1 dir=$2
mkdir -p "$dir"
figure() {  # backend, normal
  AMRSTREAM_VALIDATION=1 "$amrstream" slice builtin:cloud --width 160 --lic --lic-length 0.05 \
    --normal "$2" --backend "$1" --out "$dir/$1-$2.png" > "$dir/$1-$2.txt"
}
for normal in z 1,2,3; do
  figure cpu "$normal"
  for backend in rayquery pipeline compute; do
    figure "$backend" "$normal"
    grep -q "^lic .*$backend \[" "$dir/$backend-$normal.txt" || {
      echo "slice --backend $backend did not say it made the LIC there:"
      cat "$dir/$backend-$normal.txt"
      exit 1
    }
    cmp "$dir/cpu-$normal.png" "$dir/$backend-$normal.png" || {
      echo "slice --normal $normal --lic: $backend's figure differs from the cpu's"
      exit 1
    }
    echo "$backend, normal $normal: the cpu's figure"
  done
done
