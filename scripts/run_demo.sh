#!/usr/bin/env bash
# Quick start, command 1: installs what is missing, builds, and traces the built-in magnetised
# cloud to traces.vtp (open it in ParaView). Extra arguments go to `amrstream trace`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
"$root/scripts/build.sh" release
"$root/build/src/cli/amrstream" trace builtin:cloud --out traces.vtp "$@"
