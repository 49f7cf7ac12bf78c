"""Issue 57 point 2: one path per job. Add Water (API and operator), the preset operator,
`apply_preset`, `write_values`, `set_underwater`, `set_light_shafts` and the command line all set a
water's values through `water/apply.py`: the same preset gives the same water from each, compared
as data (its values, its shader's variant, its underwater body and its caustic light);
`read_values` returns every key they apply, so a saved preset restores the water; NaN, wrong
types and a scene given by name are refused before anything changes; the API's errors share one
base and name what they are about. Data only: what the caustic light and the body render is
test_caustic_light.py's and test_underwater_fog.py's."""

import math

import bpy
import pytest

import harness

DEFAULT_SAMPLES = 64  # EEVEE's own volume samples in a new scene


def _api():
    return harness.addon("api")


def _underwater():
    return harness.addon("water.underwater")


def _activate(obj):
    for other in bpy.context.view_layer.objects.selected:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def _rounded(value):
    if isinstance(value, float):
        return round(value, 5)
    if isinstance(value, tuple):
        return tuple(round(v, 5) for v in value)
    return value


def _state(water):
    """What makes two waters the same, as data: every value `read_values` gives, the variant of its
    shader (the parts built in), its underwater body, its caustic light and its light shafts."""
    underwater = _underwater()
    node = harness.addon("nodes.material").water_node(water.active_material)
    return {
        "values": {key: _rounded(value) for key, value in _api().read_values(water).items()},
        "shader": node.node_tree.name,
        "body": underwater.find(water) is not None,
        "caustic light": underwater.find(water, underwater.LIGHT_ROLE) is not None,
        "light shafts": round(underwater.light_shafts(water), 5),
    }


def _lake(scene, name, x, **values):
    """A default lake, small and alone (no mirror, no surroundings), at x."""
    options = {"size": 4.0, "mirror_setup": False, "see_surroundings": False}
    return _api().add_water(scene, name=name, location=(x, 0.0, 0.0), **{**options, **values}).object


def _preset_values(preset):
    return dict(harness.addon("presets").get(preset).values)


def test_a_preset_gives_the_same_water_from_every_entry_point(scene):
    """clear_lake (Caustics 1) from Add Water, the Add operator, `apply_preset`, `write_values`
    and the preset operator: the same values, shader, body and caustic light (the preset operator
    and `apply_preset` used to add no caustic light)."""
    added = _lake(scene, "Added", 0.0, preset="clear_lake")
    expected = _state(added)
    assert expected["caustic light"] and expected["body"], "clear_lake has caustics: the light is made"
    assert expected["shader"] == "Water Surface + Depth + Foam + Caustics"

    bpy.context.scene.cursor.location = (10.0, 0.0, 0.0)
    assert bpy.ops.object.water_add(
        preset="clear_lake", size=4.0, mirror_setup=False, see_surroundings=False
    ) == {"FINISHED"}
    operator_added = bpy.context.active_object

    by_api = _lake(scene, "By API", 20.0)
    _api().apply_preset(by_api, "clear_lake")
    written = _lake(scene, "Written", 30.0)
    _api().write_values(written, _preset_values("clear_lake"))
    by_operator = _lake(scene, "By Operator", 40.0)
    _activate(by_operator)
    assert bpy.ops.object.water_preset_apply(preset="clear_lake") == {"FINISHED"}

    for water in (operator_added, by_api, written, by_operator):
        assert _state(water) == expected, water.name


def test_a_lake_preset_on_a_clear_lake_water_takes_its_caustic_light_away(scene):
    """`lake` sets Caustics to 0: the shader's caustics and the caustic light go, from the API
    and from the operator alike (the light used to stay)."""
    for x, how in ((0.0, "api"), (10.0, "operator")):
        water = _lake(scene, f"Clear {how}", x, preset="clear_lake")
        assert _state(water)["caustic light"]
        if how == "api":
            _api().apply_preset(water, "lake")
        else:
            _activate(water)
            assert bpy.ops.object.water_preset_apply(preset="lake") == {"FINISHED"}
        state = _state(water)
        assert state["values"]["caustics"] == 0.0
        assert not state["caustic light"], how
        assert "Caustics" not in state["shader"]
        assert state == _state(_lake(scene, f"Lake {how}", x + 100.0)), "as a lake added so"


def test_underwater_and_light_shafts_act_through_write_values_and_presets(scene):
    """The preset keys `underwater` and `light_shafts` act wherever values are written (they used
    to act only when adding): off takes the body and its volume samples away, on brings them back
    with the shafts asked for; a preset without them puts the reference's back."""
    water = _lake(scene, "Pond", 0.0, preset="clear_lake")
    assert scene.eevee.volumetric_samples == 256
    _api().write_values(water, {"underwater": False})
    state = _state(water)
    assert not state["body"] and not state["caustic light"], "no body: no caustic light under it"
    assert state["values"]["underwater"] is False and state["values"]["light_shafts"] == 0.0
    assert scene.eevee.volumetric_samples == DEFAULT_SAMPLES, "the samples it raised go back"

    _api().write_values(water, {"underwater": True, "light_shafts": 0.4})
    state = _state(water)
    assert state["body"] and state["caustic light"] and state["light shafts"] == pytest.approx(0.4)
    assert state["values"]["underwater"] is True and state["values"]["light_shafts"] == pytest.approx(0.4)
    assert scene.eevee.volumetric_samples == 256

    _api().write_values(water, {"light_shafts": 7.0})  # clamped
    assert _state(water)["light shafts"] == 1.0
    _api().apply_preset(water, "clear_lake")  # every key of the preset: the reference's 0 shafts
    assert _state(water) == _state(_lake(scene, "Fresh", 20.0, preset="clear_lake"))

    _api().set_underwater(water, False)
    with pytest.raises(_api().UnderwaterError, match="Underwater is off"):
        _api().write_values(water, {"light_shafts": 0.5, "caustics": 2.0})
    assert _state(water)["values"]["caustics"] == 1.0, "refused before anything changed"
    with pytest.raises(_api().UnderwaterError, match="Underwater is off"):
        _api().add_water(scene, underwater=False, light_shafts=0.5)
    assert "Water" not in bpy.data.objects, "refused before anything was made"


def test_read_values_has_every_key_and_a_saved_preset_restores_the_water(scene):
    schema = harness.addon("presets.schema")
    presets = harness.addon("presets")
    water = _lake(scene, "Mine", 0.0, preset="murky_pond", caustics=1.3, light_shafts=0.25)
    values = _api().read_values(water)
    lake_keys = {field.key for field in schema.SHADER_FIELDS} | {"underwater", "light_shafts"}
    assert set(values) == lake_keys
    assert values["light_shafts"] == pytest.approx(0.25) and values["underwater"] is True

    _activate(water)
    try:
        assert bpy.ops.object.water_preset_add(name="One Path") == {"FINISHED"}
        saved = presets.get("user:one_path").values
        assert saved["light_shafts"] == pytest.approx(0.25) and saved["underwater"] is True
        other = _lake(scene, "Other", 10.0)
        _api().apply_preset(other, "user:one_path")
        assert _state(other) == _state(water)

        _api().set_underwater(water, False)
        assert bpy.ops.object.water_preset_add(name="One Path", replace=True) == {"FINISHED"}
        _activate(other)
        assert bpy.ops.object.water_preset_apply(preset="user:one_path") == {"FINISHED"}
        assert _state(other) == _state(water) and not _state(other)["body"]
    finally:
        presets.remove_user_preset("user:one_path")


def test_nan_wrong_types_and_a_scene_by_name_are_refused_before_anything_changes(scene):
    water = _lake(scene, "Kept", 0.0, preset="clear_lake", light_shafts=0.2)
    before = _state(water)
    names = {o.name for o in bpy.data.objects}
    refused = [
        (lambda: _api().set_light_shafts(water, math.nan), "'light_shafts' must be finite"),
        (lambda: _api().set_light_shafts(water, math.inf), "'light_shafts' must be finite"),
        (lambda: _api().set_light_shafts(water, "0.5"), "'light_shafts' must be a number"),
        (lambda: _api().write_values(water, {"caustics": 0.0, "wave_length": math.nan}), "'wave_length'"),
        (lambda: _api().write_values(water, {"caustics": 0.0, "absorption": (1, math.nan, 1)}), "absorption"),
        (lambda: _api().write_values(water, {"caustics": 0.0, "underwater": "no"}), "'underwater'"),
        (lambda: _api().set_underwater(water, 0), "'underwater' must be true or false"),
        (lambda: _api().add_water(scene, wave_height=math.nan), "'wave_height' must be finite"),
    ]
    for call, words in refused:
        with pytest.raises(_api().PresetError, match=words):
            call()
        assert _state(water) == before, words
    with pytest.raises(_api().WrongTypeError, match="scene must be a Scene, not str"):
        _api().set_underwater(water, False, scene=scene.name)
    assert _state(water) == before and scene.eevee.volumetric_samples == 256, "the body and samples kept"
    with pytest.raises(RuntimeError, match="'wave_height' must be finite"):
        bpy.ops.object.water_add(wave_height=math.nan)
    assert {o.name for o in bpy.data.objects} == names, "nothing was added"


def test_the_command_line_adds_the_water_the_api_adds(scene, tmp_path):
    harness.add_camera(scene, (0, -6, 3), (0, 0, 0))
    shot = tmp_path / "shot.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(shot))
    target = tmp_path / "water.blend"
    options = ["--preset", "clear_lake", "--size", "4", "--no-mirror", "--no-surroundings"]
    assert harness.addon("cli").main(["add", str(shot), str(target), *options, "--light-shafts", "0.3"]) == 0
    bpy.ops.wm.open_mainfile(filepath=str(target))
    by_cli = _state(bpy.data.objects["Water"])
    assert by_cli["values"]["light_shafts"] == pytest.approx(0.3) and by_cli["caustic light"]
    same = _lake(bpy.context.scene, "By API", 10.0, preset="clear_lake", light_shafts=0.3)
    assert by_cli == _state(same)


def test_every_error_the_api_exports_shares_one_base_and_names_what_it_is_about(scene):
    api = _api()
    errors = [getattr(api, name) for name in api.__all__ if name.endswith("Error")]
    assert len(errors) >= 18, [e.__name__ for e in errors]
    for error in errors:
        assert issubclass(error, api.WaterError), error.__name__
    # Their builtin bases stay, so `except ValueError` code still catches them.
    assert issubclass(api.PresetError, ValueError) and issubclass(api.AddWaterError, RuntimeError)
    assert issubclass(api.FileJobError, RuntimeError) and issubclass(api.NotEditableError, ValueError)
    assert issubclass(api.NotWaterError, ValueError) and issubclass(api.WrongTypeError, TypeError)

    cube = harness.add_cube(scene, (0, 0, 5), name="Cube")
    for call in (
        lambda: api.set_underwater(cube, True),
        lambda: api.set_light_shafts(cube, 0.5),
        lambda: api.write_values(cube, {"caustics": 1.0}),
        lambda: api.read_values(cube),
        lambda: api.switch_part(cube, "foam"),
        lambda: api.add_waves(cube),
        lambda: api.apply_preset(cube, "lake"),
    ):
        with pytest.raises(api.NotWaterError, match="'Cube' is not water") as raised:
            call()
        assert not isinstance(raised.value, api.MirrorSetupError), "not the mirror's problem"

    water = _lake(scene, "Broken", 0.0)
    with pytest.raises(api.KindError, match="no part 'fog' to switch on the lake"):
        api.switch_part(water, "fog")
    with pytest.raises(api.NoCameraError, match="the scene has no camera"):
        api.extend_camera_clip(water)
    tree = harness.addon("nodes.material").water_node(water.active_material).node_tree
    tree.interface.remove(next(i for i in tree.interface.items_tree if i.name == "Wave Length"))
    with pytest.raises(api.NeedsRepairError, match="Wave Length"):
        api.write_values(water, {"caustics": 1.0})
    assert _underwater().find(water, _underwater().LIGHT_ROLE) is None, "nothing changed"
