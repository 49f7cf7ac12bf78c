"""Issue 40 point 6: a half-under shot renders the same without the add-on, with auto-run scripts off
(a farm): the underwater body, its fog and the meniscus are Geometry Nodes and materials saved in
the file, and their drivers (the fog's colours from the water's, `Near` from the camera's Clip
Start) are simple expressions, which run without Python.

The scene is test_waterline.py's (the seeds' ocean, a camera whose lens the surface crosses),
rendered in EEVEE with the add-on, saved, and rendered again after the add-on is disabled and the
file reopened with scripts off: the same pixels (mean difference under 0.005). Then the camera's
Clip Start changes and the body's `Near` follows it, still without the add-on.
"""

import addon_utils
import bpy
import numpy as np
import pytest
from test_waterline import _scene

import harness

pytestmark = pytest.mark.render


def _near(scene):
    body = next(o for o in scene.objects if o.name.endswith(" Underwater"))
    modifier = body.modifiers[0]
    identifier = next(
        i.identifier for i in modifier.node_group.interface.items_tree if getattr(i, "name", "") == "Near"
    )
    inputs = getattr(getattr(modifier, "properties", None), "inputs", None)
    return getattr(inputs, identifier).value if inputs is not None else modifier[identifier]


def test_a_half_under_shot_renders_the_same_without_the_add_on(
    addon, eevee, render, tmp_path, addon_disabled_afterwards
):
    scene, _camera = _scene(eevee, 0.03)
    scene.eevee.taa_render_samples = 1
    path = tmp_path / "half_under.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    with_addon = render(scene, "with-addon", exr=True)

    addon_utils.disable(harness.ADDON_MODULE, default_set=True)
    assert not hasattr(bpy.types, "OBJECT_OT_water_underwater")
    bpy.context.preferences.filepaths.use_scripts_auto_execute = False
    bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False, use_scripts=False)
    scene = bpy.context.scene
    scene.frame_set(1)
    scene.frame_set(30)
    without = render(scene, "without-addon", exr=True)
    difference = np.abs(without[..., :3] - with_addon[..., :3])
    print(f"mean difference {difference.mean():.5f}, 99th percentile {np.percentile(difference, 99):.4f}")
    assert difference.mean() < 0.005 and np.percentile(difference, 99) < 0.05

    assert _near(scene) == pytest.approx(0.3)
    scene.camera.data.clip_start = 0.2
    bpy.context.view_layer.update()
    assert _near(scene) == pytest.approx(0.2), "Near follows the camera without scripts"
