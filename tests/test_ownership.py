"""The add-on reuses or upgrades only what it made; adding is all or nothing; one add pipeline.

Each test is a row of "Never lose the user's data": the user's own data-blocks
with the add-on's names, images lost or renamed, probes moved or deleted,
linked libraries, and the same water from the operator, the API and the CLI.
"""

import bpy
import numpy as np
import pytest

import harness


def _api():
    return harness.addon("api")


def _snapshot():
    kinds = ("objects", "meshes", "materials", "node_groups", "images", "lightprobes", "worlds")
    kinds += ("collections",)
    return {kind: sorted(b.name for b in getattr(bpy.data, kind)) for kind in kinds}


def _activate(obj):
    for other in bpy.context.view_layer.objects.selected:
        other.select_set(False)
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj


def _pixels(image):
    pixels = np.empty(len(image.pixels), dtype=np.float32)
    image.pixels.foreach_get(pixels)
    return pixels


def _user_shader_group():
    """A user's own five-node shader group named like ours, with inputs of its own."""
    tree = bpy.data.node_groups.new("Water Surface", "ShaderNodeTree")
    tree.interface.new_socket("Murk", in_out="INPUT", socket_type="NodeSocketFloat")
    tree.interface.new_socket("BSDF", in_out="OUTPUT", socket_type="NodeSocketShader")
    kinds = ("NodeGroupInput", "NodeGroupOutput", "ShaderNodeBsdfDiffuse", "ShaderNodeMath", "ShaderNodeMix")
    for kind in kinds:
        tree.nodes.new(kind)
    return tree


def test_users_groups_named_like_ours_are_never_changed(scene):
    mine = _user_shader_group()
    waves = bpy.data.node_groups.new("Water Waves", "GeometryNodeTree")
    for kind in ("NodeGroupInput", "NodeGroupOutput", "GeometryNodeSetPosition"):
        waves.nodes.new(kind)
    material = bpy.data.materials.new("User Material")
    if bpy.app.version < (5, 0, 0):
        material.use_nodes = True
    node = material.node_tree.nodes.new("ShaderNodeGroup")
    node.node_tree = mine
    node.inputs["Murk"].default_value = 0.25

    added = _api().add_water(scene, size=8, resolution=8, waves=True)
    ours = added.material.node_tree.nodes["Water Surface"].node_tree
    assert ours != mine and ours.name != "Water Surface" and ours.library is None
    assert len(mine.nodes) == 5 and sorted(i.name for i in mine.interface.items_tree) == ["BSDF", "Murk"]
    assert "water_surface_version" not in mine and "water_surface_version" not in waves
    assert node.inputs["Murk"].default_value == pytest.approx(0.25)
    assert len(waves.nodes) == 3
    modifier = harness.addon("water.waves").wave_modifier(added.object)
    assert modifier.node_group not in (waves, None)
    # Adding again reuses ours, never the user's, never a third.
    count = len(bpy.data.node_groups)
    again = _api().add_water(scene, size=8, resolution=8, waves=True)
    assert again.material.node_tree.nodes["Water Surface"].node_tree == ours
    assert len(bpy.data.node_groups) == count


def test_a_users_geometry_nodes_group_named_water_waves_is_left_to_the_user(scene):
    added = _api().add_water(scene, size=8, resolution=8)
    water = added.object
    theirs = bpy.data.node_groups.new("Water Waves (mine)", "GeometryNodeTree")
    theirs.interface.new_socket("Geometry", in_out="INPUT", socket_type="NodeSocketGeometry")
    theirs.interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")
    user_modifier = water.modifiers.new("Mine", "NODES")
    user_modifier.node_group = theirs
    _activate(water)
    assert bpy.ops.object.water_mirror_setup() == {"FINISHED"}  # no KeyError
    assert bpy.ops.object.water_waves_add() == {"FINISHED"}
    assert user_modifier.node_group == theirs and theirs.users >= 1
    ours = harness.addon("water.waves").wave_modifier(water)
    assert ours is not None and ours != user_modifier and ours.node_group != theirs


def test_a_users_image_named_like_our_bump_keeps_its_pixels(scene):
    theirs = bpy.data.images.new("Water Surface Bump", 16, 16)
    theirs.colorspace_settings.name = "sRGB"
    theirs.pixels.foreach_set(np.full(16 * 16 * 4, 0.75, dtype=np.float32))
    before = _snapshot()["objects"]
    added = _api().add_water(scene, size=8)
    assert np.allclose(_pixels(theirs), 0.75, atol=1 / 255) and theirs.colorspace_settings.name == "sRGB"
    bump = harness.addon("nodes.material").bump_image(added.material)
    assert bump != theirs and bump.size[:] == (512, 512) and bump.packed_file is not None
    made = [
        added.object.name,
        *(f"{added.object.name} {part}" for part in ("Mirror", "Surroundings", "Underwater")),
    ]
    assert _snapshot()["objects"] == sorted([*before, *made])


def test_an_unpacked_bump_whose_folder_is_gone_is_made_again(scene, tmp_path):
    first = _api().add_water(scene, size=8).object.name
    path = tmp_path / "shot.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    bpy.ops.file.unpack_all(method="WRITE_LOCAL")
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    for texture in (tmp_path / "textures").iterdir():
        texture.unlink()
    (tmp_path / "textures").rmdir()
    bpy.ops.wm.open_mainfile(filepath=str(path))
    before = set(o.name for o in bpy.data.objects)
    added = _api().add_water(bpy.context.scene, size=8, location=(20, 0, 0))
    bump = harness.addon("nodes.material").bump_image(added.material)
    assert bump.packed_file is not None and bump.has_data
    old_water = bpy.data.objects[first]
    assert harness.addon("nodes.material").bump_image(old_water.active_material) == bump
    assert len([i for i in bpy.data.images if i.get("water_surface_bump_version")]) == 1
    made = set(o.name for o in bpy.data.objects) - before
    assert made == {
        added.object.name,
        *(f"{added.object.name} {part}" for part in ("Mirror", "Surroundings", "Underwater")),
    }


def test_a_failed_add_leaves_nothing_behind_and_says_why_in_one_line(scene):
    # A file from a newer add-on whose wave group lacks the inputs this one reads: the add fails late,
    # after the object, mesh, material, groups, image and probe exist.
    newer = bpy.data.node_groups.new("Water Waves", "GeometryNodeTree")
    newer["water_surface_version"] = 999
    newer["water_surface_role"] = "Water Waves"
    newer.interface.new_socket("Geometry", in_out="INPUT", socket_type="NodeSocketGeometry")
    newer.interface.new_socket("Geometry", in_out="OUTPUT", socket_type="NodeSocketGeometry")
    scene.world = None
    before = _snapshot()
    engine = scene.render.engine
    with pytest.raises(harness.addon("water.plane").AddWaterError) as error:
        _api().add_water(scene, size=8, resolution=8, waves=True)
    assert "\n" not in str(error.value) and "nothing was added" in str(error.value)
    assert _snapshot() == before
    assert scene.world is None and scene.render.engine == engine
    # The operator reports the same line and cancels.
    with pytest.raises(RuntimeError, match="nothing was added"):
        bpy.ops.object.water_add(size=8, resolution=8, waves=True)
    assert _snapshot() == before


def _library(tmp_path):
    """A library .blend holding a lake and a collection; returns its path."""
    harness.clean_scene()
    _api().add_water(bpy.context.scene, size=8)
    bpy.data.collections.new("Library Shelf")
    bpy.context.scene.collection.children.link(bpy.data.collections["Library Shelf"])
    path = tmp_path / "library.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    harness.clean_scene()
    return path


def test_linked_groups_and_images_are_never_reused_for_new_water(scene, tmp_path):
    path = _library(tmp_path)
    with bpy.data.libraries.load(str(path), link=True) as (data_from, data_to):
        data_to.node_groups = list(data_from.node_groups)
        data_to.images = list(data_from.images)
    assert all(group.library is not None for group in bpy.data.node_groups)
    added = _api().add_water(bpy.context.scene, size=8, resolution=8, waves=True)
    group = added.material.node_tree.nodes["Water Surface"].node_tree
    assert group.library is None
    assert all(node.node_tree.library is None for node in group.nodes if node.type == "GROUP")
    assert harness.addon("nodes.material").bump_image(added.material).library is None
    assert harness.addon("water.waves").wave_modifier(added.object).node_group.library is None


def test_long_normal_map_names_reuse_one_group(scene):
    material = harness.addon("nodes.material")
    image = bpy.data.images.new("R" * 70, 8, 8)
    first = material.water_group(image)
    count = len(bpy.data.node_groups)
    for _ in range(3):
        assert material.water_group(image) == first
    assert len(bpy.data.node_groups) == count


def test_renamed_or_replaced_normal_maps_are_sampled_as_they_are(scene):
    material = harness.addon("nodes.material")
    image = bpy.data.images.new("Ripples", 8, 8)
    group = material.water_group(image)
    image.name = "Ripples Renamed"
    assert material.water_group(image) == group  # found by its image, not its name
    bpy.data.images.remove(image)
    replacement = bpy.data.images.new("Ripples Renamed", 8, 8)
    again = material.water_group(replacement)
    images = {node.image for node in again.nodes if node.type == "TEX_IMAGE"}
    assert images == {replacement}


def test_one_probe_per_water_whatever_the_user_did_to_it(scene):
    mirror = harness.addon("water.mirror")
    water = _api().add_water(scene, size=8).object
    probe = mirror.find_probe(water)
    probe.parent = None  # unparented
    _api().setup_mirror(water, scene)
    probes = [o for o in bpy.data.objects if o.type == "LIGHT_PROBE"]
    assert probes == [probe] and probe.parent == water
    other = bpy.data.objects.new("Pivot", None)
    scene.collection.objects.link(other)
    probe.parent = other  # parented elsewhere
    _api().setup_mirror(water, scene)
    assert [o for o in bpy.data.objects if o.type == "LIGHT_PROBE"] == [probe] and probe.parent == water
    bpy.data.objects.remove(probe)  # deleted: its data would be orphaned
    _api().setup_mirror(water, scene)
    assert len([o for o in bpy.data.objects if o.type == "LIGHT_PROBE"]) == 1
    assert len(bpy.data.lightprobes) == 1 and bpy.data.lightprobes[0].users == 1


def test_the_add_ons_sky_world_is_reused(scene):
    scene.world = None
    water = _api().add_water(scene, size=8).object
    sky = scene.world
    scene.world = None
    _api().setup_mirror(water, scene)
    assert scene.world == sky and len(bpy.data.worlds) == 1


def test_set_up_mirror_gives_an_ocean_no_probe(scene):
    ocean = _api().add_water(scene, preset="ocean", size=8, resolution=8).object
    assert _api().setup_mirror(ocean, scene) == []
    _activate(ocean)
    assert bpy.ops.object.water_mirror_setup() == {"FINISHED"}
    assert not [o for o in bpy.data.objects if o.type == "LIGHT_PROBE"]


def _describe(water):
    """What makes two waters the same: values, mesh, material groups, modifiers, probe."""
    material = water.active_material
    groups = sorted(
        (n.node_tree.get("water_surface_role"), n.node_tree.get("water_surface_version"))
        for n in material.node_tree.nodes
        if n.type == "GROUP"
    )
    modifiers = [(m.type, m.node_group.get("water_surface_role")) for m in water.modifiers]
    probe = harness.addon("water.mirror").find_probe(water)
    return {
        "values": {
            k: v if isinstance(v, bool) else np.round(v, 5).tolist()  # `underwater` is a bool
            for k, v in _api().read_values(water).items()
        },
        "vertices": len(water.data.vertices),
        "rest plane": np.round(harness.addon("water.mirror").rest_bounds(water), 4).tolist(),
        "groups": groups,
        "modifiers": modifiers,
        "probe": None if probe is None else np.round(tuple(probe.scale), 4).tolist(),
        "material": (material.surface_render_method, material.use_raytrace_refraction),
    }


def test_operator_cli_and_api_give_the_same_water(scene, tmp_path):
    values = {"preset": "windy_river", "size": 12.0, "resolution": 16, "wave_height": 0.4, "waves": True}
    bpy.ops.object.water_add(**values)
    from_operator = _describe(bpy.context.active_object)
    harness.clean_scene()
    from_api = _describe(_api().add_water(bpy.context.scene, **values).object)
    harness.clean_scene()
    empty, out = tmp_path / "empty.blend", tmp_path / "out.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(empty))
    argv = ["add", str(empty), str(out), "--preset", "windy_river", "--size", "12", "--resolution", "16"]
    assert harness.addon("cli").main([*argv, "--wave-height", "0.4", "--waves"]) == 0
    bpy.ops.wm.open_mainfile(filepath=str(out))
    from_cli = _describe(next(o for o in bpy.data.objects if _api().is_water(o)))
    assert from_operator == from_api == from_cli
