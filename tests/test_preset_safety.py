"""Hostile preset files never hang or stop the add-on; saving never writes through
a symlink and never replaces a user's preset unasked."""

import contextlib
import json
import os
import socket
import stat
import threading
import time
from pathlib import Path

import addon_utils
import bpy
import pytest

import harness

posix_only = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs and /dev/zero are POSIX")
HANG_S = 5.0  # a guarded read takes milliseconds; a blocked one is released after this


@pytest.fixture(scope="module")
def store(addon):
    return harness.addon("presets.store")


def _text(folder, name, text):
    path = folder / f"{name}.json"
    path.write_text(text, encoding="utf-8")
    return path


def _good(folder):
    return _text(folder, "good", json.dumps({"name": "Good", "values": {"wave_height": 0.4}}))


def _wave_height(folder, name, number):
    return _text(folder, name, '{"values": {"wave_height": ' + number + "}}")


def _bytes(folder, name, data):
    path = folder / f"{name}.json"
    path.write_bytes(data)
    return path


def _folder(folder, name):
    path = folder / f"{name}.json"
    path.mkdir()
    return path


def _fifo(folder, name):
    path = folder / f"{name}.json"
    os.mkfifo(path)
    return path


def _symlink(folder, name, target):
    path = folder / f"{name}.json"
    path.symlink_to(target)
    return path


def _socket(folder, name):
    path = folder / f"{name}.json"
    with socket.socket(socket.AF_UNIX) as sock:
        sock.bind(str(path))  # the socket file stays after close
    return path


def _bad_name(folder, _name):
    path = os.path.join(os.fsencode(folder), b"caf\xe9.json")  # Latin-1 bytes: not UTF-8
    with open(path, "wb") as file:
        file.write(b'{"name": "Cafe"}')
    return Path(os.fsdecode(path))


# Each maker writes one hostile file and gives the words its warning must hold.
# All of them made the old reader raise, hang, read forever or load a preset Blender cannot show.
HOSTILE = {
    "huge_int": (
        lambda f, n: _text(f, n, '{"values": {"wave_height": ' + "9" * 5000 + "}}"),
        "not valid JSON",
    ),
    "float_overflow": (
        lambda f, n: _text(f, n, '{"values": {"wave_height": 1' + "0" * 400 + "}}"),
        "out of range",
    ),
    "deep": (lambda f, n: _text(f, n, "[" * 32000), "nested too deeply"),
    "latin1": (lambda f, n: _bytes(f, n, b'{"name": "Caf\xe9"}'), "not UTF-8"),
    "surrogate": (lambda f, n: _text(f, n, '{"name": "\\ud800"}'), "'name' is not valid text"),
    "zero": (lambda f, n: _symlink(f, n, "/dev/zero"), "not a regular file"),
    "fifo": (_fifo, "not a regular file"),
    "bad_name": (_bad_name, "file name is not valid UTF-8"),
}
# Refused by the old reader too; part of the hostile folder all the same.
ODD = {
    "big": (lambda f, n: _text(f, n, '{"name": "' + "x" * 70000 + '"}'), "larger than"),
    "folder": (_folder, "not a regular file"),
    "dangling": (lambda f, n: _symlink(f, n, f / "missing_target"), "cannot be read"),
    "socket": (_socket, "cannot be read"),
}


def _release_fifos(folder, done, hung):
    """Opens each FIFO's write end once HANG_S has passed: the blocked reader then sees end of file."""
    if done.wait(HANG_S):
        return
    while not done.is_set():
        for path in Path(folder).glob("*.json"):
            with contextlib.suppress(OSError):  # ENXIO: nobody is reading it, nothing to release
                if stat.S_ISFIFO(os.lstat(path).st_mode):
                    os.close(os.open(path, os.O_WRONLY | os.O_NONBLOCK))
                    hung.append(path.name)
        done.wait(0.1)


@contextlib.contextmanager
def _memory_cap(extra=1 << 30):
    """Caps the address space so a reader of /dev/zero ends in MemoryError, not in the OOM killer."""
    try:
        import resource

        used = int(Path("/proc/self/status").read_text().split("VmSize:")[1].split()[0]) * 1024
    except (ImportError, OSError, IndexError, ValueError):
        yield
        return
    soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    cap = used + extra if hard == resource.RLIM_INFINITY else min(used + extra, hard)
    resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


@contextlib.contextmanager
def _guarded(folder):
    """Runs the block with hangs released and memory capped; fails if it blocked or was slow."""
    done, hung = threading.Event(), []
    watchdog = threading.Thread(target=_release_fifos, args=(folder, done, hung), daemon=True)
    watchdog.start()
    start = time.monotonic()
    try:
        with _memory_cap():
            yield
    finally:
        elapsed = time.monotonic() - start
        done.set()
        watchdog.join()
    assert not hung, f"reading blocked on {hung} until the test released it"
    assert elapsed < HANG_S, f"reading the presets took {elapsed:.1f} s"


def _make_all(folder, makers):
    made = []
    for name, (make, reason) in makers.items():
        try:
            made.append((make(folder, name), reason))
        except OSError as error:  # e.g. a socket path too long, a file system refusing the name
            print(f"not testing {name}: {error}")
    return made


def _assert_one_warning_each(warnings, made):
    skipped = [w for w in warnings if w.startswith("skipped preset")]
    assert len(skipped) == len(made), warnings
    for path, reason in made:
        named = [
            w
            for w in skipped
            if path.name.encode("ascii", "backslashreplace").decode() in w or str(path) in w
        ]
        assert len(named) == 1 and reason in named[0], (path, warnings)
    assert all("\n" not in w for w in warnings), "one line each"


@posix_only
@pytest.mark.parametrize("kind", HOSTILE)
def test_each_hostile_file_is_skipped_with_one_warning_naming_it(store, tmp_path, kind):
    _good(tmp_path)
    make, reason = HOSTILE[kind]
    made = [(make(tmp_path, kind), reason)]
    with _guarded(tmp_path):
        presets, warnings = store.load_dir(tmp_path, user=True)
    assert [p.id for p in presets] == ["user:good"]
    assert presets[0].values["wave_height"] == pytest.approx(0.4)
    _assert_one_warning_each(warnings, made)


@pytest.fixture
def hostile_user_folder(addon):
    """The user preset folder holding a good preset and every hostile file; emptied again after."""
    folder = Path(harness.addon("presets").user_dir())
    before = set(os.listdir(folder))
    made = _make_all(folder, {**HOSTILE, **ODD})
    _good(folder)
    try:
        yield folder, made
    finally:
        for entry in set(os.listdir(folder)) - before:
            path = folder / entry
            if path.is_dir() and not path.is_symlink():
                path.rmdir()
            else:
                path.unlink()
        if not addon_utils.check(harness.ADDON_MODULE)[1]:
            addon_utils.enable(harness.ADDON_MODULE, default_set=True)
        harness.addon("presets").reload()


@posix_only
def test_reload_skips_every_hostile_user_file_once_and_keeps_the_good_ones(hostile_user_folder):
    folder, made = hostile_user_folder
    presets = harness.addon("presets")
    with _guarded(folder):
        warnings = presets.reload()
    _assert_one_warning_each(warnings, made)
    ids = [p.id for p in presets.all_presets()]
    assert ids[0] == "lake" and "user:good" in ids
    assert [i for i in ids if i.startswith("user:")] == ["user:good"]


@posix_only
def test_the_add_on_disables_and_enables_with_hostile_user_files(hostile_user_folder, capfd):
    folder, made = hostile_user_folder
    with _guarded(folder):
        addon_utils.disable(harness.ADDON_MODULE, default_set=True)
        addon_utils.enable(harness.ADDON_MODULE, default_set=True)
    console = capfd.readouterr().err
    assert "Traceback" not in console, console
    assert addon_utils.check(harness.ADDON_MODULE)[1], "the add-on is enabled"
    assert harness.ADDON_MODULE in bpy.context.preferences.addons
    assert console.count("skipped preset") == len(made), console
    ids = [item[0] for item in harness.addon("presets").enum_items()]
    assert ids[0] == "lake" and "user:good" in ids


VALUES = {"wave_height": 0.5}


@posix_only
@pytest.mark.parametrize("overwrite", [False, True])
def test_saving_never_writes_through_a_symlink(store, tmp_path, overwrite):
    other = tmp_path / "other.txt"
    other.write_bytes(b"someone else's file\n")
    folder = tmp_path / "presets"
    folder.mkdir()
    link = _symlink(folder, "x", other)
    dangling = _symlink(folder, "y", tmp_path / "created_through_link.txt")
    given = {"overwrite": True} if overwrite else {}  # the default never replaces
    for name in ("x", "y"):
        with pytest.raises(store.PresetError, match="symbolic link"):
            store.write_preset(folder, name, VALUES, **given)
    assert other.read_bytes() == b"someone else's file\n"
    assert not (tmp_path / "created_through_link.txt").exists()
    assert link.is_symlink() and dangling.is_symlink()
    assert sorted(os.listdir(folder)) == ["x.json", "y.json"], "no temporary file left"


def test_saving_an_existing_name_needs_overwrite(store, tmp_path):
    path = store.write_preset(tmp_path, "lake", {"wave_height": 0.5})
    first = path.read_bytes()
    with pytest.raises(store.PresetExistsError, match="'lake' already exists"):
        store.write_preset(tmp_path, "Lake", {"wave_height": 0.7})
    assert path.read_bytes() == first
    assert store.write_preset(tmp_path, "lake", {"wave_height": 0.7}, overwrite=True) == path
    preset, _ = store.read_preset(path)
    assert preset.values["wave_height"] == pytest.approx(0.7)
    assert os.listdir(tmp_path) == ["lake.json"], "the temporary file was renamed into place"


def test_the_save_operator_refuses_a_clash_unless_replace_is_ticked(scene):
    presets = harness.addon("presets")
    replace = bpy.ops.object.water_preset_add.get_rna_type().properties["replace"]
    assert replace.name == "Replace Existing" and replace.default is False
    bpy.ops.object.water_add(mirror_setup=False)
    node = harness.addon("nodes.material").water_node(bpy.context.active_object.active_material)
    node.inputs["Wave Height"].default_value = 0.55
    path = Path(presets.user_dir()) / "clash_test.json"
    assert not path.exists()
    try:
        assert bpy.ops.object.water_preset_add(name="Clash Test") == {"FINISHED"}
        first = path.read_bytes()
        node.inputs["Wave Height"].default_value = 0.75
        with pytest.raises(RuntimeError, match="tick Replace Existing or pick another name"):
            bpy.ops.object.water_preset_add(name="Clash Test", replace=False)
        assert path.read_bytes() == first
        assert presets.get("user:clash_test").values["wave_height"] == pytest.approx(0.55)
        assert bpy.ops.object.water_preset_add(name="Clash Test", replace=True) == {"FINISHED"}
        assert presets.get("user:clash_test").values["wave_height"] == pytest.approx(0.75)
        with pytest.raises(presets.PresetError, match="already exists"):
            presets.save_user_preset("Clash Test", {"wave_height": 0.1})
        presets.save_user_preset("Clash Test", {"wave_height": 0.1}, overwrite=True)
        assert presets.get("user:clash_test").values["wave_height"] == pytest.approx(0.1)
    finally:
        path.unlink(missing_ok=True)
        presets.reload()
