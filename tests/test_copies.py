"""A data-block the user copied from one of the add-on's is the user's.

Blender copies ID properties, so a copy carries the add-on's mark. New water must never take
the copy, and an upgrade must never rebuild it: each test copies one kind (group, image, world,
probe, collection), edits the copy, then adds water or upgrades, and checks the copy as left.
"""

import bpy

import harness

VERSION_KEY = "water_surface_version"


def _api():
    return harness.addon("api")


def _group(material):
    return material.node_tree.nodes["Water Surface"].node_tree


def test_a_copied_group_is_never_used_for_new_water_nor_rebuilt(scene):
    # A user's group holds our name, so ours is "Water Surface.001" and has no name advantage.
    bpy.data.node_groups.new("Water Surface", "ShaderNodeTree").use_fake_user = True
    first = _api().add_water(scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False)
    ours = _group(first.material)
    assert ours.name != "Water Surface"
    # Named so it sorts before ours, as the "My Custom Water" did.
    copy = ours.copy()
    copy.name = "A Custom Water"
    copy.nodes.new("ShaderNodeBsdfDiffuse").name = "my edit"
    edited = len(copy.nodes)

    second = _api().add_water(scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False)
    assert _group(second.material) == ours

    # An older stamp on both: the add-on's own is rebuilt, the copy keeps the user's edit.
    copy[VERSION_KEY] = 1
    ours[VERSION_KEY] = 1
    third = _api().add_water(scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False)
    assert _group(third.material) == ours and ours[VERSION_KEY] > 1
    assert len(copy.nodes) == edited and copy.nodes.get("my edit") is not None
    assert copy[VERSION_KEY] == 1 and copy.name == "A Custom Water"


def test_a_copy_named_like_blenders_duplicate_is_not_rebuilt_when_ours_is_gone(scene):
    added = _api().add_water(scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False)
    ours = _group(added.material)
    copy = ours.copy()  # "Water Surface.001", as Shift+D in the node editor names it
    copy.nodes.new("ShaderNodeBsdfDiffuse").name = "my edit"
    copy[VERSION_KEY] = 1
    user_material = bpy.data.materials.new("Mine")
    if bpy.app.version < (5, 0, 0):
        user_material.use_nodes = True
    user_material.node_tree.nodes.new("ShaderNodeGroup").node_tree = copy
    bpy.data.objects.remove(added.object)
    bpy.data.materials.remove(added.material)
    bpy.data.node_groups.remove(ours)

    again = _api().add_water(scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False)
    assert _group(again.material) != copy
    assert copy.nodes.get("my edit") is not None and copy[VERSION_KEY] == 1


def test_a_copied_bump_image_is_left_and_a_lost_original_made_again(scene):
    added = _api().add_water(scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False)
    bump = _group(added.material).nodes["bump"].image
    copy = bump.copy()
    copy.name = "A Bump of Mine"
    copy.pixels[0] = 0.25  # the user's edit
    bpy.data.objects.remove(added.object)
    bpy.data.materials.remove(added.material)
    for group in [g for g in bpy.data.node_groups if g.get(VERSION_KEY) is not None]:
        bpy.data.node_groups.remove(group)
    bpy.data.images.remove(bump)

    again = _api().add_water(scene, size=8, resolution=8, see_surroundings=False, mirror_setup=False)
    image = _group(again.material).nodes["bump"].image
    assert image is not None and image != copy
    assert abs(copy.pixels[0] - 0.25) < 1e-3


def test_a_copied_sky_world_is_never_taken_for_a_new_scene(scene):
    scene.world = None
    _api().add_water(scene, size=8, resolution=8, see_surroundings=False)
    sky = scene.world
    assert sky is not None and sky.get(VERSION_KEY) is not None
    copy = sky.copy()
    copy.name = "A Sky of Mine"
    copy.use_fake_user = True
    scene.world = None
    bpy.data.worlds.remove(sky)

    _api().add_water(scene, size=8, resolution=8, see_surroundings=False)
    assert scene.world is not None and scene.world != copy


def test_a_copied_probe_is_the_users_and_never_refitted(scene):
    added = _api().add_water(scene, size=8, resolution=8, see_surroundings=False)
    water = added.object
    mirror = harness.addon("water.mirror")
    probe = mirror.find_probe(water)
    copy = probe.copy()
    copy.data = probe.data.copy()
    copy.name = "A Probe of Mine"
    scene.collection.objects.link(copy)
    copy.scale = (0.5, 0.5, 0.5)  # the user's edit
    bpy.data.objects.remove(probe)

    _api().setup_mirror(water, scene)
    fresh = mirror.find_probe(water)
    assert fresh is not None and fresh != copy
    assert tuple(copy.scale) == (0.5, 0.5, 0.5)


def test_a_copied_surroundings_collection_is_never_refilled(scene):
    bed = harness.add_cube(scene, (0.0, 0.0, -1.0), size=2.0, name="Bed")
    added = _api().add_water(scene, size=8, resolution=8, mirror_setup=False)
    water = added.object
    surroundings = harness.addon("water.surroundings")
    own = surroundings.surroundings_collection(water)
    assert bed.name in own.objects
    copy = own.copy()  # "Surroundings of Water.001", holding the bed too
    copy.name = "Mine"
    other = harness.add_cube(scene, (30.0, 0.0, 5.0), size=1.0, name="Far Away")
    copy.objects.link(other)  # the user's edit: far from the water, never gathered
    copy.use_fake_user = True
    surroundings.remove_surroundings(water)

    _api().set_surroundings(water)
    fresh = surroundings.surroundings_collection(water)
    assert fresh is not None and fresh != copy
    assert sorted(o.name for o in copy.objects) == ["Bed", "Far Away"]
