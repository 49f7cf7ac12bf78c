"""Issue 38 point 2: the open sea reflects as water does, by its refractive index (its
`Water Fresnel` 1, set when the sea is made): 2% of the sky looking straight down, most of it only
at grazing angles, so the sea near a boat is dark and the far sea bright. The seeds' ocean keeps
the seeds' Fresnel. (Far off, where EEVEE's mipmaps average the bump's slopes away, the shade
gives back their mean reflectance: test_sea_band.py.)

A calm open sea (3 m/s, no whitecaps) under a plain sky S, seen from 3 m up over a wide view from
steep to grazing. Each pixel's ray meets the sea at an angle θ to the vertical; numpy's colour
there is `R(θ) S + (1 - R(θ)) D` (R: Fresnel's reflectance of unpolarised light for water's
n = 1.333, `reference_models.fresnel`; D the shade's Deep Color: what the unlit ocean shading
draws). Binned by θ, the rendered brightness is numpy's within 20% (the waves' slopes, 0.13 rad
rms at 3 m/s, tilt each pixel's own angle; measured: within 4% in EEVEE, 8% in Cycles, from 15° to
85°). The seeds' formula, which the open sea had before, is 30% over it 45° from straight down.
"""

import math

import numpy as np
import pytest
from reference_models import fresnel, seeds_ocean_fresnel

import harness

pytestmark = pytest.mark.render

SKY = (0.55, 0.7, 0.95)


def _render_calm_sea(engine, render, preset):
    scene = harness.clean_scene(engine=engine, width=96, height=96, samples=1 if engine != "CYCLES" else 8)
    harness.set_world_color(scene, SKY, 1.0)
    values = {"sea_wind_speed": 3.0, "wind_direction": (0.8, 0.6)} if preset == "open_sea" else {}
    added = harness.addon("api").add_water(scene, preset=preset, see_surroundings=False, **values)
    camera = harness.add_camera(scene, (0.0, 0.0, 3.0), (0.0, 10.0, 0.2), lens=12.0)
    camera.data.clip_end = 30000.0
    shade = harness.addon("nodes.sea.ocean_material").ocean_nodes(added.material)[1]
    # The open sea as it is made (Water Fresnel 1); the seeds' ocean as it is made (0).
    deep = np.array(shade.inputs["Deep Color"].default_value[:3])
    pixels = render(scene, f"calm_{preset}_{engine}", exr=True)[..., :3]
    _origin, directions = harness.pixel_rays(scene, camera)
    return pixels, directions, deep


@pytest.mark.parametrize("engine", ["EEVEE", "CYCLES"])
def test_the_open_sea_is_dark_looking_down_and_bright_at_grazing_as_fresnel_says(
    addon, eevee, render, engine
):
    engine = eevee if engine == "EEVEE" else engine
    pixels, directions, deep = _render_calm_sea(engine, render, "open_sea")
    cos_i = -directions[..., 2]
    sea = cos_i > 0.05  # below the horizon
    model = fresnel(cos_i)[..., None] * np.array(SKY) + (1.0 - fresnel(cos_i))[..., None] * deep
    angle = np.degrees(np.arccos(np.clip(cos_i, -1.0, 1.0)))
    rows = []
    for low in range(15, 85, 5):
        bin_ = sea & (angle >= low) & (angle < low + 5)
        if bin_.sum() < 20:
            continue
        seen, want = pixels[bin_].mean(), model[bin_].mean()
        rows.append((low, bin_.sum(), seen, want, seen / want))
    for low, count, seen, want, ratio in rows:
        print(
            f"{engine}: {low}-{low + 5}° from straight down, {count} px: {seen:.3f} "
            f"(numpy {want:.3f}, {ratio:.2f})"
        )
    ratios = np.array([row[4] for row in rows])
    assert len(rows) >= 8 and rows[0][0] <= 30 and rows[-1][0] >= 75  # steep to grazing in view
    assert np.all(np.abs(ratios - 1.0) < 0.2)
    near, far = rows[0][2], rows[-1][2]
    assert far > 1.5 * near, "the far sea brighter than the near"


def test_the_seeds_ocean_keeps_the_seeds_fresnel(addon, eevee, render):
    """The seeds' ocean keeps its own F = (1 + cos θ) / 2 (the deep colour's share; the sky's,
    (1 - cos θ) / 2, reaches a half at grazing): 35-60° from straight down, within 5% of that
    and more than 15% off water's."""
    pixels, directions, deep = _render_calm_sea(eevee, render, "ocean")
    cos_i = -directions[..., 2]
    sky_share = (1.0 - seeds_ocean_fresnel(-directions))[..., None]
    seeds = sky_share * np.array(SKY) + (1.0 - sky_share) * deep
    water = fresnel(cos_i)[..., None] * np.array(SKY) + (1.0 - fresnel(cos_i))[..., None] * deep
    middle = (cos_i > math.cos(math.radians(60.0))) & (cos_i < math.cos(math.radians(35.0)))
    seen, want, not_want = pixels[middle].mean(), seeds[middle].mean(), water[middle].mean()
    print(
        f"the seeds' ocean 35-60° from straight down: {seen:.3f} (the seeds' {want:.3f}, "
        f"water's {not_want:.3f})"
    )
    assert middle.sum() > 100 and abs(seen / want - 1.0) < 0.05 and abs(seen / not_want - 1.0) > 0.15
