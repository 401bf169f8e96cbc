#!/bin/bash
# The input stage of `amrstream info` on the same generated cloud written as a FLASH HDF5 file, an
# Enzo output and an AMReX plotfile (amrstream gen --format), each file set at least 1 GB with the
# default 64 M cells. Each format is read twice by each build given; prints a table of format,
# bytes, the input stage's seconds (from the `wall` line) and GB/s. Needs only the executables:
# the files are written by NEW itself.
#
#   bench/format_reads.sh [--dir DIR] [--cells N] NEW [OLD]
#
# DIR (default $FORMAT_READS_DIR, else /dev/shm/amrstream-formats: a tmpfs keeps the page cache
# warm, so that the reading, not the storage, is measured) holds one format's files at a time;
# they are removed at the end. OLD's rows come first.
set -euo pipefail

dir=${FORMAT_READS_DIR:-/dev/shm/amrstream-formats}
cells=64000000
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --dir) dir=$2; shift 2 ;;
    --cells) cells=$2; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
if [[ $# -lt 1 ]]; then
  echo "usage: $0 [--dir DIR] [--cells N] NEW [OLD]" >&2
  exit 2
fi
new=$1
builds=("$new")
[[ $# -ge 2 ]] && builds=("$2" "$new")

mkdir -p "$dir"
trap 'rm -rf "$dir"' EXIT

# The input stage's seconds, from the summary's `wall ...: ..., input S, ...` line.
input_seconds() {
  "$1" info "$2" 2>&1 | sed -n 's/^wall .*input \([0-9.]*\).*/\1/p'
}

printf '%-6s %-5s %14s %10s %8s\n' format build bytes "input s" "GB/s"
for format in flash enzo amrex; do
  rm -rf "${dir:?}"/*
  "$new" gen cloud --levels 7 --root-blocks 8 --target-cells "$cells" --format "$format" \
    --out "$dir/cloud" >/dev/null
  case $format in
    flash) input=$dir/cloud.h5 ;;
    enzo) input=$dir/cloud ;;
    amrex) input=$dir/cloud.plt ;;
  esac
  bytes=$(du -sbc "$dir"/cloud* | tail -1 | cut -f1)
  for build in "${builds[@]}"; do
    name=new
    [[ ${#builds[@]} -eq 2 && $build == "${builds[0]}" ]] && name=old
    for run in 1 2; do
      seconds=$(input_seconds "$build" "$input")
      printf '%-6s %-5s %14s %10s %8s\n' "$format" "$name" "$bytes" "$seconds" \
        "$(awk -v b="$bytes" -v s="$seconds" 'BEGIN { if (s > 0) printf "%.2f", b / s / 1e9 }')"
    done
  done
done
