"""Issue 59 point 3: the layout CONTRIBUTING's "Adding a feature" asks for, read from the sources.
A family has one place at every layer, a node group one module, and no module grows past what one
can read (600 lines)."""

import ast

from conftest import ROOT

MAX_LINES = 600
# Not part of the add-on (never zipped): their length is their own business.
OUTSIDE = {"tests", "tools", "bench", ".git", ".ci", "docs", "out", "build"}
# Modules still over MAX_LINES, each with why and when it goes. None now.
TOO_LONG = {}
# Families that have a package under nodes/ or operators/ but none under water/: where water/ keeps
# them instead. The lake is what every water is (water/'s top level); the view from below and the
# surroundings are one module each there.
WATER_HOME = {
    "lake": "water/plane.py",
    "under": "water/underwater.py",
    "surroundings": "water/surroundings.py",
}


def _addon_modules():
    for path in sorted(ROOT.rglob("*.py")):
        parts = path.relative_to(ROOT).parts
        if parts[0] not in OUTSIDE and not any(part.startswith(".") for part in parts):
            yield path


def _families(layer):
    return {p.name for p in (ROOT / layer).iterdir() if p.is_dir() and (p / "__init__.py").exists()}


def test_no_module_is_over_600_lines():
    long = {}
    for path in _addon_modules():
        name = path.relative_to(ROOT).as_posix()
        lines = len(path.read_text(encoding="utf-8").splitlines())
        if lines > MAX_LINES and name not in TOO_LONG:
            long[name] = lines
    assert not long, f"split these (one module a group; helpers to a *_parts.py): {long}"
    for name in TOO_LONG:
        assert (ROOT / name).exists(), f"{name} is gone: take it off TOO_LONG"


def test_each_family_has_one_place_at_every_layer():
    water = _families("water")
    for layer in ("nodes", "operators"):
        for family in _families(layer):
            if family in water:
                continue
            assert family in WATER_HOME, f"{layer}/{family}/ has no water/{family}/ (nor a WATER_HOME)"
            assert (ROOT / WATER_HOME[family]).exists(), WATER_HOME[family]
    # The panel's part of each family with operators is ui/<family>.py.
    for family in _families("operators"):
        assert (ROOT / "ui" / f"{family}.py").exists(), f"operators/{family}/ has no ui/{family}.py"


def _group_specs(tree):
    return [
        node
        for node in ast.walk(tree)
        if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "GroupSpec"
    ]


def test_one_module_a_group():
    """A module describes at most one group: one `GroupSpec(...)`. Its optional parts' variants
    (the lake's and the ocean shade's `FULL_SPEC.variant(...)`) are that one description."""
    found = 0
    for path in sorted((ROOT / "nodes").rglob("*.py")):
        specs = _group_specs(ast.parse(path.read_text(encoding="utf-8")))
        assert len(specs) <= 1, f"{path.relative_to(ROOT)} describes {len(specs)} groups: a module each"
        found += len(specs)
    assert found >= 20  # the check reads the groups at all
