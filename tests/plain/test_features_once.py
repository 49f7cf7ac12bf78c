"""Issue 41 point 2: `water/kind.py`'s `FEATURES` is the one place that says what a kind of water
allows. Every key in it is asked somewhere (else it says nothing), and no other module decides by
comparing a water's kind with a kind constant. Read from the sources (kind.py needs Blender)."""

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
KIND = "water/kind.py"
ADDON = ("api.py", "cli.py", "handlers.py", "engine.py", "__init__.py", "operators", "ui", "water", "nodes")
# The calls that ask the table, each with the feature as a string argument.
ASKING = {"allows", "refusal", "water_allowing", "any_water", "selected_water_allowing", "check_allowed"}
KIND_NAMES = {"LAKE", "OCEAN", "OPEN_SEA"}
# Where a module needs the kind itself, not what it allows: (path, function) and why.
NEEDS_THE_KIND = {
    ("water/plane.py", "dress_water"): "adding water builds the kind's own material and waves",
    ("water/plane.py", "_new_mesh"): "the open sea's mesh is graded to the horizon, the others' even",
    ("water/plane.py", "add_water"): "an open sea's memory note, and its mesh kept as made",
    ("water/values.py", "_shader_node"): "the lake's and the ocean's values sit in different group nodes",
    ("water/values.py", "set_values"): "the lake's and the ocean's values sit in different group nodes",
    ("water/values.py", "switch_part"): "the lake's and the ocean's shadings have different parts",
    ("water/repair.py", "_parts"): "repair rebuilds the group nodes the water's shading has",
    ("water/surroundings.py", "coarse_grid_note"): "the open sea's grid is graded by design: no note",
}


def _modules():
    for entry in ADDON:
        path = ROOT / entry
        for file in sorted(path.rglob("*.py")) if path.is_dir() else [path]:
            yield file.relative_to(ROOT).as_posix(), ast.parse(file.read_text(encoding="utf-8"))


def _features():
    """kind.FEATURES, worked out from kind.py's own assignments (importing it needs Blender)."""
    tree = ast.parse((ROOT / KIND).read_text(encoding="utf-8"))
    wanted = {"LAKE", "OCEAN", "OPEN_SEA", "_EVERY_KIND", "FEATURES"}
    body = [
        node
        for node in tree.body
        if isinstance(node, ast.Assign) and {getattr(t, "id", None) for t in node.targets} & wanted
    ]
    space = {}
    exec(compile(ast.Module(body=body, type_ignores=[]), KIND, "exec"), space)
    return space["FEATURES"]


def _name(node):
    return node.id if isinstance(node, ast.Name) else node.attr if isinstance(node, ast.Attribute) else None


def _asked():
    """The features the add-on asks outside kind.py: string arguments of the asking calls, and
    `feature = "..."` (an operator class naming the feature its poll asks)."""
    found = set()
    for path, tree in _modules():
        if path == KIND:
            continue
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and _name(node.func) in ASKING:
                args = list(node.args) + [k.value for k in node.keywords if k.arg == "feature"]
                found |= {a.value for a in args if isinstance(a, ast.Constant) and isinstance(a.value, str)}
            elif isinstance(node, ast.Assign) and [_name(t) for t in node.targets] == ["feature"]:
                if isinstance(node.value, ast.Constant):
                    found.add(node.value.value)
    return found


def _deciding_by_kind():
    """(path, function, line) of each comparison with a kind constant, and each call of
    `is_open_sea`, outside kind.py (and open_sea.py, which defines it); the function is the
    innermost one holding it."""
    found = []

    def visit(path, node, where):
        if isinstance(node, ast.FunctionDef):
            where = node.name
        if isinstance(node, ast.Compare) and any(
            _name(o) in KIND_NAMES for o in [node.left, *node.comparators]
        ):
            found.append((path, where, node.lineno))
        open_sea_itself = path == "water/sea/open_sea.py"
        if isinstance(node, ast.Call) and _name(node.func) == "is_open_sea" and not open_sea_itself:
            found.append((path, where, node.lineno))
        for child in ast.iter_child_nodes(node):
            visit(path, child, where)

    for path, tree in _modules():
        if path != KIND:
            visit(path, tree, "<module>")
    return sorted(found)


def test_every_feature_in_the_table_is_asked_somewhere():
    table = _features()
    assert set(table) == {"lake", "ocean", "open_sea"}
    keys = set().union(*table.values())
    assert {"floating", "wake", "keep_out"} <= keys, "what floating offers is in the table"
    never = sorted(keys - _asked())
    assert not never, f"keys of kind.FEATURES nothing asks: {never}"


def test_no_module_but_kind_decides_by_comparing_kinds():
    unexplained = [
        f"{path}:{line} in {where}"
        for path, where, line in _deciding_by_kind()
        if (path, where) not in NEEDS_THE_KIND
    ]
    assert not unexplained, "ask kind.allows / kind.refusal instead:\n" + "\n".join(unexplained)


def test_the_allow_list_names_only_places_that_still_compare_kinds():
    left = {(path, where) for path, where, _line in _deciding_by_kind()}
    stale = sorted(set(NEEDS_THE_KIND) - left)
    assert not stale, f"no longer compares kinds, take it off NEEDS_THE_KIND: {stale}"
