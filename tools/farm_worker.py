"""A render-farm worker: plain bpy with no add-on installed, auto-run scripts off.

`python tools/farm_worker.py FILE OUT FRAME [FRAME ...]` renders each frame to OUT
(each `#` run becomes the padded frame number) in one process, frame by frame as
`blender -b FILE -o OUT -f N` does; `--animation FIRST LAST STEP` renders the
range in one `-a`-style job instead. Used by `tests/test_render_farm.py`.
"""

import sys

import harness


def main(argv):
    bpy = harness.start()  # a fresh user folder: the add-on is not installed here
    bpy.context.preferences.filepaths.use_scripts_auto_execute = False
    blend, out, *rest = argv
    bpy.ops.wm.open_mainfile(filepath=blend, load_ui=False)
    scene = bpy.context.scene
    scene.render.filepath = out
    scene.render.use_file_extension = False
    if out.endswith(".exr"):  # exact linear values to compare, as the tests' own renders
        settings = scene.render.image_settings
        settings.file_format, settings.color_mode, settings.color_depth = "OPEN_EXR", "RGBA", "32"
    if rest[0] == "--animation":
        scene.frame_start, scene.frame_end, scene.frame_step = (int(v) for v in rest[1:4])
        bpy.ops.render.render(animation=True)
        return 0
    for frame in (int(v) for v in rest):
        scene.frame_set(frame)
        scene.render.filepath = out.replace("####", f"{frame:04d}")
        bpy.ops.render.render(write_still=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
