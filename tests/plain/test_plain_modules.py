"""The add-on's Blender-free parts, tested without Blender: preset schema and store, the wave and
sea maths, and the shape of the imports (no cycles, nothing in nodes/ reaching up into water/)."""

import ast
import json
import math
import sys
from pathlib import Path

import numpy as np
import pytest
import reference_models as rm
from conftest import ROOT, load


def test_these_modules_import_without_blender():
    for name in (
        "presets",
        "presets.schema",
        "presets.store",
        "water.sea.sea_math",
        "nodes.wave_math",
        "water.boats.footprint_math",
        "water.boats.dry_mask_math",
        "water.sea.whitecap_math",
    ):
        load(name)
    load("nodes")  # the group descriptions are data
    assert "bpy" not in sys.modules


def test_a_value_is_clamped_into_its_range_and_nan_refused_by_type(addon_module):
    schema = addon_module("presets.schema")
    values = schema.clamp_values({"size": 1e9, "wave_height": -5.0, "bump_layers": 99})
    assert values["size"] == schema.SIZE.max
    assert values["wave_height"] == schema.BY_KEY["wave_height"].min
    assert values["bump_layers"] == schema.BY_KEY["bump_layers"].max
    with pytest.raises(schema.PresetError, match="caustics"):
        schema.check_types({"caustics": "2"})
    with pytest.raises(schema.PresetError, match="caustics"):
        schema.check_types({"caustics": None})
    with pytest.raises(schema.PresetError, match="waves"):
        schema.check_types({"waves": 1})
    schema.check_types({"caustics": 2, "wind_direction": (0.6, 0.8)})


def test_every_field_has_a_default_within_its_range_and_a_tooltip(addon_module):
    schema = addon_module("presets.schema")
    for field in schema.FIELDS:
        assert field.tooltip and field.label
        if field.kind in ("float", "int"):
            assert field.min <= field.default <= field.max, field.key
        elif field.kind in ("vec2", "color"):
            assert all(field.min <= v <= field.max for v in field.default), field.key


def test_the_built_in_presets_read_and_a_byte_order_mark_is_fine(addon_module, tmp_path):
    store = addon_module("presets.store")
    built_in, warnings = store.load_dir(store.BUILTIN_DIR)
    assert warnings == []
    ids = {preset.id for preset in built_in}
    assert {"lake", "ocean", "open_sea", "clear_lake", "murky_pond"} <= ids
    text = json.dumps({"name": "Marked", "values": {"wave_height": 0.5}})
    (tmp_path / "marked.json").write_bytes(b"\xef\xbb\xbf" + text.encode())
    user, warnings = store.load_dir(tmp_path, user=True)
    assert warnings == [] and [p.name for p in user] == ["Marked"]
    assert user[0].values["wave_height"] == 0.5


def test_a_grown_seas_height_and_tile_follow_the_wind(addon_module):
    sea = addon_module("water.sea.sea_math")
    for wind in (5.0, 10.0, 15.0):
        for spectrum in sea.HEIGHT_STD_AT_SCALE_1:
            hs = 4.0 * sea.wave_scale(wind, spectrum) * sea.HEIGHT_STD_AT_SCALE_1[spectrum]
            assert hs == pytest.approx(rm.pm_significant_height(wind), rel=1e-9)
        peak = sea.peak_wavelength(wind)
        assert peak == pytest.approx(rm.wavelength_at_speed(wind), rel=1e-3)
        tile = sea.tile_size(wind)
        assert sea.MIN_TILE <= tile <= sea.MAX_TILE
        assert tile >= min(sea.MAX_TILE, sea.TILE_WAVES * peak)
    # The wind's direction (x, y) turns into the modifier's angle atan2(y, -x): its waves travel
    # along (-cos a, sin a), the wind's way, for any direction.
    for x, y in ((1, 0), (0.6, 0.8), (-0.6, 0.8), (-1, -1)):
        angle = sea.wave_angle((x, y))
        assert (-math.cos(angle), math.sin(angle)) == pytest.approx(np.array([x, y]) / math.hypot(x, y))
        assert sea.angle_direction(angle) == pytest.approx(np.array([x, y]) / math.hypot(x, y))
    assert sea.ocean_resolution(available=10**12) == sea.RESOLUTIONS[0]
    assert sea.ocean_resolution(available=1) == sea.RESOLUTIONS[-1]


def test_a_grown_sea_s_height_period_and_a_measured_calibration(addon_module):
    """Pierson and Moskowitz: Hs 0.21 U^2 / g, Tp 2 pi U / (0.877 g); `wave_scale` from the
    heights' spread at `wave_scale` 1, measured when given, else the spectrum's typical one."""
    sea = addon_module("water.sea.sea_math")
    assert sea.significant_height(10.0) == pytest.approx(2.141, abs=1e-3)
    assert sea.peak_period(10.0) == pytest.approx(7.303, abs=1e-3)
    assert sea.peak_period(0.0) == 0.0
    assert sea.sea_peak_wavelength(10.0) == pytest.approx(rm.deep_water_wavelength(7.303), rel=1e-3)
    assert sea.sea_peak_wavelength(10.0) == pytest.approx(sea.peak_wavelength(10.0) / 0.877**2)
    assert 4 * 0.3 * sea.wave_scale(12.0, "PIERSON_MOSKOWITZ", 0.3) == pytest.approx(
        sea.significant_height(12.0)
    )
    # Blender's alignment term cos^(10 a) / k^(10 a) times S(omega) is a sea's S(omega) k^-1.5 at 0.15.
    assert 10 * sea.WIND_ALIGNMENT == pytest.approx(1.5)
    assert sea.WIND_DAMPING == 1.0


def test_the_swell_s_wavelength_tile_and_narrow_spectrum(addon_module):
    """The swell's waves are g T^2 / 2 pi long in deep water (the dispersion relation's in
    shallow water, T sqrt(g d) as it grows shallow); its tile holds SWELL_TILE_WAVES of them, and
    Blender's Phillips spectrum with its settings peaks at the tile's ring of that many waves."""
    sea = addon_module("water.sea.sea_math")
    assert sea.wavelength(10.0) == pytest.approx(rm.deep_water_wavelength(10.0))
    assert sea.wavelength(10.0, 1000.0) == pytest.approx(sea.wavelength(10.0), rel=1e-9)
    assert sea.wavelength(20.0, 2.0) == pytest.approx(20.0 * math.sqrt(rm.G * 2.0), rel=0.01)
    shallow = sea.wavelength(8.0, 10.0)
    k = 2 * math.pi / shallow
    assert rm.G * k * math.tanh(k * 10.0) == pytest.approx((2 * math.pi / 8.0) ** 2, rel=1e-9)
    for period, direction in ((4.0, (1.0, 0.0)), (9.0, (-0.28, 0.96)), (25.0, (0.0, -1.0))):
        settings = sea.swell_settings(1.0, period, direction, 200.0)
        length = sea.wavelength(period, 200.0)
        assert settings["spatial_size"] == round(sea.SWELL_TILE_WAVES * length)
        k0 = 2 * math.pi / length
        scale = settings["wind_velocity"] ** 2 / sea.GRAVITY  # Phillips' L = V^2 / g
        smallest = settings["wave_scale_min"]
        assert smallest == pytest.approx(sea.SWELL_NARROWNESS * scale)
        # Phillips exp(-1 / (k L)^2 - (k l)^2) k^-4 peaks where 1 / (k L)^2 - (k l)^2 = 2.
        ks = k0 * np.exp(np.linspace(-0.3, 0.3, 6001))
        spectrum = np.exp(-1 / (ks * scale) ** 2 - (ks * smallest) ** 2) * ks**-4.0
        assert ks[np.argmax(spectrum)] == pytest.approx(k0, rel=0.01)
        width = np.sqrt((spectrum * np.log(ks / k0) ** 2).sum() / spectrum.sum())
        assert width < 0.07
        # Its exponentials stay well within a float's range (Blender multiplies them in single precision).
        assert 1 / (k0 * scale) ** 2 + (k0 * smallest) ** 2 < 80.0
        assert sea.angle_direction(settings["wave_direction"]) == pytest.approx(
            np.array(direction) / math.hypot(*direction)
        )
    assert 4 * 0.25 * sea.swell_wave_scale(2.0, 0.25) == pytest.approx(2.0)
    assert sea.swell_wave_scale(2.0) == pytest.approx(0.5 / sea.SWELL_STD_AT_SCALE_1)


def test_the_swell_keys_are_checked_clamped_and_saved(addon_module, tmp_path):
    schema = addon_module("presets.schema")
    store = addon_module("presets.store")
    assert schema.defaults()["sea_swell_height"] == 0.0, "no swell unless asked"
    values = schema.clamp_values(
        {"sea_swell_height": 99.0, "sea_swell_period": 0.5, "sea_swell_direction": (0.0, 0.0)}
    )
    assert values == {"sea_swell_height": 20.0, "sea_swell_period": 2.0, "sea_swell_direction": (0.0, 1.0)}
    with pytest.raises(schema.PresetError, match="sea_swell_direction"):
        schema.check_types({"sea_swell_direction": 3.0})
    swell = {
        "sea": True,
        "sea_swell_height": 1.5,
        "sea_swell_period": 12.0,
        "sea_swell_direction": [0.6, -0.8],
    }
    path = store.write_preset(tmp_path, "Swell Sea", swell)
    preset, warnings = store.read_preset(path, user=True)
    assert warnings == []
    assert preset.values["sea_swell_height"] == 1.5 and preset.values["sea_swell_period"] == 12.0
    assert tuple(preset.values["sea_swell_direction"]) == (0.6, -0.8)
    built_in = {p.id: p for p in store.load_dir(ROOT / "presets")[0]}
    assert built_in["open_sea"].values["sea_swell_height"] == 0.0


def test_the_four_sines_heights_and_normals_agree(addon_module):
    wave_math = addon_module("nodes.wave_math")
    rng = np.random.default_rng(3)
    xy = rng.uniform(-20, 20, size=(64, 2))
    step = 1e-4
    h = wave_math.heights(xy, 1.7)
    dx = (wave_math.heights(xy + [step, 0], 1.7) - h) / step
    dy = (wave_math.heights(xy + [0, step], 1.7) - h) / step
    expected = np.column_stack([-dx, -dy, np.ones(len(xy))])
    expected /= np.linalg.norm(expected, axis=1, keepdims=True)
    assert np.allclose(wave_math.normals(xy, 1.7), expected, atol=2e-3)


def _imports():
    """{module: set of the add-on's modules it imports}, read from the source."""
    graph = {}
    files = [p for p in ROOT.rglob("*.py") if not {"tests", "tools", "bench", "docs", "out"} & set(p.parts)]
    for path in files:
        relative = path.relative_to(ROOT).with_suffix("")
        parts = list(relative.parts)
        is_package = parts[-1] == "__init__"
        if is_package:
            parts = parts[:-1]
        name = ".".join(parts)
        here = parts if is_package else parts[:-1]
        found = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.level:
                base = here[: len(here) - (node.level - 1)] if node.level > 1 else here
                target = ".".join([*base, *(node.module.split(".") if node.module else [])])
                for alias in node.names:
                    candidate = f"{target}.{alias.name}".strip(".")
                    found.add(
                        candidate
                        if (ROOT / Path(*candidate.split("."))).with_suffix(".py").exists()
                        or (ROOT / Path(*candidate.split(".")) / "__init__.py").exists()
                        else target
                    )
        graph[name] = {f for f in found if f and f != name}
    return graph


def test_no_module_of_nodes_imports_from_water_or_the_operators():
    graph = _imports()
    upward = {
        (module, target)
        for module, targets in graph.items()
        if module.startswith("nodes")
        for target in targets
        if target.split(".")[0] in {"water", "operators", "ui", "cli", "api"}
    }
    assert upward == set()


def test_the_add_ons_modules_import_each_other_without_a_cycle():
    graph = _imports()
    cycles = []

    def visit(module, path):
        if module in path:
            cycles.append(path[path.index(module) :] + [module])
            return
        for target in graph.get(module, ()):
            if target in graph and not target.endswith("__init__"):
                visit(target, path + [module])

    for start in sorted(graph):
        if start:  # the root package chains the others: its own imports are the register order
            visit(start, [])
    assert cycles == []
