"""Presets are JSON data: read, validated, clamped and written without running anything."""

import json

import pytest

import harness

REFERENCE = {
    "size": 128.0,
    "wave_height": 0.3,
    "wave_length": 0.1,
    "wind_direction": (0.0, 1.0),
    "wind_force": 0.02,
    "dull_color": (0.3, 0.3, 0.5),
    "dull_blend": 0.2,
    "specular_power": 256.0,
}


@pytest.fixture(scope="module")
def store(addon):
    return harness.addon("presets.store")


@pytest.fixture(scope="module")
def schema(addon):
    return harness.addon("presets.schema")


def _write(folder, name, data):
    path = folder / f"{name}.json"
    path.write_text(data if isinstance(data, str) else json.dumps(data), encoding="utf-8")
    return path


def test_builtin_presets_hold_the_lake_calm_mirror_windy_river_and_murky_pond(store):
    presets, warnings = store.load_dir(store.BUILTIN_DIR)
    assert warnings == []
    ids = [p.id for p in presets]
    assert ids[0] == "lake", "the reference comes first"
    assert {"lake", "calm_mirror", "windy_river", "murky_pond", "ocean"} <= set(ids)
    lake = presets[0].values
    for key, value in REFERENCE.items():
        assert lake[key] == pytest.approx(value), key
    others = [p.values for p in presets[1:]]
    assert all(values != lake for values in others), "every preset differs from the lake"


def test_out_of_range_values_are_clamped(store, tmp_path):
    path = _write(
        tmp_path,
        "wild",
        {"values": {"wave_height": 99, "wave_length": -1, "size": 1e12, "dull_color": [2, -1, 0.5]}},
    )
    preset, warnings = store.read_preset(path)
    assert warnings == []
    assert preset.values["wave_height"] == 10.0
    assert preset.values["wave_length"] == pytest.approx(0.001)
    assert preset.values["size"] == 100000.0
    assert preset.values["dull_color"] == (1.0, 0.0, 0.5)
    assert preset.name == "Wild", "a missing name comes from the file name"


def test_a_zero_wind_becomes_the_reference_direction(store, tmp_path):
    preset, _ = store.read_preset(_write(tmp_path, "still", {"values": {"wind_direction": [0, 0]}}))
    assert preset.values["wind_direction"] == (0.0, 1.0)


@pytest.mark.parametrize(
    "content, reason",
    [
        ("{ not json", "not valid JSON"),
        ("[1, 2]", "JSON object"),
        ({"values": {"wave_height": "high"}}, "'wave_height' must be a number"),
        ({"values": {"wave_height": True}}, "'wave_height' must be a number"),
        ({"values": {"wind_direction": [1]}}, "list of 2 numbers"),
        ({"values": {"dull_color": [0.1, "x", 0.1]}}, "must be a number"),
        ({"values": [1, 2]}, "'values' must be an object"),
        ({"name": 3}, "'name' must be a non-empty string"),
        ('{"values": {"wave_height": NaN}}', "must be finite"),
        ({"values": {"resolution": 2.5}}, "'resolution' must be a whole number"),
        ({"values": {"waves": 1}}, "'waves' must be true or false"),
        ({"values": {"shading": "lava"}}, "'shading' must be one of lake, ocean"),
    ],
)
def test_broken_or_ill_typed_files_are_skipped_with_a_warning_that_names_them(
    store, tmp_path, content, reason
):
    _write(tmp_path, "good", {"name": "Good"})
    bad = _write(tmp_path, "bad", content)
    presets, warnings = store.load_dir(tmp_path, user=True)
    assert [p.id for p in presets] == ["user:good"]
    assert len(warnings) == 1 and str(bad) in warnings[0] and reason in warnings[0], warnings


def test_unknown_keys_are_ignored_with_a_warning(store, tmp_path):
    preset, warnings = store.read_preset(_write(tmp_path, "extra", {"values": {"colour": 1}, "script": "x"}))
    assert preset.values["wave_height"] == pytest.approx(0.3)
    assert any("'colour'" in w for w in warnings) and any("'script'" in w for w in warnings)


def test_written_presets_read_back_equal(store, tmp_path):
    values = {"wave_height": 0.7, "wind_direction": (1.0, 0.0), "dull_color": (0.1, 0.2, 0.3)}
    path = store.write_preset(tmp_path / "new", "My  Pond!", values)
    assert path.name == "my_pond.json"
    preset, warnings = store.read_preset(path, user=True)
    assert warnings == [] and preset.name == "My  Pond!" and preset.id == "user:my_pond"
    for key, value in values.items():
        assert preset.values[key] == pytest.approx(value)


@pytest.mark.parametrize("name", ["", "   ", "!!!"])
def test_a_preset_needs_a_usable_name(store, tmp_path, name):
    with pytest.raises(store.PresetError):
        store.write_preset(tmp_path, name, {"wave_height": 0.1})


def test_clamp_values_never_refuses(schema):
    safe = schema.clamp_values(
        {
            "wave_length": float("nan"),
            "size": float("inf"),
            "wave_height": -float("inf"),
            "wind_direction": (0.0, 0.0),
            "specular_power": 0.0,
            "wind_force": -3.0,
        }
    )
    assert safe == {
        "wave_length": pytest.approx(0.1),
        "size": 100000.0,
        "wave_height": 0.0,
        "wind_direction": (0.0, 1.0),
        "specular_power": 1.0,
        "wind_force": 0.0,
    }


def test_depth_and_foam_presets_and_keys(store, tmp_path):
    presets = {p.id: p.values for p in store.load_dir(store.BUILTIN_DIR)[0]}
    lake = presets["lake"]
    assert lake["absorption"] == (0.0, 0.0, 0.0) and lake["foam_amount"] == 0.0, "the seeds' model"
    for name in ("clear_lake", "tropical_shallows", "murky_pond"):
        assert min(presets[name]["absorption"]) > 0, name
    for name in ("clear_lake", "tropical_shallows"):
        assert presets[name]["foam_amount"] > 0, name
    # Absorption is per metre: beyond 1 is allowed, up to the cap; the others are clamped as usual.
    path = _write(
        tmp_path,
        "deep",
        {
            "values": {
                "absorption": [99, 2.5, -1],
                "scatter_color": [2, 0.5, -1],
                "foam_width": 0,
                "foam_amount": 3,
            }
        },
    )
    values = store.read_preset(path)[0].values
    assert values["absorption"] == (50.0, 2.5, 0.0)
    assert values["scatter_color"] == (1.0, 0.5, 0.0)
    assert values["foam_width"] == pytest.approx(0.01) and values["foam_amount"] == 1.0
