#!/bin/sh
# `amrstream resample builtin:abc` writes a .vti that VTK's vtkXMLImageDataReader opens, with the
# analytic ABC flow at its points (check_resampled_abc.py), in each compression.
# Usage: resample_opens_in_vtk.sh AMRSTREAM PYTHON CHECK_SCRIPT WORK_DIR
set -eu
amrstream=$1 python=$2 check=$3 dir=$4
mkdir -p "$dir"
for compression in zlib lz4 none; do
  out="$dir/abc_$compression.vti"
  rm -f "$out"
  "$amrstream" resample builtin:abc --dims 24,20,16 --compression "$compression" --out "$out"
  # The coarsest cells are 1/16 wide: the tent reconstruction is within 0.017 of the flow there;
  # points half a spacing off would be 0.58 away.
  "$python" "$check" "$out" 24 20 16 0.05
done
