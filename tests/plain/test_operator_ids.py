"""Issue 59 point 3: every operator id is `object.water_<what>`, and a switch is one operator with
`enable`, never a pair; the old ids (`object.water_surface_*`, `RENAMED`, and those of one way of
a switch, `FIXED`) live only in the alias list (`operators/_aliases.py`, which keeps them
working), and nothing else (the panel, the tools, the tests, the documents) calls them. Read from
the sources; the Blender side is `tests/test_operator_ids.py`."""

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


def _literal(name):
    tree = ast.parse(ALIASES.read_text(encoding="utf-8"))
    for node in tree.body:
        if _assigns(node, name):
            return ast.literal_eval(node.value)
    raise AssertionError(f"operators/_aliases.py has no {name} literal")


def _renamed():
    return _literal("RENAMED")


def _fixed():
    return _literal("FIXED")


def _old_ids():
    return {*_renamed(), *_fixed()}


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


def test_each_fixed_old_id_is_one_way_of_a_switch_and_each_way_once():
    fixed, idnames, renamed = _fixed(), _idnames(), _renamed()
    assert fixed and not set(fixed) & set(idnames), "an old id is an alias, not an operator's bl_idname"
    assert not set(fixed) & set(renamed)
    ways = set()
    for old, (new, values, label) in fixed.items():
        assert re.fullmatch(r"object\.water_[a-z]+(_[a-z]+)*", old), old
        assert new in idnames, f"{old}: alias of no operator {new}"
        assert values in ({"enable": True}, {"enable": False}), f"{old}: a switch's way is all it fixes"
        assert isinstance(label, str) and label, old
        assert (new, values["enable"]) not in ways, f"two old ids for one way of {new}"
        ways.add((new, values["enable"]))
        source = (ROOT / idnames[new]).read_text(encoding="utf-8")
        assert "enable: bpy.props.BoolProperty(" in source, f"{new} has no `enable`"


# Operator names that say one way of a switch: a pair, where one operator with `enable` is asked.
ONE_WAY = re.compile(r"_(stop|remove|let_in|off|disable|add|on|enable|start)$")
# The actions named so that are no switch's way: what each does, and why it has no other way.
ACTIONS = {
    "object.water_add": "makes a new water, no switch of one",
    "object.water_remove": "takes a whole water away, and all made for it",
    "object.water_waves_add": "adds the Water Waves modifier (the modifier stack takes it off)",
    "object.water_preset_add": "saves the values as a user preset, a file",
    "object.water_preset_remove": "deletes a user preset's file",
}


def test_no_switch_is_a_pair_of_operators():
    """CONTRIBUTING's "Adding a feature": a switch is one operator `object.water_<feature>` with
    `enable`; an operator named for one way (`*_stop`, `*_remove`, `*_let_in`, ...) is an action
    listed in `ACTIONS` with why, or an old id in `operators/_aliases.py`."""
    idnames = _idnames()
    one_way = sorted(idname for idname in idnames if ONE_WAY.search(idname) and idname not in ACTIONS)
    assert not one_way, (
        f"one way of a switch (make it `enable` of one operator, old ids in _aliases.FIXED): {one_way}"
    )
    gone = sorted(set(ACTIONS) - set(idnames))
    assert not gone, f"no such operator any more: take it off ACTIONS: {gone}"


def test_nothing_but_the_alias_list_calls_an_old_id():
    names = sorted(old.split(".")[1] for old in _old_ids())
    pattern = re.compile(r"(" + "|".join(names) + r")\b")
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
