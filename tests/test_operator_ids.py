"""Issue 59 point 3: the operators answer to `object.water_<what>`, and the ids they had before
still work for saved keymaps and scripts (`operators/_aliases.py`), hidden from search: each
`object.water_surface_*` id (`RENAMED`) is the same operator, with the same properties, poll and
result; each id of one way of a switch (`FIXED`: `object.water_float_stop`, ...) is the switch
with that way fixed, polling as the old operator did and doing what `enable` set so does.
Marked `lts`: how Blender registers a copied class is what could differ between versions."""

import bpy
import pytest

import harness

pytestmark = pytest.mark.lts


def _renamed():
    return harness.addon("operators._aliases").RENAMED


def _fixed():
    return harness.addon("operators._aliases").FIXED


def _op(idname):
    module, name = idname.split(".")
    return getattr(getattr(bpy.ops, module), name)


def _properties(idname):
    """{identifier: (type, name, default)} of the operator's properties (dynamic enums: no default)."""
    found = {}
    for prop in _op(idname).get_rna_type().properties:
        if prop.identifier == "rna_type":
            continue
        if prop.type == "ENUM":
            default = None
        elif getattr(prop, "is_array", False):
            default = tuple(prop.default_array)
        else:
            default = prop.default
        found[prop.identifier] = (prop.type, prop.name, default)
    return found


def _polls():
    return {old: (_op(old).poll(), _op(new).poll()) for old, new in _renamed().items()}


def test_every_new_and_old_id_is_registered_with_the_same_properties(addon):
    operators = harness.addon("operators")
    new_ids = {cls.bl_idname for cls in operators.classes if "INTERNAL" not in getattr(cls, "bl_options", ())}
    assert set(_renamed().values()) <= new_ids
    assert not any(idname.startswith("object.water_surface_") for idname in new_ids)
    # Its own, those made from the preset schema and the mix-in's (AddObjectHelper).
    added = _properties("object.water_surface_add")
    assert {"preset", "size", "wave_height", "location", "align"} <= set(added)
    for old, new in _renamed().items():
        for idname in (old, new):
            assert hasattr(bpy.types, "OBJECT_OT_" + idname.split(".")[1]), idname
        assert _properties(old) == _properties(new), old
        assert _op(old).get_rna_type().name == _op(new).get_rna_type().name, "the keymap editor's label"
        options = set(_op(old).bl_options)
        assert options == set(_op(new).bl_options) | {"INTERNAL"}, old  # undo as the new one
        assert "INTERNAL" not in _op(new).bl_options


def test_old_ids_poll_as_the_new_ones_with_and_without_water(scene):
    polls = _polls()  # nothing active: only Add Water runs (and Remove Preset, with user presets)
    assert polls["object.water_surface_add"] == (True, True)
    assert all(old == new for old, new in polls.values()), polls
    water = harness.addon("api").add_water(scene, size=8, resolution=8, see_surroundings=False).object
    bpy.context.view_layer.objects.active = water
    polls = _polls()
    assert all(old == new for old, new in polls.values()), polls
    assert polls["object.water_surface_preset_apply"] == (True, True)
    assert polls["object.water_surface_repair"] == (False, False), "nothing to repair"
    with pytest.raises(RuntimeError, match="needs no repair"):
        bpy.ops.object.water_surface_repair()


def test_a_script_calling_the_old_ids_gets_the_same_water(scene):
    made = []
    for add, apply, x in (
        (bpy.ops.object.water_surface_add, bpy.ops.object.water_surface_preset_apply, 0.0),
        (bpy.ops.object.water_add, bpy.ops.object.water_preset_apply, 20.0),
    ):
        assert add(size=8, resolution=8, mirror_setup=False, location=(x, 0, 0)) == {"FINISHED"}
        assert apply(preset="clear_lake") == {"FINISHED"}
        made.append(bpy.context.active_object)
    read = harness.addon("water.apply").read_water
    assert read(made[0]) == read(made[1])
    assert bpy.ops.object.water_surface_sun_set(sun="NONE") == {"FINISHED"}
    assert bpy.ops.object.water_surface_bump_set(image="DEFAULT") == {"FINISHED"}
    assert bpy.ops.object.water_surface_preset_add(name="Old Id") == {"FINISHED"}
    presets = harness.addon("presets")
    assert "user:old_id" in [item[0] for item in presets.enum_items()]
    assert bpy.ops.object.water_surface_preset_remove(preset="user:old_id") == {"FINISHED"}
    assert "user:old_id" not in [item[0] for item in presets.enum_items()]


def test_a_saved_keymap_item_with_an_old_id_finds_its_operator(addon):
    keyconfigs = bpy.context.window_manager.keyconfigs
    config = keyconfigs.new("Water Ids Test")
    try:
        keymap = config.keymaps.new("3D View", space_type="VIEW_3D")
        for old, new in _renamed().items():
            item = keymap.keymap_items.new(old, "W", "PRESS", shift=True)
            assert item.idname == old
            assert item.name == _op(new).get_rna_type().name, old  # resolved: an unknown id has no name
            assert item.properties.bl_rna.identifier == "OBJECT_OT_" + old.split(".")[1], old
        # What a saved item holds is the operator's properties, read and set as the new id's.
        item = keymap.keymap_items.new("object.water_surface_add", "W", "PRESS", ctrl=True)
        item.properties.size = 12.0
        assert item.properties.size == 12.0 and item.properties.preset
    finally:
        keyconfigs.remove(config)


def test_every_fixed_old_id_is_its_switch_with_that_way_fixed_and_hidden(addon):
    for old, (new, values, label) in _fixed().items():
        assert hasattr(bpy.types, "OBJECT_OT_" + old.split(".")[1]), old
        assert values == {"enable": values["enable"]}, "a switch's way is all an old id fixes"
        old_properties, new_properties = _properties(old), _properties(new)
        assert new_properties["enable"][0] == "BOOLEAN", new
        assert new_properties["enable"][2] is True, "a switch is on by default"
        # Every property the new id takes (the old ones' among them), the way fixed as its default.
        assert old_properties == {
            **new_properties,
            "enable": (*new_properties["enable"][:2], values["enable"]),
        }
        rna = _op(old).get_rna_type()
        assert (
            rna.properties["enable"].is_hidden and not _op(new).get_rna_type().properties["enable"].is_hidden
        )
        assert rna.name == label, "the keymap editor's label: the old operator's"
        if not values["enable"]:  # its description says what it does: the off way
            assert rna.description and rna.description != _op(new).get_rna_type().description, old
        assert set(_op(old).bl_options) == set(_op(new).bl_options) | {"INTERNAL"}, old  # undo as the new one
    # The ids every old way had: what the panel's buttons called before one switch each.
    assert {new for new, _values, _label in _fixed().values()} == {
        "object.water_float",
        "object.water_keep_out",
        "object.water_wake",
    }


def _water_and_boat(scene):
    water = harness.addon("api").add_water(scene, name="Lake", size=8, resolution=8, see_surroundings=False)
    boat = harness.add_cube(scene, (0.0, 0.0, 0.2), size=0.6, name="Boat")
    for obj in bpy.context.view_layer.objects.selected:
        obj.select_set(False)
    boat.select_set(True)
    bpy.context.view_layer.objects.active = boat
    return water.object, boat


def _state(boat):
    """(floats, water kept out of it, leaves a wake): what the switches of a boat change."""
    floating = harness.addon("water.boats.floating")
    wake = harness.addon("water.boats.wake")
    keep_out = harness.addon("water.boats.keep_out")
    return floating.is_floating(boat), bool(keep_out.kept_out_of(boat)), bool(wake.modifiers_of(boat))


def test_fixed_old_ids_poll_as_their_way_and_the_switch_refuses_the_way_that_may_not_run(scene):
    water, boat = _water_and_boat(scene)
    polls = {old: _op(old).poll() for old in _fixed()}
    assert polls == {
        "object.water_float_stop": False,
        "object.water_let_in": False,
        "object.water_wake_add": True,
        "object.water_wake_remove": False,
    }, "nothing on yet: only adding a wake may run"
    with pytest.raises(RuntimeError, match="No selected object floats on water"):
        bpy.ops.object.water_float_stop()
    with pytest.raises(RuntimeError, match="No water is kept out of a selected object"):
        bpy.ops.object.water_let_in()
    with pytest.raises(RuntimeError, match="No selected object leaves a wake"):
        bpy.ops.object.water_wake_remove()
    # The switch polls true where either way may run, and refuses the other way in its poll's words.
    for new, why in (
        ("object.water_float", "No selected object floats on water"),
        ("object.water_keep_out", "No water is kept out of a selected object"),
        ("object.water_wake", "No selected object leaves a wake"),
    ):
        assert _op(new).poll(), new
        with pytest.raises(RuntimeError, match=why):
            _op(new)(enable=False)
    assert _state(boat) == (False, False, False), "nothing done by a refusal"

    assert bpy.ops.object.water_wake(strength=0.5) == {"FINISHED"}
    assert bpy.ops.object.water_wake_remove.poll() and bpy.ops.object.water_wake.poll()
    # A second water selected: adding is refused, taking off still may run (the old ids' polls).
    other = harness.addon("api").add_water(scene, name="Pond", size=4, resolution=8, location=(0, 9, 0))
    with bpy.context.temp_override(active_object=boat, selected_objects=[boat, water, other.object]):
        assert not bpy.ops.object.water_wake_add.poll()
        assert bpy.ops.object.water_wake_remove.poll()
        assert bpy.ops.object.water_wake.poll(), "its off way may run"
        with pytest.raises(RuntimeError, match="Select one water at most"):
            bpy.ops.object.water_wake(enable=True)
    assert _state(boat) == (False, False, True)


def test_a_script_calling_the_fixed_old_ids_does_what_the_switch_does(scene):
    _water, boat = _water_and_boat(scene)
    wake = harness.addon("water.boats.wake")
    waves = harness.addon("water.waves")
    # Each way, by the old id (its old properties) and by the switch with `enable`: the same state.
    for on, off in (
        ((bpy.ops.object.water_wake_add, {"strength": 0.5}), (bpy.ops.object.water_wake_remove, {})),
        ((bpy.ops.object.water_wake, {"strength": 0.5}), (bpy.ops.object.water_wake, {"enable": False})),
    ):
        assert on[0](**on[1]) == {"FINISHED"}
        (modifier,) = wake.modifiers_of(boat)
        assert waves.get_wave_input(modifier, "Strength") == pytest.approx(0.5)
        assert off[0](**off[1]) == {"FINISHED"}
        assert _state(boat) == (False, False, False)
    for on, off in (
        ((bpy.ops.object.water_float, {"wake": False}), bpy.ops.object.water_float_stop),
        ((bpy.ops.object.water_keep_out, {}), bpy.ops.object.water_let_in),
    ):
        assert on[0](**on[1]) == {"FINISHED"}
        done = _state(boat)
        assert any(done)
        assert off() == {"FINISHED"}
        assert _state(boat) == (False, False, False)
        assert on[0](**on[1]) == {"FINISHED"} and _state(boat) == done
        assert on[0](enable=False) == {"FINISHED"}
        assert _state(boat) == (False, False, False)
    # The way is fixed: the hidden `enable` set otherwise changes nothing.
    assert bpy.ops.object.water_wake_add(enable=False) == {"FINISHED"}
    assert _state(boat) == (False, False, True)
    assert bpy.ops.object.water_wake_remove(enable=True) == {"FINISHED"}
    assert _state(boat) == (False, False, False)
    # What Float on Water takes, the old Stop Floating takes too (it took nothing): no error.
    assert bpy.ops.object.water_float(wake=False) == {"FINISHED"}
    assert bpy.ops.object.water_float_stop(wake=True, tilt_damping=0.5) == {"FINISHED"}
    assert _state(boat) == (False, False, False)


def test_a_saved_keymap_item_with_a_fixed_old_id_finds_its_switch_with_its_way(addon):
    keyconfigs = bpy.context.window_manager.keyconfigs
    config = keyconfigs.new("Water Fixed Ids Test")
    try:
        keymap = config.keymaps.new("3D View", space_type="VIEW_3D")
        for old, (_new, values, label) in _fixed().items():
            item = keymap.keymap_items.new(old, "W", "PRESS", alt=True)
            assert item.idname == old
            assert item.name == label, old  # resolved: an unknown id has no name
            assert item.properties.bl_rna.identifier == "OBJECT_OT_" + old.split(".")[1], old
            assert item.properties.enable == values["enable"], old
        item = keymap.keymap_items.new("object.water_wake_add", "W", "PRESS", ctrl=True, alt=True)
        item.properties.strength = 2.0  # what the old Add Wake took, saved with the item
        assert item.properties.strength == 2.0
    finally:
        keyconfigs.remove(config)
