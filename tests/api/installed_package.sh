#!/bin/sh
# `cmake --install` gives the headers, the libraries and a CMake package that another project
# finds with find_package(amrstream) and links: tests/api/consumer builds against it and runs.
# Usage: installed_package.sh BUILD_DIR CONSUMER_SOURCE WORK_DIR
set -eu
build=$1 consumer=$2 work=$3
rm -rf "$work"
cmake --install "$build" --prefix "$work/prefix" --component library > "$work.install.log"
test -f "$work/prefix/include/amrstream/trace_job.hpp"
test -f "$work/prefix/lib/cmake/amrstream/amrstreamConfig.cmake"
if grep -rq '#include "\(bricks\|flow\|gpu\|vk\|formats\|synth\|mpi\|output\|render\|util\|api\)/' \
    "$work/prefix/include/amrstream"; then
  echo "an installed header includes the library's internals" >&2
  exit 1
fi
cmake -S "$consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work.configure.log"
cmake --build "$work/build" -j 2 > "$work.build.log"
"$work/build/consumer"
