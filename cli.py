"""Command-line commands: `blender -c water_surface add|render|presets ...`.

`main(argv)` is the registered command; it prints what it did and returns 0,
or prints one line starting with "water_surface: error:" and returns non-zero.
The work itself is done by plain functions in `water/files.py`.
"""

import argparse
import math
import re
import sys

import bpy

from . import presets
from .presets import schema
from .water import files

COMMAND = "water_surface"
_handle = None


MAX_SAMPLES = 1 << 24  # Cycles' own limit; far beyond any useful EEVEE count


class UsageError(Exception):
    pass


class _ParserExitError(Exception):
    """argparse is done (`--help`): return this status from `main`, not `sys.exit` inside Blender."""

    def __init__(self, status):
        super().__init__(status)
        self.status = status


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, not argparse's usage dump and exit
        raise UsageError(message)

    def exit(self, status=0, message=None):
        if message:
            print(message, end="", file=sys.stderr)
        raise _ParserExitError(status)


MAX_NUMBER_TEXT = 64  # characters: repr() writes any float in at most 24; longer text is no number


def _whole(what, low, high):
    """argparse type: an integer within low..high, refused (not clamped) outside it.

    Read without int()'s own limit on digits (its message would name no option): plain
    ASCII digits with an optional sign, as many as `high` and `low` have at most.
    """
    longest = max(len(str(abs(low))), len(str(abs(high))))

    def parse(text):
        match = re.fullmatch(r"\s*([+-]?)0*([0-9]+)\s*", text, re.ASCII)
        if match is None:
            raise argparse.ArgumentTypeError(f"invalid int value: {files.shown(text)}")
        sign, digits = match.groups()
        if len(digits) > longest:
            bound = f"at least {low}" if sign == "-" else f"at most {high}"
            raise argparse.ArgumentTypeError(f"{what} must be {bound}, not {files.shown(text.strip())}")
        number = int(sign + digits)
        if number < low:
            raise argparse.ArgumentTypeError(f"{what} must be at least {low}, not {number}")
        if number > high:
            raise argparse.ArgumentTypeError(f"{what} must be at most {high}, not {number}")
        return number

    return parse


def _finite(text):
    """argparse type: a float that is a number (values outside a field's range are clamped later)."""
    if len(text) > MAX_NUMBER_TEXT:
        raise argparse.ArgumentTypeError(
            f"not a number of at most {MAX_NUMBER_TEXT} characters: {files.shown(text)}"
        )
    try:
        number = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"invalid float value: {files.shown(text)}") from None
    if not math.isfinite(number):
        word = "a finite number" if text.strip().lstrip("+-").isalpha() else "within a float's range"
        raise argparse.ArgumentTypeError(f"must be {word}, not {files.shown(text)}")
    return number


def _frames(text):
    """argparse type: N or FIRST-LAST as a list of frame numbers (`files.parse_frames`)."""
    try:
        return files.parse_frames(text)
    except files.FileJobError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def _one_line(error, named=False):
    """The error's message on one line; `named` puts its type first (for errors nobody foresaw)."""
    text = " ".join(line.strip() for line in str(error).splitlines() if line.strip())
    if named or not text:
        return f"{type(error).__name__}: {text}" if text else type(error).__name__
    return text


def _parser():
    parser = _Parser(prog=f"blender -c {COMMAND}", description="Water Surface from the command line")
    commands = parser.add_subparsers(dest="command", required=True, parser_class=_Parser)

    add = commands.add_parser("add", help="add water to a saved .blend and save it")
    add.add_argument("source", help="the .blend to read")
    add.add_argument("target", help="the .blend to write (may be the same file)")
    add.add_argument("--preset", default="lake", help="preset id (see `presets`), default lake")
    add.add_argument("--scene", help="scene name (default: the file's active scene)")
    add.add_argument("--no-mirror", action="store_true", help="skip the mirror set-up")
    add.add_argument(
        "--no-surroundings", action="store_true", help="no surroundings collection (the lake stays one quad)"
    )
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
            kind = _whole(field.key, int(field.min), int(field.max)) if field.kind == "int" else _finite
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
    which.add_argument(
        "--frame",
        type=_whole("frame", files.MIN_FRAME, files.MAX_FRAME),
        help="one frame to render (default: the file's current frame)",
    )
    which.add_argument(
        "--frames", type=_frames, help="frames to render, N or FIRST-LAST (e.g. 1-48), one line a frame"
    )
    render.add_argument(
        "--samples", type=_whole("samples", 1, MAX_SAMPLES), help="render samples (default: the file's)"
    )

    commands.add_parser("presets", help="list the presets")
    return parser


def main(argv):
    """Runs one command; returns its exit status.

    Every failure is one "water_surface: error:" line on stderr and a non-zero status
    (2: the command line is wrong, 1: the job cannot run); nothing raises out of here
    but KeyboardInterrupt, so Blender never prints a traceback for this command.
    """
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
                see_surroundings=not args.no_surroundings,
                keep_session=False,  # the command's session is thrown away: no snapshot to restore
                **values,
            )
        else:
            done = files.render_file(
                args.source,
                args.target,
                scene=args.scene,
                frame=args.frame,
                samples=args.samples,
                frames=args.frames,
                progress=lambda line: print(line, flush=True),
                keep_session=False,
            )
    except _ParserExitError as stop:  # --help: argparse has printed it
        return stop.status
    except (UsageError, files.FileJobError) as error:
        print(f"{COMMAND}: error: {_one_line(error)}", file=sys.stderr)
        return 2 if isinstance(error, UsageError) else 1
    except Exception as error:  # a bug or something unforeseen: still one line, no traceback
        print(f"{COMMAND}: error: {_one_line(error, named=True)}", file=sys.stderr)
        return 1
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
