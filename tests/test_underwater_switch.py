"""Issue 40 point 3: the `Underwater` switch, one word for the preset, the panel, the operator, the
API and the command line. Off, the water has no underwater body and the scene's EEVEE volume
samples are the user's own; on, both come back; Remove Water and a second water put back only what
is theirs to put back. Data only: what the body does to a render is test_underwater_fog.py's.
"""

import bpy
import pytest

import harness

DEFAULT_SAMPLES = 64  # EEVEE's own volume samples in a new scene


def _api():
    return harness.addon("api")


def _body(water):
    return harness.addon("water.underwater").find(water)


def _samples(scene):
    return scene.eevee.volumetric_samples


def _activate(obj):
    for other in bpy.context.view_layer.objects.selected:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


@pytest.mark.lts
def test_a_water_added_with_underwater_off_has_no_body_and_leaves_the_volume_samples(addon, scene):
    assert _samples(scene) == DEFAULT_SAMPLES
    off = _api().add_water(scene, preset="clear_lake", size=10.0, underwater=False, name="Off").object
    assert _body(off) is None
    assert not [o for o in bpy.data.objects if o.name.startswith("Off Underwater")]
    assert _samples(scene) == DEFAULT_SAMPLES, "the user's volume samples are left alone"
    assert scene.eevee.volumetric_tile_size == "8"
    on = _api().add_water(scene, preset="clear_lake", size=10.0, name="On", location=(30, 0, 0)).object
    assert _body(on) is not None and _samples(scene) == 256
    assert scene.eevee.volumetric_tile_size == "4", "froxels no wider than 4 pixels for the waterline"


def test_the_switch_takes_the_body_away_and_brings_it_back_with_the_samples(addon, scene):
    scene.eevee.volumetric_samples = 96  # the user's own, raised to 256 and put back to 96
    water = _api().add_water(scene, preset="murky_pond", size=10.0, name="Pond").object
    assert _body(water) is not None and _samples(scene) == 256
    scene.eevee.volumetric_tile_size = "2"  # finer than the add-on needs: left alone
    changes = _api().set_underwater(water, False)
    assert changes and _body(water) is None
    assert scene.eevee.volumetric_tile_size == "2"
    assert "Pond Underwater" not in bpy.data.objects and "Pond Underwater" not in bpy.data.materials
    assert _samples(scene) == 96
    assert _api().set_underwater(water, False) == [], "off twice: nothing to do"
    changes = _api().set_underwater(water, True)
    assert _body(water) is not None and _samples(scene) == 256
    assert _api().set_underwater(water, True) == [], "on twice: nothing to do"
    _api().remove_water(water)
    assert _samples(scene) == 96
    assert not [o for o in bpy.data.objects if o.name.startswith("Pond")]


def test_a_second_water_keeps_the_samples_the_first_one_lets_go(addon, scene):
    first = _api().add_water(scene, preset="clear_lake", size=10.0, name="First").object
    second = (
        _api().add_water(scene, preset="clear_lake", size=10.0, name="Second", location=(30, 0, 0)).object
    )
    _api().set_underwater(first, False)
    assert _body(first) is None and _body(second) is not None
    assert _samples(scene) == 256, "the second water's fog still needs them"
    assert "Water Meniscus" in bpy.data.materials, "the waterline's material, shared, stays"
    _api().set_underwater(second, False)
    assert _samples(scene) == DEFAULT_SAMPLES
    assert "Water Meniscus" not in bpy.data.materials, "nothing left behind"


def test_the_operator_switches_and_refuses_what_is_not_water(addon, scene):
    water = _api().add_water(scene, preset="ocean", size=10.0, name="Sea").object
    _activate(water)
    assert bpy.ops.object.water_underwater.poll()
    assert bpy.ops.object.water_underwater(enable=False) == {"FINISHED"}
    assert _body(water) is None
    bpy.ops.ed.undo_push(message="off")
    assert bpy.ops.object.water_underwater(enable=True) == {"FINISHED"}
    assert _body(water) is not None
    cube = harness.add_cube(scene, (0, 0, 5), name="Cube")
    _activate(cube)
    assert not bpy.ops.object.water_underwater.poll()
    with pytest.raises(_api().NotWaterError, match="Cube"):
        _api().set_underwater(cube, True)


def test_the_preset_key_and_the_command_line_flag_turn_it_off(addon, scene, tmp_path):
    schema = harness.addon("presets.schema")
    assert schema.check_values({"underwater": False}) == ({"underwater": False}, [])
    with pytest.raises(schema.PresetError, match="underwater"):
        schema.check_values({"underwater": "no"})
    harness.add_camera(scene, (0, -6, 3), (0, 0, 0))
    shot = tmp_path / "shot.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(shot))
    target = tmp_path / "dry.blend"
    cli = harness.addon("cli")
    assert cli.main(["add", str(shot), str(target), "--size", "20", "--no-underwater"]) == 0
    bpy.ops.wm.open_mainfile(filepath=str(target))
    water = bpy.data.objects["Water"]
    assert _body(water) is None
    assert bpy.context.scene.eevee.volumetric_samples == DEFAULT_SAMPLES


def _near(water):
    """The evaluated `Near` of the water's underwater body, the depsgraph brought up to date."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    depsgraph.update()
    body = _body(water).evaluated_get(depsgraph)
    owner, path = harness.addon("water.waves").input_property(body.modifiers[0], "Near")
    return owner.path_resolve(path)


def _new_camera(scene, name, clip_start):
    camera = bpy.data.objects.new(name, bpy.data.cameras.new(name))
    scene.collection.objects.link(camera)
    camera.data.clip_start = clip_start
    return camera


@pytest.mark.lts
def test_near_follows_the_scene_camera_replaced_even_after_it_had_none(addon, scene):
    """Issue 57 point 6: the waterline's `Near` is the scene's camera's Clip Start through every
    change of camera: another camera, the camera deleted (the scene has none a while) and a new
    one set, without reopening the file. It stayed at 0 once the scene had been without one."""
    default_clip = bpy.data.cameras.new("Blender's default").clip_start  # 0.1 m
    scene.camera = _new_camera(scene, "First", 0.25)
    water = _api().add_water(scene, preset="ocean", size=10.0, name="Sea").object
    assert _near(water) == pytest.approx(0.25)
    second = _new_camera(scene, "Second", 0.5)
    scene.camera = second
    assert _near(water) == pytest.approx(0.5)
    bpy.data.objects.remove(second)  # deleted: the scene has no camera
    assert scene.camera is None
    assert _near(water) == pytest.approx(default_clip)
    third = _new_camera(scene, "Third", 0.05)
    scene.camera = third
    assert _near(water) == pytest.approx(0.05), "the replaced camera's Clip Start, not 0"
    third.data.clip_start = 0.3
    assert _near(water) == pytest.approx(0.3)
    scene.camera = None  # unset, not deleted
    assert _near(water) == pytest.approx(default_clip)
    scene.camera = _new_camera(scene, "Fourth", 0.2)
    assert _near(water) == pytest.approx(0.2)


def test_near_follows_a_camera_added_after_the_water(addon, scene):
    """A water given its body in a scene with no camera: `Near` follows the first camera set."""
    assert scene.camera is None
    water = _api().add_water(scene, preset="clear_lake", size=10.0, name="Lake").object
    scene.camera = _new_camera(scene, "Late", 0.4)
    assert _near(water) == pytest.approx(0.4)


def test_a_file_with_the_older_near_driver_still_follows_its_camera(addon, scene, tmp_path):
    """Files saved before the driver's fallback value: their driver (no fallback) still evaluates
    after reopening with scripts off, and follows the camera's Clip Start and a replaced camera."""
    scene.camera = _new_camera(scene, "First", 0.25)
    water = _api().add_water(scene, preset="ocean", size=10.0, name="Sea").object
    (fcurve,) = _body(water).animation_data.drivers
    for variable in fcurve.driver.variables:  # as the add-on wrote it before
        variable.targets[0].use_fallback_value = False
    path = tmp_path / "older.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False, use_scripts=False)
    scene, water = bpy.context.scene, bpy.data.objects["Sea"]
    assert not _body(water).animation_data.drivers[0].driver.variables[0].targets[0].use_fallback_value
    scene.camera.data.clip_start = 0.15
    assert _near(water) == pytest.approx(0.15)
    scene.camera = _new_camera(scene, "Second", 0.5)
    assert _near(water) == pytest.approx(0.5)
