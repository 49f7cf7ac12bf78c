"""The open sea's whitecaps on a farm (issue 58 point 6): no memory, no add-on needed at render.

The whitecaps are worked out each frame from that frame's waves (`Water Sea Fade` marks the crests
and their run over the last second and a half, the ocean shading draws the foam), so a frame
rendered alone, in a Blender of its own without the add-on and with auto-run scripts off, is the
frame a job stepping through the range renders. The scene: the `open_sea` preset at 15 m/s from
12 m up, a sun 15 degrees up behind the camera, 96 x 54, one EEVEE sample (the comparisons are
exact at any count; software EEVEE's cost is per sample).

The add-on has no bake of the sea (its Bake is the wakes'); a user's Bake for the sea is the Ocean
modifier's own (`object.ocean_bake`), which writes the waves of each frame of its range to image
files the modifier then reads.
"""

import json
import os
import time

import bpy
import mathutils
import numpy as np
import pytest

import harness

pytestmark = pytest.mark.render

WIND = (0.8, 0.6)
LOOK = np.array((0.6, 0.8))
FRAME = 40
# Alone and stepped, measured: no difference at all (4.2.23, 4.5.15, 5.2.3). Frame 39 against 40
# differs by MAX_DIFFERENCE 50 times over at some pixel and MEAN_DIFFERENCE 10 times over on average.
MAX_DIFFERENCE = 2e-3
MEAN_DIFFERENCE = 1e-4

# A worker: plain bpy with a fresh user folder (the add-on is not installed there), auto-run off.
# Each job opens a saved file, evaluates frames FIRST to FRAME in turn and renders FRAME.
WORKER = """
import json, sys
import harness
bpy = harness.start()
bpy.context.preferences.filepaths.use_scripts_auto_execute = False
assert not hasattr(bpy.types, "OBJECT_OT_water_add"), "the add-on is not installed here"
for blend, first, frame, out in json.loads(sys.argv[1]):
    bpy.ops.wm.open_mainfile(filepath=blend, load_ui=False, use_scripts=False)
    scene = bpy.context.scene
    for each in range(first, frame + 1):
        scene.frame_set(each)
    harness.render(scene, out, exr=True)
"""


def _work(jobs):
    """Runs WORKER over `jobs` ((blend, first frame, frame, out EXR), ...) in a process of its own."""
    harness.run_worker(
        "-c", WORKER, json.dumps([[str(v) if not isinstance(v, int) else v for v in job] for job in jobs])
    )
    return [harness.load_image(job[3])[..., :3] for job in jobs]


@pytest.fixture(scope="module")
def shot(addon, eevee, tmp_path_factory):
    """The saved sea (at frame 1) and, in this session with the add-on, its frame FRAME rendered
    after frames 1 to FRAME were evaluated in turn; its foam view; and the frame without foam."""
    folder = tmp_path_factory.mktemp("whitecap_bake")
    scene = harness.clean_scene(engine=eevee, width=96, height=54, samples=1)
    harness.set_world_color(scene, (0.45, 0.6, 0.8), 1.0)
    sun = bpy.data.objects.new("Low sun", bpy.data.lights.new("Low sun", "SUN"))
    sun.data.energy = 4.0
    up = np.radians(15.0)
    to_sun = mathutils.Vector((-LOOK[0] * np.cos(up), -LOOK[1] * np.cos(up), np.sin(up)))
    sun.rotation_euler = to_sun.to_track_quat("Z", "Y").to_euler()
    scene.collection.objects.link(sun)
    api = harness.addon("api")
    sea = api.add_water(scene, preset="open_sea", sea_wind_speed=15.0, wind_direction=WIND, name="Sea").object
    camera = harness.add_camera(scene, (2.0, -5.0, 12.0), (2.0 + 100 * LOOK[0], -5.0 + 100 * LOOK[1], -48.0))
    scene.camera = camera
    scene.frame_start, scene.frame_end = 1, FRAME
    scene.frame_set(1)
    path = folder / "sea.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    started = time.perf_counter()
    for frame in range(1, FRAME + 1):
        scene.frame_set(frame)
    stepped = harness.render(scene, folder / "stepped.exr", exr=True)[..., :3]
    shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.active_material)[1]
    shade.inputs["Debug View"].default_value = 7
    foam = harness.render(scene, folder / "foam.exr", exr=True)[..., 0] > 0.5
    shade.inputs["Debug View"].default_value = 0
    shade.inputs["Whitecaps"].default_value = 0.0
    bare = harness.render(scene, folder / "bare.exr", exr=True)[..., :3]
    shade.inputs["Whitecaps"].default_value = 1.0
    print(f"\nsession: frames 1-{FRAME} stepped and three renders in {time.perf_counter() - started:.1f} s")
    return {
        "path": path,
        "folder": folder,
        "scene": scene,
        "sea": sea,
        "stepped": stepped,
        "foam": foam,
        "bare": bare,
    }


@pytest.mark.lts
def test_a_frame_rendered_alone_without_the_add_on_is_the_stepped_frame_with_it(shot, tmp_path):
    """Frame 40 rendered alone from the saved file, in a Blender of its own without the add-on and
    with auto-run off, equals frame 40 rendered in this session (the add-on enabled) after frames
    1 to 40 were evaluated in turn. One comparison holds both: no memory between frames, and
    nothing at render time needs the add-on. The whitecaps are in view (over 1% of the frame in
    the foam view, Debug View 7). Would the test see a lost property? Frame 39,
    a moment a memory could leave behind, differs from frame 40 by far more than the tolerance,
    and so does frame 40 without its whitecaps (as a farm without the foam would render it)."""
    started = time.perf_counter()
    alone, earlier = _work(
        [
            (shot["path"], FRAME, FRAME, tmp_path / "alone.exr"),
            (shot["path"], FRAME - 1, FRAME - 1, tmp_path / "39.exr"),
        ]
    )
    seconds = time.perf_counter() - started
    stepped = shot["stepped"]
    foam = shot["foam"]
    difference = np.abs(alone - stepped)
    moved = np.abs(earlier - stepped)
    unfoamed = np.abs(shot["bare"] - stepped)[foam].mean()
    print(
        f"worker {seconds:.1f} s; whitecaps on {foam.mean():.4f} of the frame; alone vs stepped: max "
        f"{difference.max():.2e}, mean {difference.mean():.2e}; "
        f"frame 39 vs 40: max {moved.max():.3f}, mean {moved.mean():.4f}; "
        f"without whitecaps, on the foam: mean {unfoamed:.4f}"
    )
    assert foam.mean() > 0.01, "whitecaps in view"
    assert difference.max() < MAX_DIFFERENCE and difference.mean() < MEAN_DIFFERENCE
    assert moved.max() > 50 * MAX_DIFFERENCE and moved.mean() > 10 * MEAN_DIFFERENCE, (
        "another moment would fail"
    )
    assert unfoamed > 50 * MAX_DIFFERENCE, "a frame without its foam would fail the test"


def test_the_ocean_modifier_s_bake_keeps_the_waves_moving(shot, tmp_path):
    """The Ocean modifier's own Bake over frames 1 to 40 writes each frame's waves (`disp_####.exr`,
    the displacement of the modifier's grid), which a baked sea renders from, its whitecaps
    worked out from their heights. So frames 1, 39 and 40 must hold different waves: the clock runs
    through the bake as through the render. The bake reads `time` from the object's F-curves only
    (Blender's `ocean_bake_exec`: no drivers); with the add-on's driven clock alone every frame's
    displacement equalled frame 1's, exactly (4.2.23, 4.5.15, 5.2.3). The clock is keyed too now
    (`water/sea/sea_clock.py`: a keyless F-curve's Generator, the driver's seconds). In a Blender
    without a window (these tests, a farm) the bake's job writes the files but never ends, so
    `is_cached` stays off and nothing reads them: only a bake made in Blender's window is saved as
    baked, so a frame rendered alone from a baked sea cannot be checked here."""
    scene, sea = shot["scene"], shot["sea"]
    ocean = harness.addon("water.sea.open_sea").sea_modifiers(sea)[0]
    ocean.frame_start, ocean.frame_end = 1, FRAME
    cache = tmp_path / "ocean_cache"
    ocean.filepath = str(cache) + os.sep
    scene.frame_set(1)
    started = time.perf_counter()
    with bpy.context.temp_override(object=sea, active_object=sea, selected_objects=[sea]):
        assert bpy.ops.object.ocean_bake(modifier=ocean.name) == {"FINISHED"}
    # The bake runs as a job in a thread of its own; the files come one frame after another.
    last = cache / f"disp_{FRAME:04d}.exr"
    while not last.exists() and time.perf_counter() - started < 120:
        time.sleep(0.2)
    time.sleep(1.0)
    print(
        f"\nbake: {len(list(cache.glob('*.exr')))} files in {time.perf_counter() - started:.1f} s: "
        f"{sorted(p.name for p in cache.glob('*'))[:4]}; is_cached {ocean.is_cached}"
    )
    waves = {
        frame: harness.load_image(cache / f"disp_{frame:04d}.exr")[..., :3] for frame in (1, FRAME - 1, FRAME)
    }
    spread = waves[FRAME].std()
    steps = {frame: np.abs(waves[frame] - waves[FRAME]).mean() for frame in (1, FRAME - 1)}
    print(f"displacement spread {spread:.3f}; frame 1 vs 40 {steps[1]:.4f}, 39 vs 40 {steps[FRAME - 1]:.4f}")
    assert spread > 0.1, "waves baked"
    assert steps[FRAME - 1] > 1e-4 * spread and steps[1] > 0.1 * spread, "the baked waves move"
