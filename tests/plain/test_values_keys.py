"""Issue 57 point 2: one path per job. Every preset key reaches a water one way, the table
`water/value_keys.py` says which (a shader socket, a step of `water/apply.py`, or made only when
adding, with what changes it later), and `apply.py` has a step and a reader for each key of its
own: walked here against `presets/schema.py`'s fields and `kind.FEATURES`, so a new key or feature
cannot miss one. The schema refuses NaN and infinities for every number, and every error class of
the add-on shares `WaterError`. Read from the sources where a module needs Blender."""

import ast
import math

import pytest
from conftest import ROOT, load
from test_features_once import _features

APPLY = "water/apply.py"


@pytest.fixture(scope="module")
def schema():
    return load("presets.schema")


@pytest.fixture(scope="module")
def table():
    return load("water.value_keys")


def _dict_keys(path, name):
    """The string keys of the module-level dict literal `name` in `path`."""
    tree = ast.parse((ROOT / path).read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.Assign) and [getattr(t, "id", None) for t in node.targets] == [name]:
            assert isinstance(node.value, ast.Dict), f"{path}: {name} is not a dict literal"
            return [key.value for key in node.value.keys]
    raise AssertionError(f"{path} has no {name}")


def test_every_key_of_the_schema_reaches_a_water_one_way(schema, table):
    shader = {field.key for field in schema.FIELDS if field.socket is not None}
    water, adding = set(table.WATER_KEYS), set(table.ADDING_KEYS)
    assert not shader & water and not shader & adding and not water & adding, "one way each"
    missing = sorted(set(schema.BY_KEY) - shader - water - adding)
    assert not missing, f"keys of the schema no path applies (add them to water/value_keys.py): {missing}"
    stale = sorted((water | adding) - set(schema.BY_KEY))
    assert not stale, f"water/value_keys.py names keys the schema lacks: {stale}"
    assert {"underwater", "light_shafts"} <= water, "issue 57: presets and write_values apply them"
    assert all(reason.strip() for reason in table.ADDING_KEYS.values())


def test_apply_has_one_step_and_one_reader_for_each_water_key_in_order(table):
    steps, readers = _dict_keys(APPLY, "_STEPS"), _dict_keys(APPLY, "_READERS")
    assert sorted(steps) == sorted(table.WATER_KEYS), "apply_values: one step per key"
    assert sorted(readers) == sorted(table.WATER_KEYS), "read_water: one reader per key"
    assert steps.index("underwater") < steps.index("light_shafts"), "the body before its fog's shafts"


def test_every_feature_is_a_water_keys_or_said_why_not(table):
    features = set().union(*_features().values())
    named = set(table.WATER_KEYS.values())
    assert named <= features, f"water/value_keys.py names features kind.FEATURES lacks: {named - features}"
    without = set(table.FEATURES_WITHOUT_VALUES)
    assert not named & without, f"both a value's feature and one without values: {named & without}"
    missing = sorted(features - named - without)
    assert not missing, f"kind.FEATURES keys water/value_keys.py does not place: {missing}"
    stale = sorted(without - features)
    assert not stale, f"FEATURES_WITHOUT_VALUES names features kind.FEATURES lacks: {stale}"


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_every_number_of_the_schema_refuses_nan_and_infinity_naming_its_key(schema, bad):
    numeric = [field for field in schema.FIELDS if field.kind in ("float", "int", "vec2", "color")]
    assert {"light_shafts", "caustics", "wind_direction", "absorption"} <= {f.key for f in numeric}
    for field in numeric:
        width = {"vec2": 2, "color": 3}.get(field.kind)
        value = bad if width is None else (0.5,) * (width - 1) + (bad,)
        with pytest.raises(schema.PresetError, match=f"'{field.key}' must be finite"):
            schema.check_types({field.key: value})


def _classes():
    """{class name: (path, base names)} of every class in the add-on's modules."""
    found = {}
    for path in sorted(ROOT.rglob("*.py")):
        if {"tests", "tools", "bench", "docs", "out"} & set(path.relative_to(ROOT).parts):
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ClassDef):
                bases = [b.id if isinstance(b, ast.Name) else getattr(b, "attr", None) for b in node.bases]
                found[node.name] = (path.relative_to(ROOT).as_posix(), bases)
    return found


# Errors that never leave the add-on's own code: the command line's (turned into one line and an
# exit status by `cli.main`) and the node builder's (nodes/ imports nothing of water/; adding and
# repair turn it into their own errors).
INTERNAL = {"UsageError", "_ParserExitError", "NodeGroupError"}


def test_every_error_class_of_the_add_on_shares_water_error():
    classes = _classes()

    def derives(name, seen=()):
        if name == "WaterError":
            return True
        if name not in classes or name in seen:
            return False
        return any(derives(base, (*seen, name)) for base in classes[name][1])

    errors = {name for name, (_path, bases) in classes.items() if name.endswith("Error")}
    assert len(errors - INTERNAL) >= 14, sorted(errors)
    lonely = sorted(f"{classes[n][0]}: {n}" for n in errors - INTERNAL if not derives(n))
    assert not lonely, f"error classes without the WaterError base: {lonely}"
    assert INTERNAL <= errors, "INTERNAL names classes that no longer exist"
