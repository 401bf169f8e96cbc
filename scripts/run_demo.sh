#!/usr/bin/env bash
# Quick start, command 1: installs what is missing, builds, traces the built-in magnetised cloud
# to traces.vtp (open it in ParaView) and renders its field lines as tubes in front of the
# density to cloud.png (the README's first image; seconds on lavapipe). Installs the Python
# package with pip into the virtual environment .venv (`source .venv/bin/activate`, then
# `import amrstream`). Extra arguments go to `amrstream trace`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh" release
"$root/scripts/install_python.sh"
"$root/build/src/cli/amrstream" trace builtin:cloud --out traces.vtp "$@"
"$root/build/src/cli/amrstream" render builtin:cloud --count 512 --steps 2000 --volume dens \
  --axes --width 800 --height 500 --frames 8 --out cloud.png
