"""Input the add-on is handed is checked where it comes in, and refused in one line.

A preset file with a UTF-8 byte-order mark is read; removing a user preset whose file
vanished says so and drops it from the list; every number of the command line is read
within limits (exit 2 naming the option); a FIFO, a folder or a device is "not a regular
file", never waited on; `write_values` takes numbers, not strings, None or bools, by the
same rule presets read from JSON follow.
"""

import json
import os
import threading
from pathlib import Path

import bpy
import numpy as np
import pytest
from mathutils import Color, Vector

import harness

posix_only = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="FIFOs and /dev/null are POSIX")
BOM = b"\xef\xbb\xbf"


@pytest.fixture(scope="module")
def store(addon):
    return harness.addon("presets.store")


@pytest.fixture(scope="module")
def schema(addon):
    return harness.addon("presets.schema")


@pytest.fixture(scope="module")
def presets(addon):
    return harness.addon("presets")


@pytest.fixture(scope="module")
def cli(addon):
    return harness.addon("cli")


@pytest.fixture(scope="module")
def files(addon):
    return harness.addon("water.files")


@pytest.fixture(scope="module")
def api(addon):
    return harness.addon("api")


@pytest.fixture
def user_folder(presets):
    """The user preset folder; what a test leaves in it is removed and the list reloaded."""
    folder = Path(presets.user_dir())
    before = set(os.listdir(folder))
    yield folder
    for entry in set(os.listdir(folder)) - before:
        (folder / entry).unlink()
    presets.reload()


def _one_error_line(capsys):
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("water_surface: error:"), captured.err
    assert "Traceback" not in captured.out + captured.err
    return lines[0]


# A byte-order mark (Notepad, PowerShell) -------------------------------------------------


def test_a_preset_file_with_a_byte_order_mark_is_read(store, tmp_path):
    path = tmp_path / "bom_pond.json"
    data = {"name": "BOM Pond", "values": {"wave_height": 0.6, "dull_color": [0.1, 0.4, 0.2]}}
    path.write_bytes(BOM + json.dumps(data).encode("utf-8"))
    preset, warnings = store.read_preset(path, user=True)
    assert warnings == [] and preset.name == "BOM Pond" and preset.id == "user:bom_pond"
    assert preset.values["wave_height"] == pytest.approx(0.6)
    assert preset.values["dull_color"] == pytest.approx((0.1, 0.4, 0.2))
    presets, warnings = store.load_dir(tmp_path, user=True)
    assert [p.id for p in presets] == ["user:bom_pond"] and warnings == []


def test_a_byte_order_mark_does_not_excuse_bad_utf8_and_the_byte_named_is_the_files(store, tmp_path):
    text = b'{"name": "Caf\xe9"}'  # Latin-1: not UTF-8
    path = tmp_path / "latin1.json"
    path.write_bytes(BOM + text)
    with pytest.raises(
        store.PresetError, match=f"is not UTF-8 text .* at byte {len(BOM) + text.index(0xE9)}"
    ):
        store.read_preset(path)


def test_a_user_preset_saved_with_a_byte_order_mark_is_listed(presets, user_folder):
    (user_folder / "bom_user_test.json").write_bytes(
        BOM + b'{"name": "BOM User Test", "values": {"caustics": 2}}'
    )
    warnings = presets.reload()
    assert not [w for w in warnings if "bom_user_test" in w], warnings
    assert presets.get("user:bom_user_test").values["caustics"] == pytest.approx(2.0)
    assert "user:bom_user_test" in [item[0] for item in presets.enum_items()]


# A user preset whose file vanished ----------------------------------------------------------


def test_removing_a_preset_whose_file_vanished_says_so_in_one_line_and_drops_it(presets, user_folder):
    presets.save_user_preset("Vanish Test", {"wave_height": 0.4})
    (user_folder / "vanish_test.json").unlink()  # deleted outside Blender: the list still has it
    assert "user:vanish_test" in [p.id for p in presets.all_presets()]
    with pytest.raises(presets.PresetGoneError) as raised:
        presets.remove_user_preset("user:vanish_test")
    assert isinstance(raised.value, presets.PresetError) and not isinstance(raised.value, OSError)
    message = str(raised.value)
    assert "vanish_test.json" in message and "gone already" in message and "\n" not in message
    assert "user:vanish_test" not in [p.id for p in presets.all_presets()], "the list is reloaded"
    assert "user:vanish_test" not in [item[0] for item in presets.enum_items()]


def test_the_remove_operator_reports_a_vanished_file_and_refreshes_the_list(presets, user_folder):
    presets.save_user_preset("Vanish Op Test", {"wave_height": 0.4})
    presets.save_user_preset("Stays Test", {"wave_height": 0.5})
    (user_folder / "vanish_op_test.json").unlink()
    with pytest.raises(RuntimeError) as raised:  # Blender raises an operator's ERROR report
        bpy.ops.object.water_preset_remove(preset="user:vanish_op_test")
    message = str(raised.value).strip()
    assert "FileNotFoundError" not in message and "Traceback" not in message
    assert "'Vanish Op Test'" in message and "gone already" in message and "no longer listed" in message
    assert len(message.splitlines()) == 1, message
    ids = [item[0] for item in presets.enum_items()]
    assert "user:vanish_op_test" not in ids and "user:stays_test" in ids
    assert bpy.ops.object.water_preset_remove(preset="user:stays_test") == {"FINISHED"}
    assert not (user_folder / "stays_test.json").exists()
    assert "user:stays_test" not in [p.id for p in presets.all_presets()]


def test_removing_a_built_in_preset_is_still_refused(presets):
    with pytest.raises(presets.PresetError, match="built in"):
        presets.remove_user_preset("lake")
    assert (Path(presets.store.BUILTIN_DIR) / "lake.json").is_file()


# Numbers on the command line ------------------------------------------------------------

HUGE = "9" * 5000  # over Python's 4300-digit limit for int()
# Each way a number can be bad: thousands of digits, negative, as a float, too long, not one.
BAD_NUMBERS = [HUGE, "-" + HUGE, HUGE + ".5", "1" * 70 + ".5", "1e999", "12abc", ""]


def _numeric_options(schema):
    """(command, option, values it takes) for every number the command line reads."""
    options = [
        ("render", "--frame", 1),
        ("render", "--frames", 1),
        ("render", "--samples", 1),
    ]
    for field in schema.FIELDS:
        if field.kind in ("float", "int", "vec2", "color"):
            width = {"vec2": 2, "color": 3}.get(field.kind, 1)
            options.append(("add", "--" + field.key.replace("_", "-"), width))
    return options


def test_every_numeric_option_is_known_to_this_test(cli, schema):
    """The parser's options that read numbers are the ones `_numeric_options` lists."""
    parser = cli._parser()
    commands = next(a for a in parser._actions if a.dest == "command").choices
    read = {
        (name, action.option_strings[0])
        for name, sub in commands.items()
        for action in sub._actions
        if action.type is not None and action.option_strings
    }
    assert read == {(command, option) for command, option, _ in _numeric_options(schema)}


def test_every_number_the_command_line_reads_is_read_within_limits(cli, schema, tmp_path, capsys):
    source, added, image = (str(tmp_path / name) for name in ("shot.blend", "out.blend", "out.png"))
    checked = 0
    for command, option, width in _numeric_options(schema):
        target = added if command == "add" else image
        for bad in BAD_NUMBERS:
            for position in range(width):  # the bad number in each place of a vector
                given = ["0.5"] * width
                given[position] = bad
                args = [command, source, target, option, *given]
                assert cli.main(args) == 2, (option, bad[:20])
                line = _one_error_line(capsys)
                assert f"argument {option}:" in line, line
                assert len(line) < 240 and "Exceeds the limit" not in line, line
                checked += 1
    assert checked > 200
    assert os.listdir(tmp_path) == [], "nothing was read or written"


@pytest.mark.parametrize(
    "args, message",
    [
        (["--frames", "1-" + HUGE], "outside Blender's range"),
        (["--frames", HUGE], "outside Blender's range"),
        (["--frames", "1-2000000"], "frame 2000000 is outside Blender's range"),
        (["--frames", "5-3"], "the last frame comes before the first"),
        (["--frames", "one-two"], "N or FIRST-LAST"),
        (["--frame", HUGE], "frame must be at most 1048574"),
        (["--frame", "-" + HUGE], "frame must be at least -1048574"),
        (["--samples", HUGE], "samples must be at most"),
    ],
)
def test_frames_and_samples_out_of_range_name_the_option_and_exit_2(cli, tmp_path, capsys, args, message):
    status = cli.main(["render", str(tmp_path / "shot.blend"), str(tmp_path / "out.png"), *args])
    line = _one_error_line(capsys)
    assert status == 2
    assert f"argument {args[0]}:" in line and message in line, line
    assert len(line) < 240, line


def test_numbers_within_limits_still_parse(cli):
    parser = cli._parser()
    render = parser.parse_args(["render", "a.blend", "b.png", "--frames", " -2 - 3 ", "--samples", "+16"])
    assert render.frames == [-2, -1, 0, 1, 2, 3] and render.samples == 16
    assert parser.parse_args(["render", "a.blend", "b.png", "--frame", "0007"]).frame == 7
    assert parser.parse_args(["render", "a.blend", "b.png", "--frame", "-1048574"]).frame == -1048574
    add = parser.parse_args(
        ["add", "a.blend", "b.blend", "--size", "1e3", "--resolution", "2048", "--wind-direction", "-1", ".5"]
    )
    assert add.size == 1000.0 and add.resolution == 2048 and add.wind_direction == [-1.0, 0.5]


# Files that are not regular files ------------------------------------------------------


@posix_only
@pytest.mark.parametrize("command, target", [("add", "out.blend"), ("render", "out.png")])
@pytest.mark.parametrize("kind", ["FIFO", "folder", "character device"])
def test_a_source_that_is_not_a_regular_file_is_named_so(cli, files, tmp_path, capsys, command, target, kind):
    source = tmp_path / "shot.blend"
    if kind == "FIFO":
        os.mkfifo(source)  # never opened here: a reader would block until a writer comes
    elif kind == "folder":
        source.mkdir()
    else:
        source.symlink_to("/dev/null")
    status = cli.main([command, str(source), str(tmp_path / target)])
    line = _one_error_line(capsys)
    assert status == 1, "a bad path is exit status 1, as a missing file"
    assert f"not a regular file (a {kind}): {source}" in line and "no such" not in line, line
    job = files.add_water_to_file if command == "add" else files.render_file
    with pytest.raises(files.FileJobError, match=f"not a regular file \\(a {kind}\\)"):
        job(source, tmp_path / target)
    assert sorted(os.listdir(tmp_path)) == ["shot.blend"], "nothing was written"


def test_a_missing_source_is_still_no_such_file(files, tmp_path):
    with pytest.raises(files.FileJobError, match="no such .blend file"):
        files.add_water_to_file(tmp_path / "missing.blend", tmp_path / "out.blend")
    (tmp_path / "dangling.blend").symlink_to(tmp_path / "nowhere.blend")
    with pytest.raises(files.FileJobError, match="no such .blend file"):
        files.render_file(tmp_path / "dangling.blend", tmp_path / "out.png")


@posix_only
def test_a_fifo_as_the_output_image_is_refused_before_anything_is_rendered(files, scene, tmp_path):
    """Writing an image into a FIFO would block until someone reads it: refused up front."""
    harness.add_camera(scene, (0, -6, 3), (0, 0, 0))
    shot = tmp_path / "shot.blend"
    bpy.ops.wm.save_as_mainfile(filepath=str(shot), copy=True)
    fifo = tmp_path / "frame.png"
    os.mkfifo(fifo)
    done = threading.Event()

    def release():  # without the check the render would block: a reader lets it through
        if not done.wait(20.0):
            os.close(os.open(fifo, os.O_RDONLY | os.O_NONBLOCK))

    guard = threading.Thread(target=release, daemon=True)
    guard.start()
    try:
        with pytest.raises(files.FileJobError, match=r"not a regular file \(a FIFO\)"):
            files.render_file(shot, fifo, samples=1)
    finally:
        done.set()
        guard.join()
    assert sorted(os.listdir(tmp_path)) == ["frame.png", "shot.blend"]


# write_values: numbers are numbers ---------------------------------------------------------

# Wrong types for write_values and for a preset's JSON alike: (values, words the error holds).
ILL_TYPED = [
    ({"caustics": None}, ["'caustics'", "must be a number", "NoneType"]),
    ({"caustics": "2"}, ["'caustics'", "must be a number", "str"]),
    ({"wave_height": True}, ["'wave_height'", "must be a number", "bool"]),
    ({"bump_layers": "3"}, ["'bump_layers'", "must be a number"]),
    ({"wind_direction": "ab"}, ["'wind_direction'", "list of 2 numbers", "str"]),
    ({"wind_direction": [1.0]}, ["'wind_direction'", "list of 2 numbers"]),
    ({"dull_color": [0.1, "0.2", 0.3]}, ["'dull_color'", "must be a number", "str"]),
    ({"absorption": {"r": 1, "g": 1, "b": 1}}, ["'absorption'", "list of 3 numbers", "dict"]),
    ({"scatter_color": None}, ["'scatter_color'", "list of 3 numbers"]),
    ({"waves": "yes"}, ["'waves'", "true or false"]),
    ({"shading": 1}, ["'shading'", "one of lake, ocean"]),
]


@pytest.fixture
def water(api, scene):
    return api.add_water(scene, size=4, mirror_setup=False, see_surroundings=False).object


@pytest.mark.parametrize("values, words", ILL_TYPED)
def test_write_values_refuses_a_wrong_type_in_one_line_naming_the_key(api, presets, water, values, words):
    before = api.read_values(water)
    with pytest.raises(presets.PresetError) as raised:
        api.write_values(water, {"wave_height": 0.77, **values})
    assert isinstance(raised.value, ValueError)
    message = str(raised.value)
    assert all(word in message for word in words) and "\n" not in message, message
    assert api.read_values(water) == before, "nothing was written, not even the good value"


@pytest.mark.parametrize("values, words", ILL_TYPED)
def test_a_preset_refuses_the_same_types_with_the_same_words(store, tmp_path, values, words):
    path = tmp_path / "typed.json"
    path.write_text(json.dumps({"values": values}), encoding="utf-8")
    with pytest.raises(store.PresetError) as raised:
        store.read_preset(path)
    assert all(word in str(raised.value) for word in words), raised.value


def test_a_number_too_large_for_a_float_is_out_of_range_not_an_overflow(api, presets, water):
    with pytest.raises(presets.PresetError, match="'caustics' holds a number out of range"):
        api.write_values(water, {"caustics": 10**400})


def test_write_values_takes_numbers_of_any_kind_and_vectors(api, water):
    api.write_values(
        water,
        {
            "caustics": 2,
            "wave_height": np.float32(0.25),
            "bump_layers": np.int64(3),
            "wind_direction": Vector((1.0, 0.0)),
            "dull_color": Color((0.1, 0.2, 0.3)),
            "absorption": np.array([0.5, 0.25, 0.125]),
            "scatter_color": [0, 1, 0],
            "wave_length": -1.0,  # clamped (NaN is refused: test_one_path.py)
            "size": 8.0,  # the plane's: ignored here
            "colour": "not a key",  # unknown keys are not looked at
        },
    )
    values = api.read_values(water)
    assert values["caustics"] == pytest.approx(2.0)
    assert values["wave_height"] == pytest.approx(0.25)
    assert values["bump_layers"] == 3
    assert values["wind_direction"] == pytest.approx((1.0, 0.0))
    assert values["dull_color"] == pytest.approx((0.1, 0.2, 0.3))
    assert values["absorption"] == pytest.approx((0.5, 0.25, 0.125))
    assert values["scatter_color"] == pytest.approx((0.0, 1.0, 0.0))
    assert values["wave_length"] == pytest.approx(0.001)


def test_check_types_is_the_schemas_one_rule(schema):
    schema.check_types(
        {"caustics": 1, "wind_direction": (0, 1), "waves": False, "shading": "ocean", "x": None}
    )
    for values, words in ILL_TYPED:
        with pytest.raises(schema.PresetError) as raised:
            schema.check_types(values)
        assert all(word in str(raised.value) for word in words), raised.value
        with pytest.raises(schema.PresetError):
            schema.check_values(values)
    with pytest.raises(schema.PresetError, match="must be a dict"):
        schema.check_types([("caustics", 1)])


@pytest.mark.parametrize("option", [{"frame": "2"}, {"samples": 2.5}, {"frames": [1, "3"]}, {"frame": True}])
def test_render_file_from_a_script_refuses_a_number_of_the_wrong_type_in_one_line(tmp_path, addon, option):
    files = harness.addon("water.files")
    source = tmp_path / "none.blend"
    with pytest.raises(files.FileJobError, match="whole numbers") as error:
        files.render_file(str(source), str(tmp_path / "out.png"), **option)
    assert "\n" not in str(error.value)
