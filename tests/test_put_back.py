"""Switches put back only what they changed, only when nobody else needs it; nothing is left behind.

Physical Caustics, the mirror set-up (engine, ray tracing, world) and light linking, each with a
user's change in between and with two waters; a failed add compared setting by setting; Remove
Water and an ordinary delete, saved and reopened.
"""

import bpy
import pytest

import harness


def _api():
    return harness.addon("api")


def _sun(scene, name="Sun"):
    light = bpy.data.lights.new(name, "SUN")
    sun = bpy.data.objects.new(name, light)
    scene.collection.objects.link(sun)
    sun.rotation_euler = (0.6, 0.2, 0.8)
    return sun


def _plain_settings(struct):
    """Every writable plain setting of an RNA struct, read independently of the add-on."""
    found = {}
    for prop in struct.bl_rna.properties:
        if prop.type not in {"BOOLEAN", "INT", "FLOAT", "STRING", "ENUM"} or prop.is_readonly:
            continue
        value = getattr(struct, prop.identifier)
        found[prop.identifier] = tuple(value) if getattr(prop, "is_array", False) else value
    return found


def _scene_settings(scene):
    structs = {
        "render": scene.render,
        "eevee": scene.eevee,
        "ray tracing": scene.eevee.ray_tracing_options,
        "cycles": scene.cycles,
        "view": scene.view_settings,
    }
    settings = {name: _plain_settings(struct) for name, struct in structs.items()}
    settings["world"] = scene.world.name if scene.world else None
    settings["scene keys"] = sorted(scene.keys())
    return settings


@pytest.fixture
def pool(scene):
    """A sun and a bed under two lakes side by side, Cycles settings of the user's own."""
    sun = _sun(scene)
    bed = harness.add_cube(scene, (0.0, 0.0, -3.0), size=4.0, name="Bed")
    bed.scale = (8.0, 2.0, 1.0)
    cycles = scene.cycles
    cycles.transmission_bounces, cycles.transparent_max_bounces, cycles.max_bounces = 3, 4, 5
    cycles.caustics_refractive = False
    a = _api().add_water(scene, name="A", size=8, resolution=8, location=(-5.0, 0.0, 0.0)).object
    b = _api().add_water(scene, name="B", size=8, resolution=8, location=(5.0, 0.0, 0.0)).object
    return scene, sun, bed, a, b


def test_physical_caustics_off_keeps_a_setting_the_user_changed_since(pool):
    scene, sun, bed, a, _b = pool
    _api().set_physical_caustics(a, True, scene)
    assert scene.cycles.transmission_bounces == 8 and scene.cycles.max_bounces == 8
    scene.cycles.transmission_bounces = 20  # the user's own change
    changes = _api().set_physical_caustics(a, False, scene)
    assert scene.cycles.transmission_bounces == 20
    assert scene.cycles.max_bounces == 5 and scene.cycles.transparent_max_bounces == 4
    assert not scene.cycles.caustics_refractive
    assert not sun.data.cycles.is_caustics_light and not bed.cycles.is_caustics_receiver
    assert any("left at 20" in change for change in changes)


def test_switching_one_water_off_never_breaks_another(pool):
    scene, sun, bed, a, b = pool
    _api().set_physical_caustics(a, True, scene)
    _api().set_physical_caustics(b, True, scene)
    _api().set_physical_caustics(a, False, scene)
    physical = harness.addon("water.physical_caustics")
    assert physical.is_on(b) and not physical.is_on(a)
    assert scene.cycles.transmission_bounces == 8 and scene.cycles.caustics_refractive
    assert sun.data.cycles.is_caustics_light and bed.cycles.is_caustics_receiver
    assert not a.cycles.is_caustics_caster and b.cycles.is_caustics_caster
    _api().set_physical_caustics(b, False, scene)
    assert (scene.cycles.transmission_bounces, scene.cycles.max_bounces) == (3, 5)
    assert not scene.cycles.caustics_refractive and not sun.data.cycles.is_caustics_light
    assert not bed.cycles.is_caustics_receiver


def test_remove_water_puts_the_mirror_set_up_back_once_no_water_needs_it(scene):
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.eevee.use_raytracing = False
    scene.world = None
    sun = _sun(scene)
    a = _api().add_water(scene, name="A", size=8, resolution=8, see_surroundings=False).object
    b = _api().add_water(scene, name="B", size=8, resolution=8, see_surroundings=False).object
    assert scene.render.engine != "BLENDER_WORKBENCH" and scene.eevee.use_raytracing
    sky = scene.world
    assert sky is not None
    receivers = sun.light_linking.receiver_collection
    assert {a.name, b.name} <= {o.name for o in receivers.objects}

    _api().remove_water(a, scene)
    assert "A" not in bpy.data.objects and "A Mirror" not in bpy.data.objects
    assert scene.render.engine != "BLENDER_WORKBENCH" and scene.eevee.use_raytracing  # B needs them
    assert scene.world == sky and sun.light_linking.receiver_collection == receivers
    scene.eevee.ray_tracing_method = "PROBE"  # the user's own change in between

    _api().remove_water(b, scene)
    assert scene.render.engine == "BLENDER_WORKBENCH" and not scene.eevee.use_raytracing
    assert scene.eevee.ray_tracing_method == "PROBE"
    assert scene.world is None and "Sky" not in bpy.data.worlds
    assert sun.light_linking.receiver_collection is None
    assert not [c for c in bpy.data.collections if c.get("water_surface_version") is not None]


def test_a_users_own_light_linking_stays_when_water_is_removed(scene):
    sun = _sun(scene)
    mine = bpy.data.collections.new("My Receivers")
    cube = harness.add_cube(scene, (9.0, 0.0, 1.0), name="Lit")
    mine.objects.link(cube)
    sun.light_linking.receiver_collection = mine
    water = _api().add_water(scene, size=8, resolution=8, see_surroundings=False).object
    assert water.name in mine.objects
    _api().remove_water(water, scene)
    assert sun.light_linking.receiver_collection == mine
    assert [o.name for o in mine.objects] == ["Lit"]


def test_a_failed_add_leaves_every_scene_setting_as_it_was(scene, monkeypatch):
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.eevee.use_raytracing = False
    scene.eevee.ray_tracing_options.resolution_scale = "2"
    scene.world = None
    _sun(scene)
    harness.add_cube(scene, (0.0, 0.0, -2.0), size=2.0, name="Bed")
    before = _scene_settings(scene)
    names = {kind: sorted(b.name for b in getattr(bpy.data, kind)) for kind in ("objects", "collections")}

    def fail(*_args):
        raise RuntimeError("the last step failed")

    # The last step of the set-up fails, after the engine, ray tracing and the world were set.
    monkeypatch.setattr(harness.addon("water.sun_link"), "exclude_water", fail)
    with pytest.raises(_api().AddWaterError, match="the last step failed"):
        _api().add_water(scene, size=8, resolution=8)
    after = _scene_settings(scene)
    differ = {
        (group, key)
        for group in before
        for key in (before[group] if isinstance(before[group], dict) else [None])
        if (before[group].get(key) if key else before[group])
        != (after[group].get(key) if key else after[group])
    }
    assert differ == set()
    assert names == {kind: sorted(b.name for b in getattr(bpy.data, kind)) for kind in names}


def _everything(scene, preset):
    """A water of `preset` with every feature the panel allows on it, a bed, a post, a boat
    floating on it that reached below it when it was added, and a sun."""
    sun = _sun(scene)
    bed = harness.add_cube(scene, (0.0, 0.0, -3.0), size=4.0, name="Bed")
    post = harness.add_cube(scene, (2.0, 2.0, 0.0), size=0.5, name="Post")
    boat = harness.add_cube(scene, (-1.0, 0.5, 0.0), size=1.0, name="Boat")
    extra = {"sea_wind_speed": 4.0} if preset == "open_sea" else {"waves": True}
    water = _api().add_water(scene, preset=preset, size=12, resolution=16, **extra).object
    if preset == "lake":
        _api().set_physical_caustics(water, True, scene)
    _api().float_on_water(boat, water)
    return water, sun, (bed, post, boat)


def _marked_leftovers():
    found = []
    for kind in ("objects", "meshes", "materials", "node_groups", "images", "worlds", "collections"):
        for block in getattr(bpy.data, kind):
            if any(key.startswith("water_surface") for key in block.keys()):
                found.append(f"{kind}:{block.name}")
    for kind in ("lightprobes", "lights", "scenes"):
        for block in getattr(bpy.data, kind):
            if any(key.startswith("water_surface") for key in block.keys()):
                found.append(f"{kind}:{block.name}")
    return found


@pytest.mark.parametrize("preset", ["lake", "ocean", "open_sea"])
@pytest.mark.parametrize("how", ["remove_water", "delete"])
def test_a_removed_or_deleted_water_leaves_nothing_in_the_saved_file(scene, tmp_path, preset, how):
    water, sun, objects = _everything(scene, preset)
    sun_before = (tuple(sun.rotation_euler), sun.data.energy, False)  # the add-on made it a caustics light
    assert _marked_leftovers()  # the water's own data is marked while it is there
    if how == "remove_water":
        _api().remove_water(water, scene)
    else:
        for obj in scene.objects:
            obj.select_set(obj == water)
        bpy.context.view_layer.objects.active = water
        bpy.ops.object.delete()
    path = tmp_path / "after.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    bpy.ops.wm.open_mainfile(filepath=str(path))
    leftovers = _marked_leftovers()
    assert leftovers == [], "; ".join(leftovers)
    assert sorted(o.name for o in bpy.data.objects) == ["Bed", "Boat", "Post", "Sun"]
    sun = bpy.data.objects["Sun"]
    assert not bpy.data.objects["Boat"].constraints
    assert (tuple(sun.rotation_euler), sun.data.energy, sun.data.cycles.is_caustics_light) == sun_before
    for name in ("Bed", "Post", "Boat"):
        assert not bpy.data.objects[name].cycles.is_caustics_receiver, name
    assert sun.light_linking.receiver_collection is None


def test_light_linking_the_add_on_made_stays_while_it_holds_the_users_own_links(scene):
    sun = _sun(scene)
    a = _api().add_water(scene, name="A", size=8, resolution=8, see_surroundings=False).object
    b = _api().add_water(scene, name="B", size=8, resolution=8, see_surroundings=False).object
    receivers = sun.light_linking.receiver_collection
    assert receivers is not None and receivers.get("water_surface_version") is not None
    lamp_post = harness.add_cube(scene, (9.0, 0.0, 1.0), name="Lamp Post")
    receivers.objects.link(lamp_post)  # the user's own change in between
    _api().remove_water(a, scene)
    assert sun.light_linking.receiver_collection == receivers
    assert sorted(o.name for o in receivers.objects) == ["B", "Lamp Post"]
    _api().remove_water(b, scene)
    assert sun.light_linking.receiver_collection == receivers  # it holds the user's link: kept
    assert [o.name for o in receivers.objects] == ["Lamp Post"]


def test_an_object_floated_after_physical_caustics_is_no_receiver_any_more(pool):
    scene, _sun, bed, a, _b = pool
    buoy = harness.add_cube(scene, (-5.0, 0.5, -0.2), size=0.6, name="Buoy")
    harness.addon("api").set_surroundings(a, scene=scene)  # gathers the buoy too: it reaches below
    _api().set_physical_caustics(a, True, scene=scene)
    assert buoy.cycles.is_caustics_receiver and bed.cycles.is_caustics_receiver
    changes = _api().float_on_water(buoy, a)
    assert not buoy.cycles.is_caustics_receiver, changes
    assert any("receiver 'Buoy'" in change for change in changes)
    assert bed.cycles.is_caustics_receiver, "the bed still receives"
    _api().set_physical_caustics(a, False, scene=scene)
    assert not bed.cycles.is_caustics_receiver and not buoy.cycles.is_caustics_receiver


def test_a_renamed_water_still_holds_what_it_changed(pool):
    scene, _sun, _bed, a, b = pool
    _api().set_physical_caustics(a, True, scene=scene)
    _api().set_physical_caustics(b, True, scene=scene)
    a.name = "Renamed A"
    # B lets go first: A, renamed, still needs the raised bounces and refractive caustics.
    _api().set_physical_caustics(b, False, scene=scene)
    assert scene.cycles.transmission_bounces == 8 and scene.cycles.caustics_refractive
    # Saving prunes holders whose water is gone: the renamed one is not gone.
    harness.addon("water.removal").remove_leftovers()
    assert scene.cycles.transmission_bounces == 8
    _api().set_physical_caustics(a, False, scene=scene)
    assert scene.cycles.transmission_bounces == 3 and not scene.cycles.caustics_refractive


def test_a_water_deleted_the_ordinary_way_leaves_the_users_receivers(scene, tmp_path):
    sun = _sun(scene)
    mine = bpy.data.collections.new("My Receivers")
    mine.objects.link(harness.add_cube(scene, (9.0, 0.0, 1.0), name="Lit"))
    sun.light_linking.receiver_collection = mine
    water = _api().add_water(scene, size=8, resolution=8, see_surroundings=False).object
    assert water.name in mine.objects
    name = water.name
    bpy.ops.object.select_all(action="DESELECT")
    water.select_set(True)
    bpy.context.view_layer.objects.active = water
    assert bpy.ops.object.delete() == {"FINISHED"}
    bpy.ops.wm.save_as_mainfile(filepath=str(tmp_path / "deleted.blend"))  # save runs the clean-up
    assert name not in bpy.data.objects and [o.name for o in mine.objects] == ["Lit"]
    assert sun.light_linking.receiver_collection == mine
