"""A `.blend` made with the add-on renders the same without it, with auto-run scripts off."""

import addon_utils
import bpy
import numpy as np
import pytest

import harness

pytestmark = [pytest.mark.render, pytest.mark.lts]


def test_saved_water_renders_the_same_without_the_add_on_and_with_auto_run_off(
    scene, render, tmp_path, addon_disabled_afterwards
):
    # One sample (software EEVEE's cost is per sample): both renders are of the same file, so any
    # difference the add-on's absence makes shows at 1 sample as at 4 (the test: 23 s at 4, 7 s).
    scene.eevee.taa_render_samples = 1
    harness.set_world_color(scene, (0.3, 0.5, 0.8))
    sun = bpy.data.objects.new("Sun", bpy.data.lights.new("Sun", "SUN"))
    sun.rotation_euler = (0.9, 0.0, 3.0)
    scene.collection.objects.link(sun)
    harness.add_cube(scene, (1, 3, 0.8), material=harness.emission_material("Block", (1, 0.2, 0.1)))
    harness.add_cube(scene, (0, 0, -1.5), material=harness.emission_material("Floor", (0.1, 0.6, 0.2)))
    bpy.ops.object.water_add(size=12, wave_length=1.0, wind_force=0.2)
    harness.add_camera(scene, (0, -6, 2.5), (0, 1, 0))
    scene.frame_set(48)  # two seconds in: the clock driver has moved the bump
    path = tmp_path / "lake.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    with_addon = render(scene, "with-addon", exr=True)

    addon_utils.disable(harness.ADDON_MODULE, default_set=True)
    assert not hasattr(bpy.types, "OBJECT_OT_water_add")
    bpy.context.preferences.filepaths.use_scripts_auto_execute = False
    bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False, use_scripts=False)
    scene = bpy.context.scene
    scene.frame_set(1)
    scene.frame_set(48)
    node = bpy.data.materials["Water"].node_tree.nodes["Water Surface"]
    assert node.inputs["Time"].default_value == pytest.approx(2.0), "the clock driver runs without scripts"
    assert bpy.data.images["Water Surface Bump"].packed_file is not None
    without = render(scene, "without-addon", exr=True)

    difference = np.abs(without[..., :3] - with_addon[..., :3])
    assert difference.mean() < 0.005 and np.percentile(difference, 99) < 0.05, difference.mean()
    # And the water does move: frame 1 differs.
    scene.frame_set(1)
    assert node.inputs["Time"].default_value == pytest.approx(1 / 24)
