"""The water sees its surroundings: depth and shore distance, evaluated by Geometry Nodes.

A 10 m lake (0.25 m grid) over a coarse sloped bed whose waterline is the line
x = 2, with a thin cylinder post standing through it. The evaluated attributes
are checked against an independent answer: BVH raycasts for the depth and the
analytic waterline (the line and the post's circle) for the shore distance.

The measuring runs on a hidden cache object per water; the water samples it.
The cache is checked too: evaluated in the viewport and in renders, drawn and
rendered never, evaluated again only when the surroundings change, no
dependency cycle, removed with the surroundings or when its water is gone.
"""

import math
import os
import sys
import tempfile
import time

import addon_utils
import bmesh
import bpy
import numpy as np
import pytest
from mathutils import Matrix, Vector
from mathutils.bvhtree import BVHTree

import harness

SIZE = 10.0
RESOLUTION = 41  # 0.25 m spacing
SHORE_X = 2.0  # the bed crosses the water along x = SHORE_X
SLOPE = 0.25
POST = (-2.0, 1.0)
POST_RADIUS = 0.15
FAR = 1000.0
NAMES = ("water_depth", "water_shore_distance", "water_surroundings")


@pytest.fixture(scope="module")
def surroundings(addon):
    return harness.addon("water.surroundings")


def _mesh_object(scene, name, verts, faces):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    obj = bpy.data.objects.new(name, mesh)
    scene.collection.objects.link(obj)
    return obj


def _bed(scene, half=6.0):
    """One big quad sloping up along +X, normal up, crossing z = 0 at x = SHORE_X."""
    z = lambda x: SLOPE * (x - SHORE_X)  # noqa: E731
    verts = [(-half, -half, z(-half)), (half, -half, z(half)), (half, half, z(half)), (-half, half, z(-half))]
    return _mesh_object(scene, "Bed", verts, [(0, 1, 2, 3)])


def _post(scene, location=(*POST, -0.5), name="Post"):
    """A closed cylinder, radius POST_RADIUS, 5 m tall (z -3 .. 2 around the default location)."""
    mesh = bpy.data.meshes.new(name)
    bm = bmesh.new()
    bmesh.ops.create_cone(bm, cap_ends=True, segments=24, radius1=POST_RADIUS, radius2=POST_RADIUS, depth=5.0)
    bmesh.ops.recalc_face_normals(bm, faces=bm.faces)
    bm.to_mesh(mesh)
    bm.free()
    obj = bpy.data.objects.new(name, mesh)
    obj.location = location
    scene.collection.objects.link(obj)
    return obj


def _lake(scene, size=SIZE, resolution=RESOLUTION, waves=False):
    added = harness.addon("api").add_water(
        scene, size=size, resolution=resolution, mirror_setup=False, waves=waves
    )
    return added.object


def _evaluate(obj):
    """Evaluated positions (N, 3) and the three attributes (N,) of `obj`."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    depsgraph.update()
    mesh = obj.evaluated_get(depsgraph).data
    count = len(mesh.vertices)
    co = np.empty(count * 3)
    mesh.vertices.foreach_get("co", co)
    values = {}
    for name in NAMES:
        attribute = mesh.attributes[name]
        assert (attribute.domain, attribute.data_type) == ("POINT", "FLOAT"), name
        values[name] = np.empty(count)
        attribute.data.foreach_get("value", values[name])
    return co.reshape(-1, 3), values


def _depth_by_bvh(points, objects):
    """World distance from each world point straight down to the nearest of `objects` (inf: none)."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    trees = [(obj.matrix_world.copy(), BVHTree.FromObject(obj, depsgraph)) for obj in objects]
    out = np.full(len(points), np.inf)
    for i, point in enumerate(points):
        point = Vector(point)
        for matrix, tree in trees:
            inverse = matrix.inverted()
            direction = (inverse.to_3x3() @ Vector((0, 0, -1))).normalized()
            hit, _normal, _index, _distance = tree.ray_cast(inverse @ point, direction)
            if hit is not None:
                out[i] = min(out[i], ((matrix @ hit) - point).length)
    return out


def _expected_shore(xy, post=POST, bed=True):
    """The analytic shore distance: 0 on dry ground (x >= SHORE_X or inside the post)."""
    to_post = np.full(len(xy), np.inf)
    if post is not None:
        to_post = np.hypot(xy[:, 0] - post[0], xy[:, 1] - post[1]) - POST_RADIUS
    to_line = SHORE_X - xy[:, 0] if bed else np.full(len(xy), np.inf)
    return np.where((to_line <= 0) | (to_post <= 0), 0.0, np.minimum(to_line, to_post))


def _world(obj, co):
    matrix = np.array(obj.matrix_world)
    return co @ matrix[:3, :3].T + matrix[:3, 3]


def _assert_finite(values, count=None, flag=(1.0,)):
    for name in NAMES:
        assert np.isfinite(values[name]).all(), name
        assert (values[name] >= 0).all() and (values[name] <= FAR).all(), name
    assert np.isin(values["water_surroundings"], flag).all()
    if count is not None:
        assert len(values["water_depth"]) == count


def test_depth_and_shore_distance_match_the_bed_and_the_post(scene, surroundings):
    lake = _lake(scene)
    bed, post = _bed(scene), _post(scene)
    far_rock = _post(scene, location=(40.0, 0.0, 0.0), name="Far Rock")  # outside the water
    cloud = _post(scene, location=(0.0, 0.0, 5.0), name="Cloud")  # wholly above it
    changes = surroundings.ensure_surroundings(lake, scene)
    assert changes, "says what it did"
    collection = surroundings.surroundings_collection(lake)
    assert {o.name for o in collection.objects} == {"Bed", "Post"}
    assert far_rock.name not in collection.objects and cloud.name not in collection.objects
    assert collection.name not in scene.collection.children, "not linked into the scene"
    assert surroundings.surroundings_modifier(lake) == lake.modifiers[-1]

    co, values = _evaluate(lake)
    _assert_finite(values, RESOLUTION**2)
    xy = co[:, :2]
    to_post = np.hypot(xy[:, 0] - POST[0], xy[:, 1] - POST[1]) - POST_RADIUS
    wet = (xy[:, 0] < SHORE_X - 0.01) & (to_post > 0.01)
    dry = (xy[:, 0] > SHORE_X + 0.01) | (to_post < -0.01)
    assert wet.sum() > 1000 and dry.sum() > 300

    expected_depth = _depth_by_bvh(_world(lake, co)[wet], [bed, post])
    assert np.isfinite(expected_depth).all()
    assert np.abs(values["water_depth"][wet] - expected_depth).max() < 0.01
    assert (values["water_depth"][dry] == 0).all() and (values["water_shore_distance"][dry] == 0).all()

    error = np.abs(values["water_shore_distance"] - _expected_shore(xy))
    assert error.max() < 0.25, f"worst shore distance error {error.max():.3f} m"
    # The post is thinner than the grid spacing, yet its ring is found.
    ring = (to_post > 0) & (to_post < 0.3)
    assert (values["water_shore_distance"][ring] < 0.3).all()


def test_a_moving_post_moves_its_ring_of_low_shore_distance(scene, surroundings):
    lake = _lake(scene)
    post = _post(scene)
    post.keyframe_insert("location", frame=1)
    post.location = (-2.0, -2.0, -0.5)
    post.keyframe_insert("location", frame=10)
    surroundings.ensure_surroundings(lake, scene)

    centres = {}
    for frame in (1, 10):
        scene.frame_set(frame)
        co, values = _evaluate(lake)
        _assert_finite(values)
        near = values["water_shore_distance"] < 0.5
        assert 4 <= near.sum() < 60, frame
        centres[frame] = co[near, :2].mean(axis=0)
        expected = _expected_shore(co[:, :2], tuple(post.matrix_world.translation[:2]), bed=False)
        assert np.abs(values["water_shore_distance"] - expected).max() < 0.25, frame
    assert centres[1] == pytest.approx(POST, abs=0.1)
    assert centres[10] == pytest.approx((-2.0, -2.0), abs=0.1)


def test_the_modifier_survives_save_and_reload_without_the_add_on(scene, surroundings, tmp_path):
    lake = _lake(scene)
    _bed(scene)
    _post(scene)
    surroundings.ensure_surroundings(lake, scene)
    _co, before = _evaluate(lake)
    path = tmp_path / "surroundings.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    addon_utils.disable(harness.ADDON_MODULE, default_set=True)
    try:
        bpy.context.preferences.filepaths.use_scripts_auto_execute = False
        bpy.ops.wm.open_mainfile(filepath=str(path), load_ui=False, use_scripts=False)
        lake = bpy.data.objects["Water"]
        collection = bpy.data.collections["Surroundings of Water"]
        assert {o.name for o in collection.objects} == {"Bed", "Post"}, "kept alive by the modifier"
        cache = bpy.data.objects["Water Surroundings"]
        assert cache.hide_render and cache.hide_viewport and cache.data == lake.data
        _co, after = _evaluate(lake)
        for name in NAMES:
            assert np.allclose(after[name], before[name], atol=1e-5), name
    finally:
        bpy.context.preferences.filepaths.use_scripts_auto_execute = True
        addon_utils.enable(harness.ADDON_MODULE, default_set=True)


def test_with_waves_the_surroundings_measure_the_displaced_surface(scene, surroundings):
    lake = _lake(scene, waves=True)
    bed = _bed(scene)
    surroundings.ensure_surroundings(lake, scene)
    waves = harness.addon("water.waves").wave_modifier(lake)
    assert list(lake.modifiers).index(waves) < list(lake.modifiers).index(
        surroundings.surroundings_modifier(lake)
    )
    scene.frame_set(13)
    co, values = _evaluate(lake)
    _assert_finite(values)
    assert np.ptp(co[:, 2]) > 0.1, "the waves are on"
    wet = values["water_depth"] > 0.05
    expected = _depth_by_bvh(_world(lake, co)[wet], [bed])
    assert np.abs(values["water_depth"][wet] - expected).max() < 0.01


def test_surroundings_added_before_the_waves_are_moved_after_them(scene, surroundings):
    lake = _lake(scene)
    _bed(scene)
    surroundings.ensure_surroundings(lake, scene)
    harness.addon("water.waves").add_waves(lake)  # goes before the surroundings, which read the waves
    assert surroundings.surroundings_modifier(lake) == lake.modifiers[-1]
    changes = surroundings.ensure_surroundings(lake, scene)
    assert not any("moved after" in change for change in changes)
    assert surroundings.surroundings_modifier(lake) == lake.modifiers[-1]
    assert len(lake.modifiers) == 2, "reused, not added twice"


def _bad_empty(scene, surroundings, lake):
    surroundings.set_surroundings(lake, bpy.data.collections.new("Empty"))


def _bad_deleted(scene, surroundings, lake):
    surroundings.ensure_surroundings(lake, scene)
    bpy.data.collections.remove(surroundings.surroundings_collection(lake))
    assert surroundings.surroundings_collection(lake) is None


def _bad_holds_the_water(scene, surroundings, lake):
    mine = bpy.data.collections.new("Mine")
    mine.objects.link(lake)
    with pytest.raises(surroundings.SurroundingsError, match="cycle"):
        surroundings.set_surroundings(lake, mine)
    surroundings.ensure_surroundings(lake, scene)
    own = surroundings.surroundings_collection(lake)
    own.objects.link(lake)  # the user drags the water in: a dependency cycle until ensured again
    _co, values = _evaluate(lake)
    _assert_finite(values, flag=(0.0, 1.0))  # in the cycle the cache may be read unevaluated
    changes = surroundings.ensure_surroundings(lake, scene)
    assert any("cycle" in change for change in changes) and lake.name not in own.objects


def _bad_not_meshes(scene, surroundings, lake):
    things = bpy.data.collections.new("Things")
    curve = bpy.data.curves.new("Rope", "CURVE")
    spline = curve.splines.new("POLY")
    spline.points.add(1)
    spline.points[0].co = (0, 0, -1, 1)
    spline.points[1].co = (0, 0, 1, 1)
    text = bpy.data.curves.new("Sign", "FONT")
    text.body = "shore"
    text.extrude = 0.1
    inner = bpy.data.collections.new("Inner")
    inner.objects.link(_post(scene, name="Inner Post"))
    instancer = bpy.data.objects.new("Instancer", None)
    instancer.instance_type = "COLLECTION"
    instancer.instance_collection = inner
    for obj in (
        bpy.data.objects.new("Rope", curve),
        bpy.data.objects.new("Sign", text),
        bpy.data.objects.new("Empty", None),
        instancer,
    ):
        things.objects.link(obj)
    surroundings.set_surroundings(lake, things)


def _bad_negative_scale(scene, surroundings, lake):
    lake.scale = (-1.0, 1.0, -2.0)
    _bed(scene)
    surroundings.ensure_surroundings(lake, scene)


def _bad_on_its_side(scene, surroundings, lake):
    lake.rotation_euler = (math.pi / 2, 0.0, 0.0)
    _bed(scene)
    _post(scene)
    surroundings.ensure_surroundings(lake, scene)


@pytest.mark.parametrize(
    "make_bad",
    [_bad_empty, _bad_deleted, _bad_holds_the_water, _bad_not_meshes, _bad_negative_scale, _bad_on_its_side],
)
def test_bad_input_gives_finite_attributes_and_no_exception(scene, surroundings, make_bad):
    lake = _lake(scene, size=4.0, resolution=17)
    make_bad(scene, surroundings, lake)
    _co, values = _evaluate(lake)
    _assert_finite(values, 17**2)


def test_nothing_around_reads_far(scene, surroundings):
    lake = _lake(scene, size=4.0, resolution=9)
    surroundings.ensure_surroundings(lake, scene)
    assert len(surroundings.surroundings_collection(lake).objects) == 0
    _co, values = _evaluate(lake)
    assert (values["water_depth"] == FAR).all() and (values["water_shore_distance"] == FAR).all()


def test_negative_scale_measures_world_metres(scene, surroundings):
    lake = _lake(scene, size=8.0, resolution=33)
    lake.scale = (-1.0, 2.0, 1.5)
    bed = _bed(scene, half=12.0)
    surroundings.ensure_surroundings(lake, scene)
    co, values = _evaluate(lake)
    world = _world(lake, co)
    wet = world[:, 0] < SHORE_X - 0.01
    expected = _depth_by_bvh(world[wet], [bed])
    assert np.abs(values["water_depth"][wet] - expected).max() < 0.01
    assert np.abs(values["water_shore_distance"] - _expected_shore(world[:, :2], None)).max() < 0.25


def test_linked_water_is_refused(scene, surroundings, tmp_path):
    lake = _lake(scene, size=2.0, resolution=3)
    path = tmp_path / "lib.blend"
    bpy.data.libraries.write(str(path), {lake})
    with bpy.data.libraries.load(str(path), link=True) as (_source, target):
        target.objects = ["Water"]
    linked = target.objects[0]
    with pytest.raises(harness.addon("water.editable").NotEditableError):
        surroundings.ensure_surroundings(linked, scene)


def test_needed_resolution_keeps_the_grid_at_a_quarter_metre(surroundings):
    assert surroundings.needed_resolution(128.0) == 513
    for size in (0.01, 1.0, 10.0, 12.3, 300.0):
        n = surroundings.needed_resolution(size)
        assert size / (n - 1) <= 0.25 or n == harness.addon("water.plane").max_resolution()
        assert 2 <= n <= 2048
    assert surroundings.needed_resolution(100000.0) <= harness.addon("water.plane").max_resolution()


def test_a_big_terrain_evaluates_in_reasonable_time(scene, surroundings):
    lake = _lake(scene, size=8.0, resolution=33)
    bpy.ops.mesh.primitive_grid_add(x_subdivisions=200, y_subdivisions=200, size=12.0, location=(0, 0, -1))
    surroundings.ensure_surroundings(lake, scene)
    start = time.perf_counter()
    _co, values = _evaluate(lake)
    assert time.perf_counter() - start < 30
    assert np.allclose(values["water_depth"], 1.0, atol=1e-4)


def _blender_output(action):
    """What Blender prints (from C, at the file descriptors) while `action()` runs."""
    saved = {fd: os.dup(fd) for fd in (1, 2)}
    with tempfile.TemporaryFile() as caught:
        sys.stdout.flush()
        sys.stderr.flush()
        for fd in saved:
            os.dup2(caught.fileno(), fd)
        try:
            action()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            for fd, copy in saved.items():
                os.dup2(copy, fd)
                os.close(copy)
        caught.seek(0)
        return caught.read().decode(errors="replace")


def test_the_cache_is_a_hidden_twin_of_the_water(scene, surroundings):
    lake = _lake(scene)
    _bed(scene)
    surroundings.remove_surroundings(lake)
    changes = surroundings.ensure_surroundings(lake, scene)
    assert "made hidden object 'Water Surroundings'" in changes
    cache = surroundings.surroundings_cache(lake)
    assert cache.name == "Water Surroundings" and cache.get(surroundings.WATER_KEY) == "Water"
    assert harness.addon("nodes.ownership").role_of(cache) == "Surroundings Cache"
    assert cache.data == lake.data, "the same points in the same order"
    assert cache.parent == lake and cache.matrix_parent_inverse == Matrix.Identity(4)
    assert cache.matrix_world == lake.matrix_world
    assert cache.hide_viewport and cache.hide_render and cache.hide_select
    assert set(cache.users_collection) == set(lake.users_collection)
    # Only the light group runs on the water, the measuring one on the cache.
    assert [m.node_group["water_surface_role"] for m in lake.modifiers] == ["Water Surroundings Sample"]
    assert [m.node_group["water_surface_role"] for m in cache.modifiers] == ["Water Surroundings"]
    assert surroundings.surroundings_collection(lake) == surroundings.surroundings_collection(cache)
    # It shares the water's mesh, its slots are its own and empty: not taken for a water.
    assert not harness.addon("water.values").is_water(cache)
    assert [slot.link for slot in cache.material_slots] == ["OBJECT"] and lake.active_material
    cache.material_slots[0].link = "DATA"  # reads as a water now, yet is never a surrounding
    assert harness.addon("water.values").is_water(cache)
    other = _lake(scene, size=4.0, resolution=9)
    assert cache not in surroundings.default_surroundings(other, scene)
    assert lake not in surroundings.default_surroundings(other, scene)
    surroundings.ensure_surroundings(lake, scene)
    assert not harness.addon("water.values").is_water(cache)
    assert surroundings.ensure_surroundings(lake, scene) == [], "ensured twice: nothing to do"
    with pytest.raises(surroundings.SurroundingsError, match="cache"):
        surroundings.ensure_surroundings(cache, scene)


def test_the_cache_is_evaluated_only_when_the_surroundings_change(scene, surroundings):
    lake = _lake(scene, waves=True)
    post = _post(scene)
    surroundings.ensure_surroundings(lake, scene)
    cache = surroundings.surroundings_cache(lake)
    updated = {}

    def note(_scene, depsgraph):
        updated[_scene.frame_current] = {
            u.id.original.name
            for u in depsgraph.updates
            if isinstance(u.id, bpy.types.Object)
            if u.is_updated_geometry
        }

    bpy.app.handlers.frame_change_post.append(note)
    try:
        for frame in (2, 3, 4):
            scene.frame_set(frame)
        post.location.x += 0.5
        scene.frame_set(5)
    finally:
        bpy.app.handlers.frame_change_post.remove(note)
    assert "Water" in updated[3] and "Water" in updated[4], "the waves move on every frame"
    assert cache.name not in updated[3] and cache.name not in updated[4], "the cache stays as it is"
    assert cache.name in updated[5], "the post moved: measured again"


def test_no_dependency_cycle(scene, surroundings):
    def build():
        lake = _lake(scene, waves=True)
        post = _post(scene)
        post.keyframe_insert("location", frame=1)
        post.location.x += 1.0
        post.keyframe_insert("location", frame=5)
        _bed(scene)
        surroundings.ensure_surroundings(lake, scene)
        for frame in range(1, 6):
            scene.frame_set(frame)
        _evaluate(lake)
        return lake

    printed = _blender_output(build)
    assert "Dependency cycle" not in printed, printed
    # The check sees a cycle when there is one: the water dragged into its own surroundings.
    lake = bpy.data.objects["Water"]
    surroundings.surroundings_collection(lake).objects.link(lake)
    assert "Dependency cycle" in _blender_output(lambda: _evaluate(lake))


def _emission_material():
    """Emits (depth / 2, shore distance / 4, flag): the attributes as colours."""
    material = bpy.data.materials.new("Attributes")
    material.use_nodes = True
    tree = material.node_tree
    tree.nodes.clear()
    combine = tree.nodes.new("ShaderNodeCombineXYZ")
    for axis, (name, scale) in zip("XYZ", zip(NAMES, (0.5, 0.25, 1.0)), strict=True):
        attribute = tree.nodes.new("ShaderNodeAttribute")
        attribute.attribute_name = name
        times = tree.nodes.new("ShaderNodeMath")
        times.operation = "MULTIPLY"
        times.inputs[1].default_value = scale
        tree.links.new(attribute.outputs["Fac"], times.inputs[0])
        tree.links.new(times.outputs["Value"], combine.inputs[axis])
    emission = tree.nodes.new("ShaderNodeEmission")
    output = tree.nodes.new("ShaderNodeOutputMaterial")
    tree.links.new(combine.outputs["Vector"], emission.inputs["Color"])
    tree.links.new(emission.outputs["Emission"], output.inputs["Surface"])
    return material


@pytest.mark.render
def test_the_cache_is_evaluated_in_a_render_and_never_rendered(scene, surroundings, render):
    """A render of the water shows the attributes the cache measured (so the render evaluates the
    cache), and equals a render of the water baked into a plain mesh with the cache deleted (so
    the cache adds nothing to the picture: with the waves the water leaves it in the troughs,
    where a rendered cache would show its rest depth)."""
    scene.render.resolution_x = scene.render.resolution_y = 32
    lake = _lake(scene, size=4.0, resolution=33, waves=True)
    _bed(scene)
    surroundings.ensure_surroundings(lake, scene)
    cache = surroundings.surroundings_cache(lake)
    material = _emission_material()
    lake.data.materials.clear()
    lake.data.materials.append(material)
    camera = bpy.data.objects.new("Camera", bpy.data.cameras.new("Camera"))
    camera.data.type = "ORTHO"
    camera.data.ortho_scale = 3.0
    camera.location = (0.0, 0.0, 10.0)
    scene.collection.objects.link(camera)
    scene.camera = camera
    scene.frame_set(13)
    with_cache = render(scene, "with_cache", exr=True)
    _co, values = _evaluate(lake)
    assert (values["water_surroundings"] == 1).all() and values["water_depth"].max() < 2
    assert np.ptp(with_cache[..., 0]) > 0.1 and (np.abs(with_cache[..., 2] - 1) < 1e-3).all()

    depsgraph = bpy.context.evaluated_depsgraph_get()
    baked_mesh = bpy.data.meshes.new_from_object(
        lake.evaluated_get(depsgraph), preserve_all_data_layers=True, depsgraph=depsgraph
    )
    baked = bpy.data.objects.new("Baked", baked_mesh)
    baked.matrix_world = lake.matrix_world
    scene.collection.objects.link(baked)
    bpy.data.objects.remove(cache)
    bpy.data.objects.remove(lake)
    without_cache = render(scene, "baked_without_cache", exr=True)
    assert np.abs(with_cache - without_cache).max() < 2e-3


def test_removing_the_surroundings_removes_the_cache(scene, surroundings):
    lake = _lake(scene, size=4.0, resolution=9)
    _bed(scene)
    surroundings.ensure_surroundings(lake, scene)
    cache_name = surroundings.surroundings_cache(lake).name
    changes = surroundings.remove_surroundings(lake)
    assert any(cache_name in change for change in changes)
    assert cache_name not in bpy.data.objects and "Surroundings of Water" not in bpy.data.collections
    assert surroundings.surroundings_modifier(lake) is None and surroundings.surroundings_cache(lake) is None
    assert "water_depth" not in lake.evaluated_get(bpy.context.evaluated_depsgraph_get()).data.attributes


def test_a_deleted_waters_cache_goes_with_the_next_surroundings(scene, surroundings):
    lake = _lake(scene, size=4.0, resolution=9)
    surroundings.ensure_surroundings(lake, scene)
    cache_name = surroundings.surroundings_cache(lake).name
    bpy.data.objects.remove(lake)
    assert bpy.data.objects[cache_name].parent is None, "left behind"
    _bed(scene)  # something below the new water, so it gets surroundings
    added = harness.addon("api").add_water(
        scene, size=4.0, resolution=9, mirror_setup=False, name="Other", foam_amount=0.5
    )
    assert cache_name not in bpy.data.objects and any("deleted" in change for change in added.changes)
    assert surroundings.surroundings_cache(added.object).name == "Other Surroundings"


def test_a_duplicated_water_reads_nothing_until_it_gets_its_own_cache(scene, surroundings):
    lake = _lake(scene, size=4.0, resolution=17)
    _bed(scene)
    surroundings.ensure_surroundings(lake, scene)
    twin = lake.copy()
    twin.data = lake.data.copy()
    twin.location.x += 1.0  # the sample modifier still reads the original's cache
    scene.collection.objects.link(twin)
    _co, values = _evaluate(twin)
    assert (values["water_surroundings"] == 0).all() and (values["water_depth"] == FAR).all()
    surroundings.ensure_surroundings(twin, scene)
    assert surroundings.surroundings_cache(twin) not in (None, surroundings.surroundings_cache(lake))
    _co, values = _evaluate(twin)
    _assert_finite(values, 17**2)
    assert values["water_depth"].max() < FAR


def test_a_failed_add_removes_the_cache(scene, surroundings, monkeypatch):
    _bed(scene)
    before = {o.name for o in bpy.data.objects}

    def fail(*_args, **_kwargs):
        raise RuntimeError("mirror broke")

    monkeypatch.setattr(harness.addon("water.mirror"), "setup_mirror", fail)
    with pytest.raises(harness.addon("water.plane").AddWaterError):
        harness.addon("api").add_water(scene, size=4.0, resolution=9, mirror_setup=True, foam_amount=0.5)
    assert {o.name for o in bpy.data.objects} == before


def test_every_water_gets_its_surroundings_collection_when_added(scene, surroundings):
    """The seeds' lake too: over a bed it gathers the bed and gets the waterline's points; over
    nothing its collection is empty, it stays one quad and reads far; opting out adds nothing."""
    api = harness.addon("api")
    alone = api.add_water(scene, size=SIZE, mirror_setup=False, location=(100.0, 0.0, 0.0))
    collection = surroundings.surroundings_collection(alone.object)
    assert collection is not None and len(collection.objects) == 0
    assert collection not in scene.collection.children_recursive, "kept out of the scene's hierarchy"
    assert len(alone.object.data.vertices) == 4
    _co, values = _evaluate(alone.object)
    assert (values["water_depth"] == FAR).all() and (values["water_shore_distance"] == FAR).all()

    bed = _bed(scene)
    lake = api.add_water(scene, size=SIZE, mirror_setup=False)
    assert list(surroundings.surroundings_collection(lake.object).objects) == [bed]
    assert len(lake.object.data.vertices) == surroundings.needed_resolution(SIZE) ** 2
    co, values = _evaluate(lake.object)
    wet = co[:, 0] < SHORE_X - 0.5
    assert np.abs(values["water_depth"][wet] - SLOPE * (SHORE_X - co[wet, 0])).max() < 0.01
    assert values["water_shore_distance"].min() == 0.0

    plain = api.add_water(scene, size=SIZE, mirror_setup=False, see_surroundings=False)
    assert len(plain.object.data.vertices) == 4 and surroundings.surroundings_cache(plain.object) is None
    assert surroundings.surroundings_collection(plain.object) is None
