"""python -m amrstream paraview|pvpython|pvbatch [ARGS...]: runs ParaView's program with the amrstream
plugin loaded and this amrstream importable in its Python (ParaView's Python must be the one this
package was built for). python -m amrstream plugin: prints the plugin's path, for Tools > Manage
Plugins or LoadPlugin()."""

import os
import shutil
import sys

PROGRAMS = ("paraview", "pvpython", "pvbatch")
PACKAGE = os.path.dirname(os.path.abspath(__file__))
# The plugin's folder holds the plugin alone, so that ParaView can load every plugin it holds.
PLUGIN_FOLDER = os.path.join(PACKAGE, "paraview_plugin")
PLUGIN = os.path.join(PLUGIN_FOLDER, "amrstream_paraview.xml")


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0
    if argv[0] == "plugin":
        print(PLUGIN)
        return 0
    if argv[0] not in PROGRAMS:
        print(f"python -m amrstream: unknown command {argv[0]!r}; the commands are plugin, "
              + ", ".join(PROGRAMS), file=sys.stderr)
        return 2
    program = shutil.which(argv[0])
    if program is None:
        print(f"python -m amrstream: {argv[0]} is not on PATH: install ParaView (on Debian the "
              "packages paraview and python3-paraview)", file=sys.stderr)
        return 1
    environment = dict(os.environ)
    paths = [os.path.dirname(PACKAGE)] + [p for p in environment.get("PYTHONPATH", "").split(
        os.pathsep) if p]
    environment["PYTHONPATH"] = os.pathsep.join(paths)
    plugin_paths = [PLUGIN_FOLDER] + [p for p in environment.get("PV_PLUGIN_PATH", "").split(
        os.pathsep) if p]
    environment["PV_PLUGIN_PATH"] = os.pathsep.join(plugin_paths)
    os.execve(program, [program, *argv[1:]], environment)
    return 1  # not reached


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
