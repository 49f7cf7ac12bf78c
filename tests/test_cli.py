"""`blender -c water_surface ...`: the registered command, called with argument lists as Blender would."""

from pathlib import Path

import bpy
import numpy as np
import pytest

import harness


@pytest.fixture(scope="module")
def cli(addon):
    module = harness.addon("cli")
    assert module._handle is not None, "the command is registered with Blender"
    return module


@pytest.fixture
def saved(scene, tmp_path):
    """A saved .blend with a camera over the origin, no water yet."""
    harness.set_world_color(scene, (0.3, 0.5, 0.8))
    harness.add_camera(scene, (0, -6, 3), (0, 0, 0))
    path = tmp_path / "shot.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    return path


@pytest.mark.lts
def test_add_writes_a_new_file_with_water_and_prints_what_it_did(cli, saved, tmp_path, capsys):
    target = tmp_path / "with_water.blend"
    status = cli.main(
        ["add", str(saved), str(target), "--preset", "lake", "--size", "64", "--wind-direction", "1", "0"]
    )
    out = capsys.readouterr().out
    assert status == 0
    assert "added 'Water'" in out and str(target) in out
    bpy.ops.wm.open_mainfile(filepath=str(target))
    water = bpy.data.objects["Water"]
    assert water.dimensions.x == pytest.approx(64)
    values = harness.addon("water.values").read_values(water.active_material)
    assert values["wind_direction"] == pytest.approx((1, 0))
    assert "Water Mirror" in bpy.data.objects


@pytest.mark.lts
@pytest.mark.render
def test_render_writes_the_image_of_one_frame(cli, saved, tmp_path, capsys):
    with_water = tmp_path / "with_water.blend"
    # A fully dull red water: unmistakable against the blue sky.
    options = ["--size", "20", "--no-mirror", "--dull-blend", "1", "--dull-color", "1", "0", "0"]
    assert cli.main(["add", str(saved), str(with_water), *options]) == 0
    image = tmp_path / "frame.png"
    status = cli.main(["render", str(with_water), str(image), "--frame", "12", "--samples", "1"])
    assert status == 0 and "frame 12" in capsys.readouterr().out
    pixels = harness.load_image(image)
    assert pixels.shape[:2] == (72, 128)
    assert np.isfinite(pixels).all()
    # The same shot without the water shows only the sky; with it, the water covers the middle.
    sky = tmp_path / "sky.png"
    assert cli.main(["render", str(saved), str(sky), "--samples", "1"]) == 0
    without = harness.load_image(sky)
    assert np.allclose(without[..., :3], without[0, 0, :3], atol=0.01), "nothing but the sky"
    red, green, blue = (pixels[24:48, 40:88, i] for i in range(3))
    assert ((red > 0.9) & (green < 0.1) & (blue < 0.1)).mean() > 0.9, "the red water covers the middle"


@pytest.mark.parametrize(
    "args, message",
    [
        (["add", "{dir}/missing.blend", "{dir}/out.blend"], "no such .blend file"),
        (["add", "{saved}", "{dir}/no/such/folder/out.blend"], "folder does not exist"),
        (["add", "{saved}", "{dir}/out.txt"], "must be a .blend"),
        (["add", "{saved}", "{dir}/out.blend", "--preset", "lava"], "no preset 'lava'"),
        (["add", "{saved}", "{dir}/out.blend", "--size", "big"], "invalid float value: 'big'"),
        (["render", "{saved}", "{dir}/out.bmpx"], "unknown image type"),
        (["render", "{saved}", "{dir}/out.png", "--samples", "0"], "samples must be at least 1"),
        (["render", "{saved}", "{dir}/out.png", "--scene", "Nope"], "no scene 'Nope'"),
        (["boil"], "invalid choice: 'boil'"),
        ([], "required"),
    ],
)
def test_bad_arguments_exit_non_zero_with_one_clear_line(cli, saved, tmp_path, capsys, args, message):
    args = [a.format(dir=tmp_path, saved=saved) for a in args]
    status = cli.main(args)
    captured = capsys.readouterr()
    assert status != 0
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("water_surface: error:") and message in lines[0], lines
    assert not Path(tmp_path / "out.blend").exists()


def test_presets_lists_the_built_in_presets(cli, capsys):
    assert cli.main(["presets"]) == 0
    listed = [line.split(":")[0] for line in capsys.readouterr().out.splitlines()]
    assert {"lake", "calm_mirror", "windy_river", "murky_pond"} <= set(listed)


def test_the_same_job_is_a_plain_function_for_scripts(addon, saved, tmp_path):
    files = harness.addon("water.files")
    target = tmp_path / "scripted.blend"
    done = files.add_water_to_file(saved, target, preset="calm_mirror", size=16)
    assert "saved" in done and target.is_file()
    with pytest.raises(files.FileJobError, match="no such .blend"):
        files.add_water_to_file(tmp_path / "nope.blend", target)
