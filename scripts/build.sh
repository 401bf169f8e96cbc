#!/usr/bin/env bash
# Configures and builds amrstream. Usage: scripts/build.sh [release|sanitize]
#   release   optimised build in build/ (default)
#   sanitize  debug build with AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/,
#             without the Python module
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=${1:-release}
case "$mode" in
  release)  dir="$root/build";      flags=(-DCMAKE_BUILD_TYPE=Release) ;;
  # The Python module's and the ParaView plugin's tests run in the release build only.
  sanitize) dir="$root/build-asan"; flags=(-DCMAKE_BUILD_TYPE=Debug -DAMRSTREAM_SANITIZE=ON
                                           -DAMRSTREAM_PYTHON=OFF) ;;
  *) echo "usage: $0 [release|sanitize]" >&2; exit 2 ;;
esac
jobs=$(nproc 2>/dev/null || echo 2)
# ccache (install_deps.sh installs it) keeps what was compiled, so that a fresh clone of the same
# sources, in any folder, compiles only what changed: paths relative to the clone, and the
# working directory left out of the hash of debug builds.
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
  flags+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
cmake -S "$root" -B "$dir" "${flags[@]}" >/dev/null
cmake --build "$dir" -j "$jobs"
