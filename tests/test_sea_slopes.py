"""The open sea's slopes are the sea's: Cox and Munk's mean square slopes for the wind, larger
upwind than crosswind, following the wind speed and direction set in the panel (drivers on the
Ocean modifier's settings: simple expressions, so farms and auto-run off keep them)."""

import bpy
import numpy as np
import pytest
from reference_models import cox_munk

import harness

PIXEL = 0.05  # metres a pixel, straight down
SIDE = 256  # pixels: a 12.8 m patch (a 6.4 m one varies by 20% from place to place)
# Two diagonals, neither along an axis of the grid or the bump's frame: the bump's raw slopes lean
# along the first (`ocean_normal.BUMP_SLOPE_COVARIANCE`), so each would favour one of them.
WINDS = [(0.6, 0.8), (-0.8, 0.6)]


def _api():
    return harness.addon("api")


def _slopes_seen(scene, sea, render, name, wind):
    """(upwind, crosswind) mean square slopes of the shading normal (Debug View 4) straight down."""
    _normal, shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.active_material)
    shade.inputs["Debug View"].default_value = 4
    n = render(scene, name, exr=True)[..., :3].reshape(-1, 3) * 2.0 - 1.0
    slopes = -n[:, :2] / n[:, 2:3]
    along = slopes @ np.array(wind)
    across = slopes @ np.array((-wind[1], wind[0]))
    return float(np.mean(along**2)), float(np.mean(across**2))


@pytest.mark.render
@pytest.mark.parametrize("direction", WINDS)
@pytest.mark.parametrize("wind", [5.0, 15.0])
def test_the_sea_s_slopes_are_cox_and_munk_s_upwind_larger(addon, eevee, render, wind, direction):
    scene = harness.clean_scene(engine=eevee, width=SIDE, height=SIDE, samples=1)
    harness.set_world_color(scene, (0.5, 0.6, 0.8))
    added = _api().add_water(
        scene, preset="open_sea", sea_wind_speed=wind, wind_direction=direction, see_surroundings=False
    )
    camera = bpy.data.objects.new("Down", bpy.data.cameras.new("Down"))
    camera.data.type, camera.data.ortho_scale, camera.data.clip_end = "ORTHO", PIXEL * SIDE, 200.0
    camera.location = (3.0, -2.0, 30.0)  # away from the centre, inside the waves' middle
    scene.collection.objects.link(camera)
    scene.camera = camera
    up, cross = _slopes_seen(scene, added.object, render, f"down-{wind:g}-{direction[0]:g}", direction)
    theirs = cox_munk(wind)
    total, expected = up + cross, sum(theirs)
    print(f"{wind} m/s: upwind {up:.4f} crosswind {cross:.4f} total {total:.4f}; Cox-Munk {theirs}")
    assert abs(total / expected - 1.0) < 0.35
    assert up > cross
    # And the split: each within 35% of theirs (their ratio is 1.25 at 5 m/s, 1.49 at 15).
    assert up / theirs[0] == pytest.approx(1.0, abs=0.35) and cross / theirs[1] == pytest.approx(
        1.0, abs=0.35
    )


@pytest.mark.lts
def test_the_slopes_follow_the_wind_set_in_the_panel(scene):
    added = _api().add_water(scene, preset="open_sea", sea_wind_speed=5.0, see_surroundings=False)
    normal, _shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material)
    ocean, _fade = harness.addon("water.sea.open_sea").sea_modifiers(added.object)
    sea_math = harness.addon("water.sea.sea_math")

    def evaluated():
        depsgraph = bpy.context.evaluated_depsgraph_get()
        depsgraph.update()
        ocean_material = harness.addon("nodes.sea.ocean_material")
        node = ocean_material.ocean_nodes(added.material.evaluated_get(depsgraph))[0]
        return {
            name: node.inputs[name].default_value for name in ("Slope Along Wind", "Slope Across Wind")
        }, tuple(node.inputs["Wind Direction"].default_value)

    for speed, angle in ((5.0, ocean.wave_direction), (20.0, 0.7)):
        ocean.wind_velocity, ocean.wave_direction = speed, angle
        slopes, direction = evaluated()
        up, cross = cox_munk(speed)
        assert slopes["Slope Along Wind"] ** 2 == pytest.approx(up, rel=1e-3)
        assert slopes["Slope Across Wind"] ** 2 == pytest.approx(cross, rel=1e-3)
        assert direction[:2] == pytest.approx(sea_math.angle_direction(angle), abs=1e-5)
    drivers = added.material.node_tree.animation_data.drivers
    assert drivers and all(fc.driver.is_simple_expression for fc in drivers)


def test_repair_gives_the_sea_its_wind_drivers_back(scene):
    added = _api().add_water(scene, preset="open_sea", sea_wind_speed=9.0, see_surroundings=False)
    normal, _shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material)
    tree = normal.node_tree
    tree.interface.remove(
        next(i for i in tree.interface.items_tree if getattr(i, "name", "") == "Tex Stretch")
    )
    repair = harness.addon("water.repair")
    assert repair.needs_repair(added.material) is not None
    repair.repair_water(added.material, scene)
    assert repair.needs_repair(added.material) is None
    depsgraph = bpy.context.evaluated_depsgraph_get()
    depsgraph.update()
    node = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material.evaluated_get(depsgraph))[0]
    up, cross = harness.addon("water.sea.sea_math").cox_munk_slopes(9.0)
    assert node.inputs["Slope Along Wind"].default_value ** 2 == pytest.approx(up, rel=1e-3)
    assert node.inputs["Slope Across Wind"].default_value ** 2 == pytest.approx(cross, rel=1e-3)
    assert node.inputs["Even Slopes"].default_value == 1.0
