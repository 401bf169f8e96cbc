#!/bin/sh
# Runs one test file with pytest: against the package installed in the virtual environment
# $AMRSTREAM_TEST_VENV where that is set (scripts/run_tests.sh sets it), else against the package
# in the build tree ($AMRSTREAM_BUILD_PACKAGE) with Debian's python3.
# Usage: run_pytest.sh TEST_FILE
set -e
if [ -n "${AMRSTREAM_TEST_VENV:-}" ]; then
  exec "$AMRSTREAM_TEST_VENV/bin/python" -m pytest -q -p no:cacheprovider "$1"
fi
PYTHONPATH="$AMRSTREAM_BUILD_PACKAGE" exec /usr/bin/python3 -m pytest -q -p no:cacheprovider "$1"
