"""Issue 59 point 3: every operator id is `object.water_<what>`; the old `object.water_surface_*`
ids live only in the alias list (`operators/_aliases.py`, which keeps them working), and nothing
else (the panel, the tools, the tests, the documents) calls them. Read from the sources; the
Blender side is `tests/test_operator_ids.py`."""

import ast
import re

from conftest import ROOT

OLD = "object.water_surface_"
ALIASES = ROOT / "operators" / "_aliases.py"
# Where an old id may be written: the alias list and the test that the old ids still work.
OLD_ALLOWED = {
    ALIASES,
    ROOT / "tests" / "test_operator_ids.py",
    ROOT / "tests" / "plain" / "test_operator_ids.py",
}


def _assigns(node, name):
    """`node` is `name = ...`."""
    return isinstance(node, ast.Assign) and [getattr(t, "id", None) for t in node.targets] == [name]


def _renamed():
    tree = ast.parse(ALIASES.read_text(encoding="utf-8"))
    for node in tree.body:
        if _assigns(node, "RENAMED"):
            return ast.literal_eval(node.value)
    raise AssertionError("operators/_aliases.py has no RENAMED literal")


def _idnames():
    """{bl_idname: path} of every operator class written in operators/."""
    found = {}
    for path in sorted((ROOT / "operators").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if _assigns(node, "bl_idname"):
                assert isinstance(node.value, ast.Constant), f"{path}: bl_idname not a literal"
                assert node.value.value not in found, f"{node.value.value} twice"
                found[node.value.value] = path.relative_to(ROOT).as_posix()
    return found


def test_every_id_is_object_water_what_and_none_is_an_old_one():
    idnames = _idnames()
    assert len(idnames) >= 20
    wrong = sorted(
        idname for idname in idnames if not re.fullmatch(r"object\.water_[a-z]+(_[a-z]+)*", idname)
    )
    assert not wrong, f"not object.water_<what>: {wrong}"
    old = sorted(idname for idname in idnames if idname.startswith(OLD))
    assert not old, f"an old id as an operator's bl_idname, not an alias: {old}"


def test_each_old_id_aliases_a_real_operator_once():
    renamed, idnames = _renamed(), _idnames()
    assert renamed and all(old.startswith(OLD) for old in renamed)
    assert len(set(renamed.values())) == len(renamed), "two old ids for one operator"
    missing = sorted(set(renamed.values()) - set(idnames))
    assert not missing, f"aliases of no operator: {missing}"


def test_nothing_but_the_alias_list_calls_an_old_id():
    pattern = re.compile(r"water_surface_(" + "|".join(old[len(OLD) :] for old in _renamed()) + r")\b")
    places = [ROOT / name for name in ("api.py", "cli.py", "README.md", "CONTRIBUTING.md")]
    for folder in ("operators", "ui", "water", "nodes", "tools", "tests", "bench", "docs"):
        places += sorted((ROOT / folder).rglob("*.py")) + sorted((ROOT / folder).rglob("*.md"))
    callers = [
        f"{path.relative_to(ROOT)}:{number}"
        for path in places
        if path not in OLD_ALLOWED
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if pattern.search(line)
    ]
    assert not callers, "calls an old id (use the new one, `operators/_aliases.py`):\n" + "\n".join(callers)
