#!/bin/sh
# The main job end to end: `amrstream trace builtin:cloud --steps 1000` writes a .vtp that VTK's
# vtkXMLPolyDataReader opens with the named arrays (the density along the lines included) and
# the polyline and point counts printed in amrstream's summary, in vtkStreamTracer's layout for
# both directions.
# Usage: trace_cloud_opens_in_vtk.sh AMRSTREAM PYTHON CHECK_SCRIPT WORK_DIR
set -eu
amrstream=$1 python=$2 check=$3 dir=$4
mkdir -p "$dir"
out="$dir/t.vtp"
rm -f "$out"
summary=$("$amrstream" trace builtin:cloud --backend cpu --steps 1000 --count 64 --out "$out")
echo "$summary"
line=$(echo "$summary" | grep '^output ')
lines=$(echo "$line" | sed -n 's/.*(\([0-9,]*\) polylines, \([0-9,]*\) points).*/\1/p' | tr -d ,)
points=$(echo "$line" | sed -n 's/.*(\([0-9,]*\) polylines, \([0-9,]*\) points).*/\2/p' | tr -d ,)
[ -n "$lines" ] && [ -n "$points" ] || { echo "no output line in the summary" >&2; exit 1; }
[ "$lines" -eq 128 ] || { echo "expected 128 polylines (64 seeds, both directions), summary says $lines" >&2; exit 1; }
exec "$python" "$check" "$out" --points "$points" --lines "$lines" \
  --point-array IntegrationTime:1 --point-array Speed:1 --point-array mag:3 --point-array dens:1 \
  --cell-array SeedIds:1 --cell-array ReasonForTermination:1 \
  --scalars IntegrationTime --vectors mag --speed-of mag --both-directions 64
