#!/bin/sh
# Runs a ParaView test script with pvpython or pvbatch through `python -m amrstream`, which loads
# the plugin and makes the package importable: the package installed in the virtual environment
# $AMRSTREAM_TEST_VENV where that is set (scripts/run_tests.sh sets it), else the one in the build
# tree ($AMRSTREAM_BUILD_PACKAGE) with Debian's python3. pvbatch and the paraview GUI run in a
# virtual X server.
# Usage: run_paraview.sh pvpython|pvbatch|paraview ARGS...
set -e
program=$1
shift
if [ -n "${AMRSTREAM_TEST_VENV:-}" ]; then
  python="$AMRSTREAM_TEST_VENV/bin/python"
else
  python=/usr/bin/python3
  export PYTHONPATH="$AMRSTREAM_BUILD_PACKAGE"
fi
if [ "$program" != pvpython ]; then
  # -noreset: see tests/app (a server resetting as a window closes refuses the next client).
  exec xvfb-run -n 140 -a -s "-screen 0 1280x1024x24 -noreset" "$python" -m amrstream "$program" "$@"
fi
exec "$python" -m amrstream "$program" "$@"
