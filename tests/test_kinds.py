"""One model of a water: what a water is and what it allows is decided in one place (`water/kind.py`),
and the operators, the API and the command line apply the same rules."""

import re

import bpy
import pytest

import harness


def _api():
    return harness.addon("api")


@pytest.fixture
def waters(scene):
    lake = _api().add_water(scene, name="Lake", size=8, resolution=8, see_surroundings=False).object
    ocean = (
        _api()
        .add_water(
            scene,
            preset="ocean",
            name="Ocean",
            size=8,
            resolution=8,
            see_surroundings=False,
            location=(20, 0, 0),
        )
        .object
    )
    sea = (
        _api()
        .add_water(
            scene,
            preset="open_sea",
            name="Sea",
            size=400,
            resolution=24,
            sea_wind_speed=3.0,
            see_surroundings=False,
            location=(0, 900, 0),
        )
        .object
    )
    return {"lake": lake, "ocean": ocean, "open_sea": sea}


def _activate(obj):
    for other in bpy.context.view_layer.objects.selected:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def test_each_water_is_told_from_its_data(waters, scene):
    for name, water in waters.items():
        assert _api().kind_of(water) == name
    cube = harness.add_cube(scene, (0, 0, 5), name="Cube")
    assert _api().kind_of(cube) is None


def test_the_operators_and_the_api_refuse_the_same_things(waters):
    table = harness.addon("water.kind").FEATURES
    for name, water in waters.items():
        _activate(water)
        allowed = table[name]
        assert bpy.ops.object.water_physical_caustics.poll() == ("physical_caustics" in allowed)
        assert bpy.ops.object.water_preset_apply.poll() == ("presets" in allowed)
        assert bpy.ops.object.water_sun_set.poll() == ("sun_choice" in allowed)
        assert bpy.ops.object.water_bump_set.poll() == ("bump_choice" in allowed)
        assert bpy.ops.object.water_surroundings_set.poll() and bpy.ops.object.water_remove.poll()
        if "presets" not in allowed:
            # The API used to write an ocean's shared keys where the operator refused: now both refuse.
            with pytest.raises(_api().PresetError, match="presets hold lake water values"):
                _api().apply_preset(water, "murky_pond")
        if "physical_caustics" not in allowed:
            with pytest.raises(_api().PhysicalCausticsError, match=water.name):
                _api().set_physical_caustics(water, True)
    with pytest.raises(_api().PresetError, match="builds its own mesh"):
        _api().apply_preset(waters["lake"], "open_sea")
    _activate(waters["lake"])
    with pytest.raises(RuntimeError, match="builds its own mesh"):
        bpy.ops.object.water_preset_apply(preset="ocean")


def test_a_value_enters_once_checked_and_clamped(scene):
    with pytest.raises(_api().PresetError, match="caustics"):
        _api().add_water(scene, size=8, resolution=8, caustics="2", see_surroundings=False)
    with pytest.raises(_api().PresetError, match="wave_height"):
        _api().add_water(scene, size=8, resolution=8, wave_height=True, see_surroundings=False)
    added = _api().add_water(scene, size=8, resolution=8, wave_height=99.0, see_surroundings=False)
    top = harness.addon("presets.schema").BY_KEY["wave_height"].max
    assert added.values["wave_height"] == top
    assert _api().read_values(added.object)["wave_height"] == pytest.approx(top)


def test_the_add_operator_has_a_property_for_every_preset_key_with_its_range(scene):
    schema = harness.addon("presets.schema")
    properties = bpy.ops.object.water_add.get_rna_type().properties
    for field in schema.FIELDS:
        prop = properties[field.key]
        assert prop.name == field.label and prop.description == field.tooltip
        if field.kind in ("float", "int"):
            assert (prop.hard_min, prop.hard_max) == pytest.approx((field.min, field.max))
            assert prop.default == pytest.approx(field.default)


# What floating offers, each with the API call that gives it and the operator that does.
_OFFERS = {
    "floating": (lambda api, boat, water: api.float_on_water(boat, water, wake=False), "water_float"),
    "wake": (lambda api, boat, water: api.add_wake_source(boat, water), "water_wake"),
    "keep_out": (lambda api, boat, water: api.keep_water_out(boat, water), "water_keep_out"),
}


def test_floating_a_wake_and_keep_out_follow_the_table_for_each_kind(waters, scene, monkeypatch):
    """Issue 41 point 2: whether a water takes a floating object, a wake or a keep-out is
    `kind.FEATURES`' answer, for the API and the operators' polls alike, in `kind.refusal`'s
    words: every kind takes them, and a kind the table is made to refuse is refused."""
    kind, api = harness.addon("water.kind"), _api()
    boat = harness.add_cube(scene, (0.0, 0.0, 0.0), size=0.6, name="Boat")
    for name, water in waters.items():
        _activate(boat)
        water.select_set(True)
        for feature, (_call, operator) in _OFFERS.items():
            assert feature in kind.FEATURES[name]
            assert getattr(bpy.ops.object, operator).poll(), (name, feature)
        for feature, (call, operator) in _OFFERS.items():
            with monkeypatch.context() as patch:
                patch.setitem(kind.FEATURES, name, kind.FEATURES[name] - {feature})
                why = kind.refusal(water, feature, subject=f"'{water.name}'")
                assert why is not None and "\n" not in why
                why = re.escape(why)
                with pytest.raises((api.FloatError, api.WakeError, api.KeepOutError), match=why):
                    call(api, boat, water)
                assert not getattr(bpy.ops.object, operator).poll(), (name, feature)
                with pytest.raises(RuntimeError, match=why):
                    getattr(bpy.ops.object, operator)()
                if feature == "wake":  # floating adds a wake unless told not to: refused whole
                    with pytest.raises(api.FloatError, match=why):
                        api.float_on_water(boat, water)
                    assert not boat.constraints, "nothing half made"
    lake = waters["lake"]
    for feature, (call, _operator) in _OFFERS.items():
        assert call(api, boat, lake), f"{feature} on the lake says what it did"


def test_the_water_an_object_acts_on_is_picked_by_one_rule(waters, scene):
    """Issue 41 point 2: the API and the operators pick the water by `floating.water_for` and say
    there is none in its one wording."""
    api, floating = _api(), harness.addon("water.boats.floating")
    stray = harness.add_cube(scene, (0.0, -90000.0, 0.0), size=0.6, name="Stray")  # past the sea
    why = re.escape(floating.no_water(stray))
    for call, error in (
        (api.float_on_water, api.FloatError),
        (api.add_wake_source, api.WakeError),
        (api.keep_water_out, api.KeepOutError),
    ):
        with pytest.raises(error, match=why):
            call(stray)
    _activate(stray)
    for operator in ("water_float", "water_wake", "water_keep_out"):
        with pytest.raises(RuntimeError, match=why):
            getattr(bpy.ops.object, operator)()
    boat = harness.add_cube(scene, (20.0, 0.0, 0.3), size=0.6, name="Boat")  # over the ocean
    assert floating.water_for(boat, scene, LookupError) == waters["ocean"]
    assert floating.water_for(boat, scene, LookupError, chosen=waters["lake"]) == waters["lake"]
    api.float_on_water(boat, waters["ocean"], wake=False)
    boat.location.x = 0.0  # over the lake now, still floating on the ocean
    bpy.context.view_layer.update()
    assert floating.water_for(boat, scene, LookupError) == waters["ocean"]
    assert floating.water_for(boat, scene, LookupError, floating_first=False) == waters["lake"]
