"""Every feature with every other, on each kind of water, saved and reopened without the add-on.

One scene per combination the panel allows: waves (the lake's choice; the seeds' ocean always
has them, the open sea has the Ocean modifier), surroundings (a bed, a post, and a boat reaching
below the surface when the water is added), the shader's caustics, Physical Caustics (lake water
with surroundings), floating objects (a buoy, and that boat, which was in the surroundings) and
repair (the water's group taken away, then repaired). Every scene is rendered (Cycles, tiny, one
sample: the same picture for the same data), the file saved, reopened with the add-on disabled
and scripts off, and rendered again. Blender prints "Dependency cycle" when it meets one: the
test reads its output throughout.
"""

import itertools

import addon_utils
import bpy
import numpy as np
import pytest

import harness

pytestmark = pytest.mark.render


def _api():
    return harness.addon("api")


def _combinations():
    for kind in ("lake", "ocean", "open_sea"):
        waves = (False, True) if kind == "lake" else (kind == "ocean",)
        for wave, surroundings, caustics, floating, repair in itertools.product(
            waves, (False, True), (0.0, 1.0), (False, True), (False, True)
        ):
            physical = (False, True) if kind == "lake" and surroundings else (False,)
            for cycles_caustics in physical:
                yield {
                    "kind": kind,
                    "waves": wave,
                    "surroundings": surroundings,
                    "caustics": caustics,
                    "physical": cycles_caustics,
                    "floating": floating,
                    "repair": repair,
                }


COMBINATIONS = list(_combinations())


def _name(combo):
    flags = [k for k in ("waves", "surroundings", "physical", "floating", "repair") if combo[k]]
    flags += ["caustics"] if combo["caustics"] else []
    return "-".join([combo["kind"], *flags])


def _build(combo):
    scene = bpy.data.scenes.new(_name(combo))
    scene.render.engine = "CYCLES"
    scene.render.resolution_x, scene.render.resolution_y = 24, 16
    scene.render.resolution_percentage = 100
    scene.cycles.samples = 1
    scene.cycles.use_denoising = False
    scene.cycles.seed = 1
    scene.view_settings.view_transform = "Standard"
    scene.frame_set(5)
    light = bpy.data.lights.new(f"Sun {scene.name}", "SUN")
    sun = bpy.data.objects.new(f"Sun {scene.name}", light)
    scene.collection.objects.link(sun)
    sun.rotation_euler = (0.7, 0.1, 2.3)
    harness.add_camera(scene, (9.0, -7.0, 6.0), (0.0, 0.0, 0.0), lens=24.0)
    if combo["surroundings"]:
        harness.add_cube(scene, (0.0, 0.0, -3.0), size=6.0, name=f"Bed {scene.name}").scale = (2, 2, 0.5)
        harness.add_cube(scene, (2.0, -2.0, 0.0), size=0.4, name=f"Post {scene.name}").scale = (1, 1, 6)
    boat = (
        harness.add_cube(scene, (-1.5, 1.0, 0.0), size=1.2, name=f"Boat {scene.name}")
        if combo["floating"]
        else None
    )
    buoy = (
        harness.add_cube(scene, (1.5, 2.0, 1.0), size=0.4, name=f"Buoy {scene.name}")
        if combo["floating"]
        else None
    )
    values = {"caustics": combo["caustics"]}
    if combo["kind"] == "open_sea":
        values.update(sea_wind_speed=3.0, size=200.0, resolution=48)
    else:
        values.update(size=12.0, resolution=16, waves=combo["waves"])
    added = _api().add_water(
        scene,
        preset=combo["kind"],
        name=f"Water {scene.name}",
        see_surroundings=combo["surroundings"],
        **values,
    )
    water = added.object
    if combo["physical"]:
        _api().set_physical_caustics(water, True, scene)
    if combo["floating"]:
        _api().float_on_water(boat, water)
        _api().float_on_water(buoy, water, tilt_damping=0.5)
    if combo["repair"]:
        _break_and_repair(added.material, scene)
    return scene, water


def _break_and_repair(material, scene):
    """The user gives the water a copy of its group with an input removed (one still at its
    default, so the repaired water should look as before), then repairs it."""
    node = next(n for n in material.node_tree.nodes if n.type == "GROUP" and n.node_tree)
    tree = node.node_tree.copy()
    node.node_tree = tree
    defaults = {
        item.name: item.default_value
        for item in tree.interface.items_tree
        if item.item_type == "SOCKET" and item.in_out == "INPUT" and item.socket_type == "NodeSocketFloat"
    }
    name = next(s.name for s in node.inputs if s.name in defaults and s.default_value == defaults[s.name])
    tree.interface.remove(tree.interface.items_tree[name])
    repair = harness.addon("water.repair")
    assert repair.needs_repair(material)
    repair.repair_water(material, scene)
    assert repair.needs_repair(material) is None


def _render_all(directory):
    pictures = {}
    for scene in sorted(bpy.data.scenes, key=lambda s: s.name):
        if scene.name == "Scene":
            continue
        path = directory / f"{scene.name}.exr"
        pictures[scene.name] = harness.render(scene, path, exr=True)
    return pictures


@pytest.fixture(scope="module")
def composed(addon, tmp_path_factory):
    directory = tmp_path_factory.mktemp("compose")
    harness.clean_scene()

    def build_all():
        return [_build(combo) for combo in COMBINATIONS]

    output, built = harness.blender_output(build_all)
    seen = {}  # the objects each water sees, by name (data-blocks go when the file is reopened)
    values = {scene.name: _api().read_values(water) for scene, water in built}
    for scene, water in built:
        collection = harness.addon("water.surroundings").surroundings_collection(water)
        seen[scene.name] = [o.name for o in collection.all_objects] if collection is not None else []
    printed, before = harness.blender_output(lambda: _render_all(directory / "before"))
    output += printed
    path = directory / "composed.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    addon_utils.disable(harness.ADDON_MODULE, default_set=True)
    bpy.context.preferences.filepaths.use_scripts_auto_execute = False
    try:
        bpy.ops.wm.open_mainfile(filepath=str(path))
        printed, after = harness.blender_output(lambda: _render_all(directory / "after"))
        output += printed
    finally:
        bpy.context.preferences.filepaths.use_scripts_auto_execute = True
        addon_utils.enable(harness.ADDON_MODULE, default_set=True)
    return {"output": output, "before": before, "after": after, "seen": seen, "values": values}


def test_every_combination_is_built_and_rendered(composed):
    names = {_name(combo) for combo in COMBINATIONS}
    assert len(names) == len(COMBINATIONS) == 80
    assert set(composed["before"]) == names and set(composed["after"]) == names


def test_no_combination_makes_a_dependency_cycle(composed):
    assert "Dependency cycle" not in composed["output"]
    assert "dependency cycles" not in composed["output"]


def test_a_floating_boat_is_never_in_its_waters_surroundings(composed):
    for name, seen in composed["seen"].items():
        assert not [o for o in seen if o.startswith(("Boat", "Buoy"))], name
        if "surroundings" in name:
            assert any(o.startswith("Bed") for o in seen), name


def test_each_combination_renders_the_same_without_the_add_on(composed):
    for name, before in composed["before"].items():
        after = composed["after"][name]
        assert np.isfinite(before).all() and np.isfinite(after).all(), name
        assert before[..., :3].max() > 0.0, f"{name} renders black"
        assert np.abs(after - before).max() < 1e-4, name


def test_the_features_show_in_the_pictures(composed):
    """The renders are of the scenes built (a control for the comparison above): a floating boat, the
    bed seen through the water and the kinds of water each change the picture."""
    before = composed["before"]

    def differ(a, b):
        return np.abs(before[a] - before[b]).max() > 0.02

    assert differ("lake", "lake-floating")
    assert differ("lake", "lake-surroundings")
    assert differ("lake", "ocean-waves") and differ("ocean-waves", "open_sea")
    distinct = {np.round(picture, 2).tobytes() for picture in before.values()}
    assert len(distinct) >= 20


def test_a_repaired_water_renders_as_it_did_before_it_broke(composed):
    before = composed["before"]
    repaired = [name for name in before if "-repair" in name]
    assert len(repaired) == 40
    # Another scene, other object names: Cycles' one sample lands differently on a few pixels
    # (it hashes names), so the twin is compared on the whole picture, not pixel by pixel; with
    # Physical Caustics, one sample of manifold caustics is all fireflies: their values compare.
    for name in repaired:
        twin = name.replace("-repair", "")
        assert composed["values"][name] == composed["values"][twin], name
        if "physical" not in name:
            assert np.abs(before[name] - before[twin]).mean() < 0.01, name
