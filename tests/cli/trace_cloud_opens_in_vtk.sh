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
summary=$("$amrstream" trace builtin:cloud --backend cpu --steps 1000 --count 64 --vorticity --out "$out")
echo "$summary"
line=$(echo "$summary" | grep '^output ')
lines=$(echo "$line" | sed -n 's/.*(\([0-9,]*\) polylines, \([0-9,]*\) points).*/\1/p' | tr -d ,)
points=$(echo "$line" | sed -n 's/.*(\([0-9,]*\) polylines, \([0-9,]*\) points).*/\2/p' | tr -d ,)
[ -n "$lines" ] && [ -n "$points" ] || { echo "no output line in the summary" >&2; exit 1; }
[ "$lines" -eq 128 ] || { echo "expected 128 polylines (64 seeds, both directions), summary says $lines" >&2; exit 1; }
"$python" "$check" "$out" --points "$points" --lines "$lines" \
  --point-array IntegrationTime:1 --point-array Speed:1 --point-array mag:3 --point-array dens:1 \
  --point-array Vorticity:3 --point-array Rotation:1 --point-array AngularVelocity:1 \
  --cell-array SeedIds:1 --cell-array ReasonForTermination:1 \
  --scalars IntegrationTime --vectors mag --speed-of mag --both-directions 64 \
  --field-text Input=builtin:cloud --field-text IntegrationDirection=both \
  --field-text PointDataChannels=dens --field-text StepMode=arc --field-text Integrator=rk4

# A periodic box: the lines are split where they wrap, so there are more polylines than lines,
# every one inside the domain; VTK opens them.
out="$dir/abc.vtp"
summary=$("$amrstream" trace builtin:abc --backend cpu --steps 3000 --count 16 --compression lz4 --out "$out")
echo "$summary"
line=$(echo "$summary" | grep '^output ')
lines=$(echo "$line" | sed -n 's/.*(\([0-9,]*\) polylines, \([0-9,]*\) points).*/\1/p' | tr -d ,)
points=$(echo "$line" | sed -n 's/.*(\([0-9,]*\) polylines, \([0-9,]*\) points).*/\2/p' | tr -d ,)
[ "$lines" -gt 32 ] || { echo "expected the 32 periodic lines split into more polylines, got $lines" >&2; exit 1; }
exec "$python" "$check" "$out" --points "$points" --lines "$lines" \
  --point-array IntegrationTime:1 --point-array vel:3 --cell-array SeedIds:1 \
  --field-text Periodic=x,y,z
