#!/usr/bin/env bash
# Installs the `amrstream` Python package into a virtual environment with pip (pyproject.toml,
# scikit-build-core), reusing the CMake build scripts/build.sh made so that nothing is compiled
# twice; makes the environment first where it does not exist (with Debian's python3 and
# --system-site-packages, so that numpy, yt and scikit-build-core come from Debian).
# Usage: scripts/install_python.sh [VENV] [BUILD_DIR]   (defaults: .venv, build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=$(realpath -m "${1:-$root/.venv}")
build=$(realpath -m "${2:-$root/build}")
[ -x "$venv/bin/python" ] || /usr/bin/python3 -m venv --system-site-packages "$venv"
# --no-build-isolation: the build requirements come from the environment (Debian's), as only
# Debian's archive may be reachable; the generator is the one scripts/build.sh configured with.
# The build keeps its tests (pyproject.toml leaves them out of a wheel's own build).
CMAKE_GENERATOR="Unix Makefiles" "$venv/bin/pip" install --quiet --no-build-isolation \
  --config-settings=build-dir="$build" \
  --config-settings=cmake.define.AMRSTREAM_BUILD_TESTS=ON "$root"
# scikit-build-core's configure left its settings in the build's cache: back to the plain build's.
cmake -S "$root" -B "$build" -U 'SKBUILD*' -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
(cd / && "$venv/bin/python" -c "import amrstream; print('python     amrstream', amrstream.__version__, 'in', '$venv', '(source $venv/bin/activate)')")
