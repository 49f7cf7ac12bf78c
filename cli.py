"""Command-line commands: `blender -c water_surface add|render|presets ...`.

`main(argv)` is the registered command; it prints what it did and returns 0,
or prints one line starting with "water_surface: error:" and returns non-zero.
The work itself is done by plain functions in `water/files.py`.
"""

import argparse
import sys

import bpy

from . import presets
from .presets import schema

COMMAND = "water_surface"
_handle = None


class UsageError(Exception):
    pass


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, not argparse's usage dump and exit
        raise UsageError(message)


def _parser():
    parser = _Parser(prog=f"blender -c {COMMAND}", description="Water Surface from the command line")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    add = commands.add_parser("add", help="add water to a saved .blend and save it")
    add.add_argument("source", help="the .blend to read")
    add.add_argument("target", help="the .blend to write (may be the same file)")
    add.add_argument("--preset", default="lake", help="preset id (see `presets`), default lake")
    add.add_argument("--scene", help="scene name (default: the file's active scene)")
    add.add_argument("--no-mirror", action="store_true", help="skip the mirror set-up")
    for field in schema.FIELDS:
        option = "--" + field.key.replace("_", "-")
        if field.kind == "bool":
            add.add_argument(
                option, action=argparse.BooleanOptionalAction, dest=field.key, help=field.tooltip
            )
        elif field.kind == "choice":
            add.add_argument(option, choices=field.choices, dest=field.key, help=field.tooltip)
        else:
            width = {"float": None, "int": None, "vec2": 2, "color": 3}[field.kind]
            kind = int if field.kind == "int" else float
            add.add_argument(option, type=kind, nargs=width, dest=field.key, help=field.tooltip)

    render = commands.add_parser("render", help="render frames of a saved .blend")
    render.add_argument("source", help="the .blend to render")
    render.add_argument(
        "target",
        help="the image to write (.png, .exr, .jpg, .tif); with --frames each run of # in it "
        "becomes the zero-padded frame number, as with blender -b -o",
    )
    render.add_argument("--scene", help="scene name (default: the file's active scene)")
    which = render.add_mutually_exclusive_group()
    which.add_argument("--frame", type=int, help="one frame to render (default: the file's current frame)")
    which.add_argument("--frames", help="frames to render, N or FIRST-LAST (e.g. 1-48), one line a frame")
    render.add_argument("--samples", type=int, help="render samples (default: the file's)")

    commands.add_parser("presets", help="list the presets")
    return parser


def main(argv):
    """Runs one command; returns its exit status."""
    from .water import files

    try:
        args = _parser().parse_args(list(argv))
        if args.command == "presets":
            for preset in presets.all_presets():
                print(f"{preset.id}: {preset.name}. {preset.description}")
            return 0
        if args.command == "add":
            values = {f.key: getattr(args, f.key) for f in schema.FIELDS if getattr(args, f.key) is not None}
            done = files.add_water_to_file(
                args.source,
                args.target,
                scene=args.scene,
                preset=args.preset,
                mirror_setup=not args.no_mirror,
                **values,
            )
        else:
            frames = files.parse_frames(args.frames) if args.frames is not None else None
            done = files.render_file(
                args.source,
                args.target,
                scene=args.scene,
                frame=args.frame,
                samples=args.samples,
                frames=frames,
                progress=lambda line: print(line, flush=True),
            )
    except (UsageError, files.FileJobError) as error:
        print(f"{COMMAND}: error: {error}", file=sys.stderr)
        return 2 if isinstance(error, UsageError) else 1
    print(f"{COMMAND}: {done}")
    return 0


def register():
    global _handle
    _handle = bpy.utils.register_cli_command(COMMAND, main)


def unregister():
    global _handle
    if _handle is not None:
        bpy.utils.unregister_cli_command(_handle)
        _handle = None
