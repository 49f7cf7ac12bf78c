"""The open sea's state: a fully grown sea's heights and periods for its wind, and a swell.

Measured on the evaluated mesh (the add-on's sea: both Ocean modifiers under the fade), over time
at the points within a quarter tile of the centre, where nothing fades: the significant height is
4 standard deviations of the heights, the peak period the peak of their periodogram (averaged
over the points, smoothed over a few of its bins). A fully grown sea (Pierson and Moskowitz) has
a significant height of 0.21 U^2 / g and a peak period of 2 pi U / (0.877 g) at a wind of U m/s.
The winds and the swell are not along an axis, and the swell's not along the wind's.
"""

import math

import bpy
import numpy as np
import pytest
from reference_models import deep_water_wavelength, pm_peak_period, pm_significant_height
from test_repair import draw_panel

import harness

WIND = (0.8, 0.6)
SWELL = (-0.28, 0.96)  # 53 degrees from the wind


def _api():
    return harness.addon("api")


def _open_sea(scene, **values):
    values.setdefault("wind_direction", WIND)
    values.setdefault("see_surroundings", False)
    return _api().add_water(scene, preset="open_sea", **values).object


def _points(obj):
    """(rest xy, evaluated positions) of the evaluated mesh's points."""
    mesh = obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    rest = np.zeros(len(mesh.vertices) * 3)
    mesh.attributes["water_rest"].data.foreach_get("vector", rest)
    position = np.zeros(len(mesh.vertices) * 3)
    mesh.vertices.foreach_get("co", position)
    return rest.reshape(-1, 3)[:, :2], position.reshape(-1, 3)


def _record(scene, sea, step, steps, inner):
    """Heights (steps, points) of the points `inner` every `step` seconds (a frame a step)."""
    scene.render.fps, scene.render.fps_base = 1, step
    heights = []
    for frame in range(steps):
        scene.frame_set(frame)
        heights.append(_points(sea)[1][inner, 2])
    scene.render.fps, scene.render.fps_base = 24, 1.0
    return np.array(heights)


def _spectrum(heights, step):
    """(frequencies, the points' mean periodogram): Hann window, each point's mean taken out."""
    heights = heights - heights.mean(axis=0)
    window = np.hanning(len(heights))[:, None]
    power = (np.abs(np.fft.rfft(heights * window, axis=0)) ** 2).mean(axis=1)
    return np.fft.rfftfreq(len(heights), step)[1:], power[1:]


def _fitted_peak_period(frequency, power, guess):
    """Seconds: the peak period of the Pierson-Moskowitz spectrum a f^-5 exp(-1.25 (fp / f)^4)
    nearest the periodogram (least squares, fp searched from half to twice 1 / `guess`). The
    periodogram's own highest bin wanders with the few waves near the peak a tile holds (0.81 to
    1.25 of the peak period over six seeds); the fitted one stayed within 5%."""
    best = None
    for peak in np.linspace(0.5, 2.0, 301) / guess:
        shape = frequency**-5.0 * np.exp(-1.25 * (peak / frequency) ** 4)
        scale = (shape @ power) / (shape @ shape)
        misfit = ((power - scale * shape) ** 2).sum()
        if best is None or misfit < best[0]:
            best = (misfit, peak)
    return 1.0 / best[1]


def _inner(sea, share=0.25):
    """The points within `share` of a tile of the centre (where nothing fades)."""
    ocean, _fade = harness.addon("water.sea.open_sea").sea_modifiers(sea)
    rest, _position = _points(sea)
    return np.hypot(rest[:, 0], rest[:, 1]) < share * ocean.spatial_size


# Blender's spectrum is its own code, which may differ between versions: one wind on the LTS too.
@pytest.mark.parametrize("wind", [5.0, pytest.param(10.0, marks=pytest.mark.lts), 15.0])
def test_a_grown_sea_s_significant_height_and_peak_period(scene, wind):
    """Over 30 peak periods, 6 frames a period: 4 standard deviations of the heights within 15%
    of 0.21 U^2 / g, the peak period of the periodogram (a Pierson-Moskowitz spectrum fitted to
    it) within 15% of 2 pi U / (0.877 g), the mean period T-1,0 = m-1 / m0 that of Pierson
    and Moskowitz's shape (0.857 of the peak period) within 10%, and the waves of the peak period
    travel downwind (the plane wave most like them within 45 degrees of the wind)."""
    sea = _open_sea(scene, resolution=33, sea_wind_speed=wind)
    inner = _inner(sea)
    target_period = pm_peak_period(wind)
    target_height = pm_significant_height(wind)
    step = target_period / 6
    heights = _record(scene, sea, step, 180, inner)
    height = 4 * heights.std()
    frequency, power = _spectrum(heights, step)
    period = _fitted_peak_period(frequency, power, target_period)
    highest = 1.0 / frequency[np.argmax(np.convolve(power, np.ones(3) / 3, mode="same"))]
    mean_period = (power / frequency).sum() / power.sum()
    xy = _points(sea)[0][inner]
    peak_length = deep_water_wavelength(target_period)
    times = np.arange(len(heights)) * step
    _length, travels = _local_plane_wave(xy, heights, times, period, peak_length)
    off = math.degrees(math.acos(np.clip(travels @ (np.array(WIND) / np.hypot(*WIND)), -1.0, 1.0)))
    print(
        f"{wind:g} m/s, {inner.sum()} points: Hs {height:.3f} m = {height / target_height:.3f} of "
        f"{target_height:.3f} m; Tp {period:.2f} s = {period / target_period:.3f} of {target_period:.2f} s"
        f" (the periodogram's highest bin {highest / target_period:.3f}); "
        f"T-1,0 {mean_period / period:.3f} of Tp; its waves travel {off:.0f} degrees off the wind"
    )
    assert height == pytest.approx(target_height, rel=0.15)
    assert period == pytest.approx(target_period, rel=0.15)
    assert mean_period / period == pytest.approx(0.857, rel=0.10)
    assert off < 45.0, "downwind (the spread about the wind is cos^1.5)"


def _local_plane_wave(xy, heights, times, period, wavelength):
    """The plane wave of `period` most like the heights: (wavelength, unit direction it travels).

    The heights' complex amplitude at the period's frequency at each point (exp(i k.x) for waves
    cos(k.x - w t)), then the k of the plane wave most like it, searched over 0.5 to 2 times
    `wavelength` and every direction."""
    amplitude = (heights * np.exp(2j * math.pi * times / period)[:, None]).sum(axis=0)
    lengths = wavelength * np.exp(np.linspace(math.log(0.5), math.log(2.0), 121))
    angles = np.radians(np.arange(0.0, 360.0, 1.0))
    k = 2 * math.pi / lengths[:, None]
    kx, ky = (k * np.cos(angles)).ravel(), (k * np.sin(angles)).ravel()
    match = np.abs(np.exp(-1j * (np.outer(kx, xy[:, 0]) + np.outer(ky, xy[:, 1]))) @ amplitude)
    best = np.argmax(match)
    size = math.hypot(kx[best], ky[best])
    return 2 * math.pi / size, np.array((kx[best], ky[best])) / size


def _tile_spectrum(scene, modifier):
    """(power, kx, ky) of the heights `modifier`'s settings give over its whole tile: a copy of it
    on a grid of its FFT's own cells, evaluated at the scene's frame."""
    open_sea = harness.addon("water.sea.open_sea")
    cells = modifier.resolution**2
    tile = modifier.spatial_size
    axis = np.arange(cells) * tile / cells
    x, y = np.meshgrid(axis, axis)
    mesh = bpy.data.meshes.new("Tile")
    mesh.vertices.add(x.size)
    mesh.vertices.foreach_set("co", np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)]).ravel())
    grid = bpy.data.objects.new("Tile", mesh)
    scene.collection.objects.link(grid)
    copy = grid.modifiers.new("Copy", "OCEAN")
    open_sea.copy_settings(modifier, copy)
    copy.time = modifier.time
    evaluated = grid.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    co = np.zeros(len(evaluated.vertices) * 3)
    evaluated.vertices.foreach_get("co", co)
    bpy.data.objects.remove(grid)
    bpy.data.meshes.remove(mesh)
    power = np.abs(np.fft.fft2(co[2::3].reshape(cells, cells))) ** 2  # rows: y, columns: x
    k = 2 * math.pi * np.fft.fftfreq(cells, tile / cells)
    kx, ky = np.meshgrid(k, k)
    return power, kx, ky


def test_a_swell_s_wavelength_direction_and_height_on_top_of_the_wind_sea(scene):
    """A 9 s swell (126 m in deep water) travelling along SWELL over a 15 m/s sea along WIND.
    The stack is swell, sea, fade; on the evaluated mesh the heights are the sea's and the
    swell's added (each alone: the other modifier hidden). The swell alone, within a quarter
    tile of the sea's middle over three periods at 8 frames a period: its significant height the
    asked 2 m within 15%, and its waves travel along SWELL (the plane wave of its period most like
    them, within 20 degrees). Over its whole tile (its modifier's copy on a grid of its cells,
    where every one of its waves shows): its mean wavelength (power-weighted wave number) is
    g T^2 / 2 pi within 10% and its mean direction SWELL within 10 degrees. (The middle's 430 m
    hold three swell waves, too few for its length: there seed 0's nearest plane wave is 0.89 of
    it, over its whole tile 0.97; the spectrum is 6.5% wide in wave number.)"""
    period, height = 9.0, 2.0
    sea = _open_sea(
        scene,
        resolution=129,
        sea_wind_speed=15.0,
        sea_swell_height=height,
        sea_swell_period=period,
        sea_swell_direction=SWELL,
    )
    open_sea = harness.addon("water.sea.open_sea")
    ocean, _fade = open_sea.sea_modifiers(sea)
    swell = open_sea.swell_modifier(sea)
    assert [m.name for m in sea.modifiers][:3] == ["Water Swell", "Water Ocean", "Water Sea Fade"]
    inner = _inner(sea)
    scene.frame_set(7)
    both = _points(sea)[1][inner, 2]
    ocean.show_viewport = False
    swell_alone = _points(sea)[1][inner, 2]
    ocean.show_viewport, swell.show_viewport = True, False
    sea_alone = _points(sea)[1][inner, 2]
    swell.show_viewport = True
    apart = np.abs(both - swell_alone - sea_alone).max()
    print(f"the sum's largest difference from the two alone: {apart:.2e} m")
    assert apart < 1e-3 * np.abs(both).max()
    assert np.abs(sea_alone).max() > 1.0 and np.abs(swell_alone).max() > 1.0

    ocean.show_viewport = False
    steps, step = 24, period / 8
    heights = _record(scene, sea, step, steps, inner)
    ocean.show_viewport = True
    xy = _points(sea)[0][inner]
    expected = deep_water_wavelength(period)
    local, travels = _local_plane_wave(xy, heights, np.arange(steps) * step, period, expected)
    unit = np.array(SWELL) / np.hypot(*SWELL)
    off = math.degrees(math.acos(np.clip(travels @ unit, -1.0, 1.0)))
    found = 4 * heights.std()

    power, kx, ky = _tile_spectrum(scene, swell)
    k = np.hypot(kx, ky)
    mean_length = 2 * math.pi * power.sum() / (power * k).sum()
    side = np.sign(kx * unit[0] + ky * unit[1])  # each wave and its mirror counted once, on SWELL's side
    mean_x = (power * side * kx / np.maximum(k, 1e-12)).sum()
    mean_y = (power * side * ky / np.maximum(k, 1e-12)).sum()
    mean_off = math.degrees(math.atan2(unit[0] * mean_y - unit[1] * mean_x, unit @ (mean_x, mean_y)))
    print(
        f"swell {period:g} s: Hs {found:.2f} m of {height:g}; the middle's plane wave {local:.1f} m "
        f"({local / expected:.3f}), travelling {off:.1f} degrees off; over its tile: mean wavelength "
        f"{mean_length:.1f} m = {mean_length / expected:.3f} of {expected:.1f}, "
        f"direction {mean_off:+.1f} degrees"
    )
    assert found == pytest.approx(height, rel=0.15)
    assert off < 20.0
    assert mean_length == pytest.approx(expected, rel=0.10)
    assert abs(mean_off) < 10.0


def _swell_driver(sea):
    animation = sea.animation_data
    return (
        [f for f in animation.drivers if f.data_path.startswith('modifiers["Water Swell"]')]
        if animation
        else []
    )


def test_the_swell_keys_through_the_operator_panel_and_api_and_height_0_removes_it(scene):
    """The add operator takes the three keys; the panel shows the swell and offers its operator,
    which (as `api.set_swell`) changes what it is given and keeps the rest; a swell the sea was
    added without comes and goes with its height (or `enable`), its time driver with it; a lake
    refuses it."""
    open_sea = harness.addon("water.sea.open_sea")
    assert _open_sea(scene, resolution=17, name="Calm") is not None
    assert open_sea.swell_modifier(bpy.data.objects["Calm"]) is None, "the preset's height 0: no swell"
    result = bpy.ops.object.water_add(
        preset="open_sea",
        resolution=17,
        see_surroundings=False,
        sea_swell_height=1.5,
        sea_swell_period=12.0,
        sea_swell_direction=(0.6, -0.8),
    )
    assert result == {"FINISHED"}
    sea = bpy.context.active_object
    swell = open_sea.swell_modifier(sea)
    sea_math = harness.addon("water.sea.sea_math")
    assert swell.spatial_size == round(sea_math.SWELL_TILE_WAVES * sea_math.wavelength(12.0, 200.0))
    assert sea_math.angle_direction(swell.wave_direction) == pytest.approx((0.6, -0.8))
    assert swell.random_seed == open_sea.sea_modifiers(sea)[0].random_seed
    assert len(_swell_driver(sea)) == 1
    assert ("operator", "object.water_sea_swell", "Swell: 1.5 m, 12 s, to (0.60, -0.80)") in draw_panel()

    assert bpy.ops.object.water_sea_swell(sea_swell_period=8.0) == {"FINISHED"}
    values = open_sea.swell_values(sea)
    assert values["sea_swell_height"] == 1.5 and values["sea_swell_period"] == 8.0
    assert values["sea_swell_direction"] == pytest.approx((0.6, -0.8))
    assert swell.spatial_size == round(sea_math.SWELL_TILE_WAVES * sea_math.wavelength(8.0, 200.0))
    assert "removed" in _api().set_swell(sea, height=0.0)
    assert open_sea.swell_modifier(sea) is None and not _swell_driver(sea)
    assert ("operator", "object.water_sea_swell", "Swell: none") in draw_panel()
    assert "swell of 3 m" in _api().set_swell(sea, height=3.0, direction=SWELL)
    assert [m.name for m in sea.modifiers][:2] == ["Water Swell", "Water Ocean"]
    assert open_sea.swell_values(sea)["sea_swell_period"] == 10.0, "the key's default once removed"
    assert len(_swell_driver(sea)) == 1
    del sea[open_sea.SWELL_PROPERTY]  # read back from the modifier: the height typical for its seed
    read = open_sea.swell_values(sea)
    assert read["sea_swell_period"] == pytest.approx(10.0, rel=0.01)
    assert read["sea_swell_direction"] == pytest.approx(np.array(SWELL) / np.hypot(*SWELL), abs=1e-3)
    assert read["sea_swell_height"] == pytest.approx(3.0, rel=0.25)
    # The switch's off takes the swell away as height 0 does, without asking (no dialog).
    assert bpy.ops.object.water_sea_swell("INVOKE_DEFAULT", enable=False) == {"FINISHED"}
    assert open_sea.swell_modifier(sea) is None and not _swell_driver(sea)
    assert open_sea.SWELL_PROPERTY not in sea
    assert bpy.ops.object.water_sea_swell(enable=False) == {"FINISHED"}, "none to take: said, no error"
    assert bpy.ops.object.water_sea_swell(sea_swell_height=2.0) == {"FINISHED"}
    assert open_sea.swell_values(sea)["sea_swell_height"] == 2.0
    assert bpy.ops.object.water_sea_swell(sea_swell_height=0.0) == {"FINISHED"}
    assert open_sea.swell_modifier(sea) is None and not _swell_driver(sea)
    with pytest.raises(_api().PresetError, match="sea_swell_height"):
        _api().set_swell(sea, height="2")
    lake = _api().add_water(scene, size=4.0, mirror_setup=False, name="Lake").object
    with pytest.raises(_api().OpenSeaError, match="swell is the open sea's"):
        _api().set_swell(lake, height=1.0)
    bpy.context.view_layer.objects.active = lake
    assert not bpy.ops.object.water_sea_swell.poll()
    assert not any(mesh.name.startswith("Water Sea Measure") for mesh in bpy.data.meshes)
    assert list(bpy.data.scenes) == [scene], "the measuring scene is gone"


def test_the_command_line_adds_a_sea_with_a_swell(scene, tmp_path, capsys):
    harness.add_camera(scene, (0, -6, 3), (0, 0, 0))
    source, target = tmp_path / "shot.blend", tmp_path / "sea.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(source))
    options = ["--preset", "open_sea", "--resolution", "17", "--no-surroundings", "--sea-swell-height", "2.5"]
    options += ["--sea-swell-period", "11", "--sea-swell-direction", "-0.28", "0.96"]
    assert harness.addon("cli").main(["add", str(source), str(target), *options]) == 0, capsys.readouterr()
    bpy.ops.wm.open_mainfile(filepath=str(target))
    values = harness.addon("water.sea.open_sea").swell_values(bpy.data.objects["Water"])
    assert values["sea_swell_height"] == 2.5 and values["sea_swell_period"] == 11.0
    assert values["sea_swell_direction"] == pytest.approx(SWELL)


def test_repair_floating_and_removal_keep_working_with_a_swell(scene):
    """Repair of the sea's shading keeps the swell and its clock; a floating cube rides the sea
    and its swell (half in: its origin within 1 cm of the surface's mean over its footprint, 5 x 5
    rays); removing the water leaves nothing."""
    from test_open_sea import _surface_below
    from test_repair import _remove_input

    sea = _open_sea(scene, resolution=65, sea_wind_speed=8.0, sea_swell_height=2.0, sea_swell_direction=SWELL)
    open_sea = harness.addon("water.sea.open_sea")
    shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(sea.active_material)[1]
    _remove_input(shade.node_tree, "Deep Color")
    bpy.context.view_layer.objects.active = sea
    assert harness.addon("water.repair").needs_repair(sea.active_material) is not None
    assert bpy.ops.object.water_repair() == {"FINISHED"}
    assert open_sea.swell_modifier(sea) is not None and len(_swell_driver(sea)) == 1
    assert open_sea.sea_modifiers(sea) is not None

    bpy.ops.mesh.primitive_cube_add(size=1.0, location=(1.5, -2.0, 5.0))
    cube = bpy.context.active_object
    _api().float_on_water(cube, sea, scene=scene, draft=0.5)
    footprint = np.linspace(-0.5, 0.5, 5)
    for frame in (1, 40):
        scene.frame_set(frame)
        depsgraph = bpy.context.evaluated_depsgraph_get()
        origin = cube.evaluated_get(depsgraph).matrix_world.translation.copy()
        heights = [
            _surface_below(sea, (origin.x + dx, origin.y + dy, origin.z), depsgraph)[0]
            for dx in footprint
            for dy in footprint
        ]
        assert abs(origin.z - float(np.mean(heights))) < 0.01, frame

    _api().remove_water(sea, scene)
    assert "Water" not in bpy.data.objects and not cube.constraints
    assert not [o.name for o in bpy.data.objects if o.get("water_surface_float_rig")], "the rig goes too"
    assert not any(mesh.name.startswith("Water Sea Measure") for mesh in bpy.data.meshes)


@pytest.mark.lts
def test_a_saved_swell_moves_the_same_without_the_add_on(scene, tmp_path, addon_disabled_afterwards):
    """The swell is an Ocean modifier whose time is a simple-expression driver: saved, then opened
    with the add-on disabled and auto-run off, the sea's heights at two frames are the same."""
    _open_sea(scene, resolution=33, sea_swell_height=2.0, sea_swell_direction=SWELL, name="Sea")

    def heights():
        found = []
        for frame in (3, 30):
            scene.frame_set(frame)
            found.append(_points(bpy.data.objects["Sea"])[1][:, 2].copy())
        return found

    before = heights()
    assert np.abs(before[0] - before[1]).max() > 0.1, "the sea moves"
    path = tmp_path / "swell.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    scene = harness.reopen_without_add_on(path)
    assert [m.name for m in bpy.data.objects["Sea"].modifiers][:2] == ["Water Swell", "Water Ocean"]
    after = heights()
    for frame, (old, new) in enumerate(zip(before, after)):
        assert np.abs(old - new).max() < 1e-4, frame
