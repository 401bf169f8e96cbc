#!/usr/bin/env bash
# Installs the built `amrstream` Python package where Debian's python3 finds it
# (/usr/local/lib/python3.X/dist-packages/amrstream), then checks that it imports.
# Usage: scripts/install_python.sh [BUILD_DIR]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
if [ "$(id -u)" -eq 0 ]; then
  cmake --install "$build" --component python
else
  sudo cmake --install "$build" --component python
fi
(cd / && /usr/bin/python3 -c "import amrstream; print('python     import amrstream works:', amrstream.__file__)")
