#!/bin/sh
# The front door holds: the public headers (include/amrstream) include nothing of src/, and the
# command line (src/cli) includes nothing of the library's internals, only include/amrstream and
# its own files. (The compiler holds both too: neither sees src/ on its include path.)
# Usage: check_front_door.sh SOURCE_DIR
set -eu
root=$1
internal='#include "\(\.\./\)*\(api\|app\|bench\|bricks\|flow\|formats\|gpu\|mpi\|output\|render\|synth\|util\|viewer\|vk\|shaders\)/'
status=0
for dir in include/amrstream src/cli; do
  if grep -rn "$internal" "$root/$dir"; then
    echo "$dir includes the library's internals (above)" >&2
    status=1
  fi
done
exit $status
