"""Plain-Python tests: the add-on's modules that need no Blender, imported without it.

This folder's tests run in their own pytest session (`tools/test` runs it first, with
`--confcutdir=tests/plain`, so the Blender conftest above is never loaded). The add-on's
package is made importable under the name `water_surface` without running its `__init__`
(which registers with Blender): only the modules a test imports are loaded.
"""

import importlib
import importlib.machinery
import sys
import types
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGE = "water_surface"


def _package():
    if PACKAGE not in sys.modules:
        module = types.ModuleType(PACKAGE)
        module.__path__ = [str(ROOT)]
        module.__spec__ = importlib.machinery.ModuleSpec(PACKAGE, None, is_package=True)
        module.__spec__.submodule_search_locations = [str(ROOT)]
        sys.modules[PACKAGE] = module
    return sys.modules[PACKAGE]


_package()


def load(name):
    """The add-on's module `name` ("presets.schema", "water.sea.sea_math"), imported without Blender."""
    return importlib.import_module(f"{PACKAGE}.{name}")


@pytest.fixture(scope="session")
def addon_module():
    return load
