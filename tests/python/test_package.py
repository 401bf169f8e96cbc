"""The package the tests run against: pip's install in $AMRSTREAM_TEST_VENV where that is set
(scripts/run_tests.sh), else the build tree's; one version for the package, module and CLI."""
import importlib.metadata
import os
import subprocess
from pathlib import Path

import amrstream
from amrstream import _amrstream


def test_the_package_is_the_one_asked_for():
    venv = os.environ.get("AMRSTREAM_TEST_VENV")
    where = Path(venv) if venv else Path(os.environ["AMRSTREAM_BUILD_PACKAGE"])
    for module in (amrstream, _amrstream):
        assert where.resolve() in Path(module.__file__).resolve().parents, module.__file__
    if venv:
        assert "site-packages" in Path(amrstream.__file__).parts


def test_one_version_for_the_package_the_module_and_the_command_line():
    cli = subprocess.run([os.environ["AMRSTREAM_CLI"], "--version"], check=True,
                         capture_output=True, text=True).stdout.split()
    assert amrstream.__version__ in cli
    if os.environ.get("AMRSTREAM_TEST_VENV"):
        assert importlib.metadata.version("amrstream") == amrstream.__version__


def test_the_package_ships_the_paraview_plugin_and_names_it():
    import sys

    plugin = Path(amrstream.__file__).parent / "paraview_plugin" / "amrstream_paraview.xml"
    assert plugin.is_file()
    # The plugin's folder holds it alone: ParaView loads every plugin in a PV_PLUGIN_PATH folder.
    assert [p.name for p in plugin.parent.iterdir()] == [plugin.name]
    printed = subprocess.run([sys.executable, "-m", "amrstream", "plugin"], check=True,
                             capture_output=True, text=True).stdout.strip()
    assert Path(printed) == plugin
    refused = subprocess.run([sys.executable, "-m", "amrstream", "paraveiw"],
                             capture_output=True, text=True)
    assert refused.returncode == 2 and "unknown command 'paraveiw'" in refused.stderr
