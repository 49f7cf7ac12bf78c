"""Render farms: a file with every kind of water the add-on makes, checked with the farm's own tools.

The file holds a lake (mirror set-up on), a lake with waves, the seeds' ocean and a
shore: tropical shallows over a sloping bed, with its surroundings (the hidden
cache object and its Geometry Nodes), depth colour and the packed foam tile.
Blender Asset Tracer (BAT, the packer Flamenco uses) must find nothing outside
the file and nothing missing; its pack must render, from another folder with no
add-on and auto-run scripts off, as the original does with the add-on. Frames
rendered by separate worker processes, in any order, must equal the same frames
of one `-a`-style job. The workers are `tools/farm_worker.py`: plain bpy with a
fresh user folder, where the add-on is not installed.
"""

import bpy
import numpy as np
import pytest

import harness

pytestmark = pytest.mark.render

FRAMES = (1, 13)


@pytest.fixture(scope="module")
def shot(addon, eevee, tmp_path_factory):
    """The saved shot and its render of frame 1 made with the add-on enabled."""
    folder = tmp_path_factory.mktemp("shot")
    # One sample, saved with the shot: every worker, the pack and the command line render it so
    # (software EEVEE's cost is per sample, hardly per pixel: this module 92 s at 2 samples, 61 s
    # at 1). The same frame renders the same in every process at any sample count, and the water
    # still moves between frames 1 and 13.
    scene = harness.clean_scene(engine=eevee, width=64, height=36, samples=1)
    harness.set_world_color(scene, (0.35, 0.5, 0.8))
    bpy.ops.object.water_add(size=12.0, location=(-7, 0, 0))
    bpy.ops.object.water_add(size=12.0, resolution=48, waves=True, wave_length=1.0, location=(6, 0, 0))
    bpy.ops.object.water_add(preset="ocean", size=40.0, resolution=64, location=(0, 30, -1))
    # A shore in front: the bed rises through the surface, so the water gathers it, with foam.
    bed = bpy.data.meshes.new("Bed")
    bed.from_pydata([(-3, -13, -1.0), (3, -13, 0.5), (3, -7, 0.5), (-3, -7, -1.0)], [], [(0, 1, 2, 3)])
    scene.collection.objects.link(bpy.data.objects.new("Bed", bed))
    bpy.ops.object.water_add(preset="tropical_shallows", size=6.0, location=(0, -10, 0))
    shore = bpy.context.active_object
    assert harness.addon("water.surroundings").surroundings_cache(shore) is not None
    harness.add_camera(scene, (0, -16, 7), (0, 4, 0))
    path = folder / "shot.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    scene.frame_set(FRAMES[0])
    original = harness.render(scene, folder / "original.exr", exr=True)
    return {"path": path, "folder": folder, "original": original}


def _work(*args):
    """Runs one farm worker process; fails the test with its output when it fails."""
    harness.run_worker(harness.ROOT / "tools" / "farm_worker.py", *args)


@pytest.mark.lts
def test_bat_finds_nothing_outside_or_missing_and_its_pack_renders_the_same(shot, tmp_path):
    target = tmp_path / "packed"
    status, output = harness.bat("pack", shot["path"], target)
    assert status in (0, None), output
    assert "missing" not in output.lower(), output
    packed = sorted(p.relative_to(target).as_posix() for p in target.rglob("*") if p.is_file())
    assert [p for p in packed if p != "pack-info.txt"] == ["shot.blend"], f"BAT packed more: {packed}"
    _work(target / "shot.blend", tmp_path / "packed_####.exr", FRAMES[0])
    pixels = harness.load_image(tmp_path / f"packed_{FRAMES[0]:04d}.exr")
    difference = np.abs(pixels[..., :3] - shot["original"][..., :3]).mean()
    assert difference < 0.01, f"mean difference {difference:.4f}"
    assert shot["original"][..., :3].std() > 0.02, "the shot shows something"


def test_frames_split_across_workers_equal_one_animation_job(shot, tmp_path):
    for frame in reversed(FRAMES):  # one worker a frame, the later frame first
        _work(shot["path"], tmp_path / "split_####.exr", frame)
    _work(
        shot["path"], tmp_path / "job_####.exr", "--animation", FRAMES[0], FRAMES[-1], FRAMES[-1] - FRAMES[0]
    )
    images = {}
    for frame in FRAMES:
        split = harness.load_image(tmp_path / f"split_{frame:04d}.exr")[..., :3]
        job = harness.load_image(tmp_path / f"job_{frame:04d}.exr")[..., :3]
        difference = np.abs(split - job).mean()
        assert difference < 0.005, f"frame {frame}: mean difference {difference:.4f}"
        images[frame] = split
    moved = np.abs(images[FRAMES[0]] - images[FRAMES[-1]]).mean()
    assert moved > 0.005, f"the water moves between the frames ({moved:.4f})"


def test_cli_renders_a_range_with_padding_and_a_line_a_frame(shot, tmp_path, capfd):
    cli = harness.addon("cli")
    status = cli.main(["render", str(shot["path"]), str(tmp_path / "cli_###.png"), "--frames", "3-5"])
    out = capfd.readouterr().out
    assert status == 0
    assert sorted(p.name for p in tmp_path.glob("cli_*.png")) == ["cli_003.png", "cli_004.png", "cli_005.png"]
    lines = [line for line in out.splitlines() if line.startswith("water_surface: frame")]
    assert [line.split()[2] for line in lines] == ["3", "4", "5"]
    assert cli.main(["render", str(shot["path"]), str(tmp_path / "one.png"), "--frames", "7"]) == 0
    assert (tmp_path / "one0007.png").is_file()
    for bad in ("5-3", "x", "1-99999999999"):  # a bad argument: exit 2, as every other option
        assert cli.main(["render", str(shot["path"]), str(tmp_path / "bad.png"), "--frames", bad]) == 2
    assert not list(tmp_path.glob("bad*"))
