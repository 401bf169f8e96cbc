#!/bin/sh
# `amrstream pathlines` and its streaklines write .vtp files that VTK's vtkXMLPolyDataReader opens
# with the named arrays (temp along the paths included), the counts of the summary and the
# provenance in FieldData.
# Usage: pathlines_open_in_vtk.sh AMRSTREAM PYTHON CHECK_SCRIPT WORK_DIR
set -eu
amrstream=$1 python=$2 check=$3 dir=$4
mkdir -p "$dir"
rm -f "$dir"/swirl_* "$dir"/*.vtp
"$amrstream" gen swirl --levels 3 --root-blocks 2 --target-cells 20000 --series 4 --interval 0.05 \
  --out "$dir/swirl" > /dev/null

counts() {  # "LINES POINTS" from the summary's output line
  echo "$1" | grep '^output ' | sed -n 's/.*(\([0-9,]*\) [a-z]*, \([0-9,]*\) points).*/\1 \2/p' | tr -d ,
}

summary=$("$amrstream" pathlines "$dir/swirl_*.exa" --count 32 --seed-box 0.3,0.3,0.3,0.7,0.7,0.7 \
  --interpolant linear --out "$dir/paths.vtp")
echo "$summary"
set -- $(counts "$summary")
[ "$1" -eq 32 ] || { echo "expected 32 pathlines, the summary says $1" >&2; exit 1; }
"$python" "$check" "$dir/paths.vtp" --points "$2" --lines "$1" \
  --point-array IntegrationTime:1 --point-array vel:3 --point-array temp:1 --point-array Speed:1 \
  --cell-array SeedIds:1 --cell-array ReasonForTermination:1 --speed-of vel --seed-ids \
  --field-text Output=pathlines --field-text Interpolant=linear --field-text StepMode=time

summary=$("$amrstream" pathlines "$dir/swirl_*.exa" --seed-line 0.6,0.5,0.5,0.7,0.5,0.5 --count 4 \
  --release-every 0.02 --out "$dir/streaks.vtp")
echo "$summary"
set -- $(counts "$summary")
[ "$1" -eq 4 ] || { echo "expected 4 streaklines, the summary says $1" >&2; exit 1; }
exec "$python" "$check" "$dir/streaks.vtp" --points "$2" --lines "$1" \
  --point-array IntegrationTime:1 --point-array temp:1 --cell-array SeedIds:1 --seed-ids \
  --field-text Output=streaklines
