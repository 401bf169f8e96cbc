"""Registers the yt plot callbacks (yt_callbacks) when yt's plots exist, without importing yt
for a program that never does: at once when yt's plot window module is already imported, else
as soon as it is. Importing yt takes about 0.6 s, more than the rest of amrstream."""
import importlib.abc
import importlib.machinery
import sys

_PLOTS = "yt.visualization.plot_window"


def _register():
    try:
        from . import yt_callbacks  # noqa: F401 (importing it registers the callbacks)
    except ModuleNotFoundError as missing:  # matplotlib or unyt absent: nothing to draw with
        if (missing.name or "").split(".")[0] not in ("yt", "unyt", "matplotlib"):
            raise


class _Loader(importlib.abc.Loader):
    """yt's own loader of the plot window module, then the registration."""

    def __init__(self, loader):
        self._loader = loader

    def create_module(self, spec):
        return self._loader.create_module(spec)

    def exec_module(self, module):
        self._loader.exec_module(module)
        _register()


class _Finder(importlib.abc.MetaPathFinder):
    """Finds yt's plot window module as the other finders do, with _Loader around its loader."""

    def find_spec(self, name, path, target=None):
        if name != _PLOTS:
            return None
        sys.meta_path.remove(self)
        spec = importlib.machinery.PathFinder.find_spec(name, path, target)
        if spec is not None and spec.loader is not None:
            spec.loader = _Loader(spec.loader)
        return spec


def install():
    if _PLOTS in sys.modules:
        _register()
    elif not any(isinstance(finder, _Finder) for finder in sys.meta_path):
        sys.meta_path.insert(0, _Finder())
