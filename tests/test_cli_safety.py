"""The command line fails safely, and the file jobs leave a script's open file as it was.

Every CLI failure is one `water_surface: error:` line and a non-zero status, decided
before anything is opened, rendered or saved; `--help` is help and status 0. The jobs
in `water.files`, called from a script, put the caller's session back afterwards.
"""

import contextlib
import os
import shutil
import tempfile
from pathlib import Path

import bpy
import pytest

import harness


@pytest.fixture(scope="module")
def cli(addon):
    return harness.addon("cli")


@pytest.fixture(scope="module")
def files(addon):
    return harness.addon("water.files")


@pytest.fixture
def shot(scene, tmp_path):
    """A saved, tiny .blend with a camera (32x32, 1 sample); the session is then a new, untitled one."""
    scene.render.resolution_x = scene.render.resolution_y = 32
    scene.eevee.taa_render_samples = scene.cycles.samples = 1
    harness.set_world_color(scene, (0.3, 0.5, 0.8))
    harness.add_camera(scene, (0, -6, 3), (0, 0, 0))
    path = tmp_path / "shot.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(path))
    bpy.ops.wm.read_homefile(use_empty=True)
    return path


def _one_error_line(capsys):
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("water_surface: error:"), captured.err
    assert "Traceback" not in captured.out + captured.err
    return lines[0]


def test_help_prints_help_and_exits_zero(cli, capsys):
    assert cli.main(["--help"]) == 0
    assert "usage:" in capsys.readouterr().out
    assert cli.main(["render", "--help"]) == 0
    captured = capsys.readouterr()
    assert "--frames" in captured.out and captured.err == ""


@pytest.mark.parametrize(
    "args, message",
    [
        (["render", "{shot}", "{dir}/out.png", "--frame", "99999999999"], "frame must be at most 1048574"),
        (["render", "{shot}", "{dir}/out.png", "--frame", "-99999999999"], "frame must be at least -1048574"),
        (["render", "{shot}", "{dir}/out.png", "--samples", "99999999999"], "samples must be at most"),
        (["add", "{shot}", "{dir}/out.blend", "--resolution", "99999999999"], "resolution must be at most"),
        (["add", "{shot}", "{dir}/out.blend", "--resolution", "1"], "resolution must be at least 2"),
        (["add", "{shot}", "{dir}/out.blend", "--bump-layers", "0"], "bump_layers must be at least 1"),
        (["add", "{shot}", "{dir}/out.blend", "--bump-layers", "99"], "bump_layers must be at most"),
        (["add", "{shot}", "{dir}/out.blend", "--wave-height", "nan"], "finite"),
        (["add", "{shot}", "{dir}/out.blend", "--size", "inf"], "finite"),
        (["add", "{shot}", "{dir}/out.blend", "--wind-direction", "nan", "1"], "finite"),
    ],
)
def test_numbers_out_of_range_or_not_finite_are_refused(cli, shot, tmp_path, capsys, args, message):
    args = [a.format(dir=tmp_path, shot=shot) for a in args]
    assert cli.main(args) == 2
    assert message in _one_error_line(capsys)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["shot.blend"], "nothing was written"


@pytest.mark.parametrize(
    "command, name, extra",
    [("add", "out.blend", []), ("render", "out.png", []), ("render", "f_0004.png", ["--frames", "3-4"])],
)
def test_an_existing_folder_as_output_is_refused_and_left_alone(
    cli, shot, tmp_path, capsys, command, name, extra
):
    folder = tmp_path / name
    folder.mkdir()
    (folder / "keep.txt").write_text("mine")
    target = tmp_path / ("f_####.png" if extra else name)
    assert cli.main([command, str(shot), str(target), *extra]) == 1
    assert "is a folder" in _one_error_line(capsys)
    assert (folder / "keep.txt").read_text() == "mine", "the folder is still there, with its contents"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(["shot.blend", name]), (
        "nothing was rendered, saved or renamed (no .blend1, no frame 3)"
    )


@contextlib.contextmanager
def _without_root():
    """Runs the body as 'nobody' when the tests run as root (root may write anything)."""
    if os.geteuid() != 0:
        yield
        return
    os.setresuid(65534, 65534, 0)  # the saved id stays root, to come back
    try:
        yield
    finally:
        os.setresuid(0, 0, 0)


@pytest.fixture
def locked(shot):
    """A folder anyone may read, holding the shot, a read-only folder and a read-only file."""
    base = Path(tempfile.mkdtemp(prefix="water_surface_locked_"))
    base.chmod(0o777)
    shutil.copy(shot, base / "shot.blend")
    (base / "shot.blend").chmod(0o644)
    (base / "read_only").mkdir()
    (base / "read_only" / "keep.txt").write_text("mine")
    (base / "read_only").chmod(0o555)
    for name in ("read_only.blend", "read_only.png"):
        (base / name).write_text("mine")
        (base / name).chmod(0o444)
    yield base
    (base / "read_only").chmod(0o755)
    shutil.rmtree(base)


@pytest.mark.parametrize(
    "command, target, extra, message",
    [
        ("add", "read_only/out.blend", [], "cannot write in folder"),
        ("render", "read_only/out.png", [], "cannot write in folder"),
        ("render", "read_only/f_##.png", ["--frames", "1-2"], "cannot write in folder"),
        ("add", "read_only.blend", [], "read-only"),
        ("render", "read_only.png", [], "read-only"),
    ],
)
def test_an_output_that_cannot_be_written_is_refused_before_anything_is_done(
    cli, locked, capsys, command, target, extra, message
):
    before = {p: p.stat().st_mtime_ns for p in locked.rglob("*")}
    with _without_root():
        status = cli.main([command, str(locked / "shot.blend"), str(locked / target), *extra])
    assert status == 1
    assert message in _one_error_line(capsys)
    assert {p: p.stat().st_mtime_ns for p in locked.rglob("*")} == before, "nothing was written"


def test_an_unforeseen_error_is_still_one_line_without_a_traceback(cli, capsys):
    assert cli.main(["render", 42]) == 1  # not a string: argparse itself fails
    assert "TypeError" in _one_error_line(capsys)


def _my_work():
    """Unsaved work in the open session: an object with its own mesh, a property and a frame."""
    mesh = bpy.data.meshes.new("MyMesh")
    mesh.from_pydata([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1)], [], [(0, 1, 2, 3)])
    obj = bpy.data.objects.new("MyThing", mesh)
    obj["note"] = "unsaved"
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.frame_current = 17
    return obj


def _assert_my_work_is_back():
    obj = bpy.data.objects.get("MyThing")
    assert obj is not None, "the caller's unsaved object is still there"
    assert len(obj.data.vertices) == 5 and len(obj.data.polygons) == 1
    assert obj.get("note") == "unsaved"
    assert bpy.context.scene.frame_current == 17
    assert "Water" not in bpy.data.objects and "Camera" not in bpy.data.objects, "not the job's file"


def _job(files, name, shot, tmp_path):
    if name == "add":
        target = tmp_path / "with_water.blend"
        done = files.add_water_to_file(shot, target, size=8, resolution=2, mirror_setup=False)
    else:
        target = tmp_path / "frame.png"
        done = files.render_file(shot, target, samples=1)
    assert target.is_file() and str(target) in done
    return target


@pytest.mark.render
@pytest.mark.parametrize("saved_before", [False, True], ids=["untitled", "saved_then_changed"])
@pytest.mark.parametrize("name", ["add", "render"])
def test_a_job_leaves_the_callers_open_file_as_it_was(files, shot, tmp_path, name, saved_before):
    if saved_before:
        bpy.ops.wm.save_as_mainfile(filepath=str(tmp_path / "mine.blend"))
    _my_work()
    _job(files, name, shot, tmp_path)
    _assert_my_work_is_back()
    if saved_before:  # reopened from the copy (in the background): a copy's path, the same name
        assert Path(bpy.data.filepath).name == "mine.blend"
        assert (tmp_path / "mine.blend").is_file(), "the caller's own file is not touched"
    # In the background the session always comes back from its copy: this job's copy, not
    # another Blender's running beside it (CI runs two versions at once), is deleted.
    copy = Path(bpy.data.filepath).parent
    assert copy.name.startswith("water_surface_session_") and copy.parent == Path(tempfile.gettempdir())
    assert not copy.exists(), "the copy is deleted"


def test_a_failing_job_also_leaves_the_callers_open_file_as_it_was(files, shot, tmp_path):
    _my_work()
    with pytest.raises(files.FileJobError, match="no scene 'Nope'"):
        files.render_file(shot, tmp_path / "frame.png", scene="Nope")  # fails after opening the shot
    _assert_my_work_is_back()
    mine = bpy.data.objects["MyThing"]
    with pytest.raises(files.FileJobError, match="unknown image type"):
        files.render_file(shot, tmp_path / "frame.bmpx")  # fails before opening anything
    assert mine.name == "MyThing", "nothing was reopened: the caller's references still hold"
    assert not (tmp_path / "frame.png").exists()


@pytest.mark.render
def test_the_command_line_keeps_no_session(cli, shot, tmp_path, capsys):
    _my_work()
    target = tmp_path / "frame.png"
    assert cli.main(["render", str(shot), str(target), "--samples", "1"]) == 0
    assert target.is_file()
    assert bpy.data.filepath == str(shot.resolve()), "the command leaves the job's file open"
    assert "MyThing" not in bpy.data.objects
