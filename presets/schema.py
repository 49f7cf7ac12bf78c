"""What a water preset may hold, and how a read value is checked and clamped.

Plain Python (no bpy): the fields come from the `Water Surface` group's own
socket descriptions, so the preset ranges, the operator's properties and the
shader's inputs cannot drift apart.
"""

import math
from collections.abc import Mapping
from dataclasses import dataclass
from numbers import Real

from ..nodes.lake import water_surface
from ..nodes.sea import ocean_shade
from ..water.errors import WaterError


class PresetError(WaterError, ValueError):
    """A preset that cannot be used: not JSON, not an object, or a value of the wrong type."""


@dataclass(frozen=True)
class Field:
    """One preset value: its key in JSON, the group socket it sets (None: the plane's size)."""

    key: str
    socket: str | None
    kind: str  # "float", "vec2" (X/Y of a vector socket), "color" (RGB), "int", "bool" or "choice"
    default: object
    min: float
    max: float
    label: str
    tooltip: str
    choices: tuple = ()


def _from_socket(key, socket_name, kind, high=None):
    """A field for one `Water Surface` input; `high` overrides the top of a colour's 0..1 range."""
    socket = next(s for s in water_surface.INPUTS if s.name == socket_name)
    if kind == "vec2":
        default, low, top = tuple(socket.default[:2]), -1.0, 1.0
    elif kind == "color":
        default, low, top = tuple(socket.default[:3]), 0.0, 1.0
    else:
        default, low, top = socket.default, socket.min, socket.max
    return Field(
        key, socket_name, kind, default, low, top if high is None else high, socket_name, socket.tooltip
    )


MAX_ABSORPTION = 50.0  # per metre: past this the water is opaque within 2 cm

SIZE = Field(
    "size", None, "float", 128.0, 0.01, 100000.0, "Size", "Edge length of the water plane (the seeds' 128)"
)

RESOLUTION = Field(
    "resolution",
    None,
    "int",
    2,
    2,
    2048,
    "Resolution",
    "Vertices along each side of the plane (2: one quad; waves need many)",
)
WAVES = Field(
    "waves", None, "bool", False, 0, 1, "Waves", "Lift the plane with the four-sine-wave Water Waves modifier"
)
UNDERWATER = Field(
    "underwater",
    None,
    "bool",
    True,
    0,
    1,
    "Underwater",
    "A camera under the water sees through water: what is far fades into the water's colour (a "
    "camera that never goes under pays nothing for it)",
)
LIGHT_SHAFTS = Field(
    "light_shafts",
    None,
    "float",
    0.0,
    0.0,
    1.0,
    "Light Shafts",
    "Under the water, the sun's light shafts: the share of what the water takes from the light "
    "that it scatters rather than absorbs (0: none, and no cost; needs Underwater)",
)
SHADING = Field(
    "shading",
    None,
    "choice",
    "lake",
    0,
    0,
    "Shading",
    "Lake: traced mirror and refraction; Ocean: the sky reflected over deep blue",
    choices=("lake", "ocean"),
)

# The open sea (`water/sea/open_sea.py`): Blender's Ocean modifier, set from these.
SEA = Field(
    "sea",
    None,
    "bool",
    False,
    0,
    1,
    "Open Sea",
    "Blender's Ocean modifier (spectrum waves, whitecaps) on a sea that reaches the horizon; ocean shading",
)
SEA_WIND_SPEED = Field(
    "sea_wind_speed",
    None,
    "float",
    12.0,
    1.0,
    40.0,
    "Sea Wind Speed",
    "Wind over the open sea in m/s: 3 is a calm sea, 15 a rough one with whitecaps (a gale is 20)",
)
SEA_SPECTRUM = Field(
    "sea_spectrum",
    None,
    "choice",
    "pierson_moskowitz",
    0,
    0,
    "Sea Spectrum",
    "The Ocean modifier's wave spectrum: Phillips, Pierson-Moskowitz (a fully grown sea), JONSWAP "
    "(a growing sea), TMA (JONSWAP in shallow water)",
    choices=("phillips", "pierson_moskowitz", "jonswap", "tma"),
)
SEA_CHOPPINESS = Field(
    "sea_choppiness",
    None,
    "float",
    1.0,
    0.0,
    2.0,
    "Sea Choppiness",
    "Sharper crests and flatter troughs (0: round waves; above 1 crests may fold)",
)
SEA_DEPTH = Field(
    "sea_depth",
    None,
    "float",
    200.0,
    1.0,
    10000.0,
    "Sea Depth",
    "Depth of the sea floor in metres: shallow water slows and shortens the waves",
)
SEA_SEED = Field("sea_seed", None, "int", 0, 0, 100000, "Sea Seed", "Another seed, another sea")
_WHITECAPS_SOCKET = next(s for s in ocean_shade.SHADE_SPEC.inputs if s.name == "Whitecaps")
# On the ocean shading's group, not `Water Surface`: set by `open_sea.py`, not `write_values`.
WHITECAPS = Field(
    "whitecaps",
    None,
    "float",
    _WHITECAPS_SOCKET.default,
    _WHITECAPS_SOCKET.min,
    _WHITECAPS_SOCKET.max,
    "Whitecaps",
    _WHITECAPS_SOCKET.tooltip,
)
# The swell (`open_sea.set_swell`): long regular waves from far away, on top of the wind's sea.
SEA_SWELL_HEIGHT = Field(
    "sea_swell_height",
    None,
    "float",
    0.0,
    0.0,
    20.0,
    "Swell Height",
    "Significant height of a swell in metres, on top of the wind's waves (0: no swell)",
)
SEA_SWELL_PERIOD = Field(
    "sea_swell_period",
    None,
    "float",
    10.0,
    2.0,
    30.0,
    "Swell Period",
    "Seconds between the swell's crests: its waves are g T^2 / 2 pi long in deep water (10 s: 156 m)",
)
SEA_SWELL_DIRECTION = Field(
    "sea_swell_direction",
    None,
    "vec2",
    (0.0, 1.0),
    -1.0,
    1.0,
    "Swell Direction",
    "The way the swell travels (x, y), apart from the wind's",
)
SEA_FIELDS = (
    SEA,
    SEA_WIND_SPEED,
    SEA_SPECTRUM,
    SEA_CHOPPINESS,
    SEA_DEPTH,
    SEA_SEED,
    WHITECAPS,
    SEA_SWELL_HEIGHT,
    SEA_SWELL_PERIOD,
    SEA_SWELL_DIRECTION,
)

FIELDS = (
    SHADING,
    SIZE,
    RESOLUTION,
    WAVES,
    UNDERWATER,
    LIGHT_SHAFTS,
    _from_socket("wave_height", "Wave Height", "float"),
    _from_socket("wave_length", "Wave Length", "float"),
    _from_socket("wind_direction", "Wind Direction", "vec2"),
    _from_socket("wind_force", "Wind Force", "float"),
    _from_socket("dull_color", "Dull Color", "color"),
    _from_socket("dull_blend", "Dull Blend", "float"),
    _from_socket("specular_power", "Specular Power", "float"),
    _from_socket("specular_strength", "Specular Strength", "float"),
    _from_socket("bump_strength", "Bump Strength", "float"),
    _from_socket("bump_layers", "Bump Layers", "int"),
    # Per metre: murky water absorbs a few times per metre, so the colour range reaches past 1.
    _from_socket("absorption", "Absorption", "color", high=MAX_ABSORPTION),
    _from_socket("scatter_color", "Scatter Color", "color"),
    _from_socket("foam_width", "Foam Width", "float"),
    _from_socket("foam_amount", "Foam Amount", "float"),
    _from_socket("caustics", "Caustics", "float"),
    _from_socket("caustics_scale", "Caustics Scale", "float"),
    *SEA_FIELDS,
)
BY_KEY = {field.key: field for field in FIELDS}
# The shader's values: everything but the plane's size.
SHADER_FIELDS = tuple(field for field in FIELDS if field.socket is not None)


def defaults():
    """The reference values (the seeds' lake)."""
    return {field.key: field.default for field in FIELDS}


def _is_number(value):
    """The one rule for a number, in a preset's JSON and from a script alike: an int or a float
    (numpy's too), never a bool (`true` is no wave height) nor a string ("2" is text)."""
    return isinstance(value, Real) and not isinstance(value, bool)


def _number(value, key):
    if not _is_number(value):
        raise PresetError(f"'{key}' must be a number, not {type(value).__name__}")
    try:
        return float(value)
    except OverflowError as error:  # an integer too large for a float
        raise PresetError(f"'{key}' holds a number out of range ({error})") from error


def _numbers(value, field):
    """The floats of a vec2 or colour value: a list, a tuple or another sequence (a mathutils
    Vector or Color, a property array) of 2 or 3 numbers; never a string, a dict or a set."""
    width = 2 if field.kind == "vec2" else 3
    sequence = not isinstance(value, (str, bytes, bytearray, Mapping)) and hasattr(value, "__getitem__")
    try:
        length = len(value) if sequence else None
    except TypeError:  # a sequence-like object without a length (numpy's 0-d array)
        length = None
    if length != width:
        what = type(value).__name__ if length is None else f"a {type(value).__name__} of {length}"
        raise PresetError(f"'{field.key}' must be a list of {width} numbers, not {what}")
    return tuple(_number(v, field.key) for v in value)


def _clamp(value, field):
    if not math.isfinite(value):
        raise PresetError(f"'{field.key}' must be finite, not {value}")
    return min(max(value, field.min), field.max)


def _finite(number, key):
    """`number` unchanged when finite; PresetError naming the key for NaN or an infinity."""
    if not math.isfinite(number):
        raise PresetError(f"'{key}' must be finite, not {number}")
    return number


def _check_type(field, value):
    """`value` unchanged when it has the field's type and its numbers are finite; PresetError
    naming the key and the type (or the NaN, the infinity)."""
    if field.kind in ("float", "int"):
        _finite(_number(value, field.key), field.key)
    elif field.kind == "bool":
        if not isinstance(value, bool):
            raise PresetError(f"'{field.key}' must be true or false, not {value!r}")
    elif field.kind == "choice":
        if not isinstance(value, str) or value not in field.choices:
            raise PresetError(f"'{field.key}' must be one of {', '.join(field.choices)}, not {value!r}")
    else:
        for number in _numbers(value, field):
            _finite(number, field.key)
    return value


def check_types(values):
    """Raises PresetError (a ValueError, one line naming the key and the type it needs) unless
    each known key of `values` holds a value of its field's type; other keys are not looked at.

    The type rule of presets read from JSON (`check_value`), for values from scripts: a number
    is an int or a float, never a bool nor a string, and finite (NaN or an infinity is refused,
    as in a preset file: a NaN stored in the shader washes the water out); `wind_direction` and
    the colours are 2 or 3 such numbers; a bool is True or False; a choice one of its strings.
    Ranges are not checked: callers clamp (`clamp_values`).
    """
    if not isinstance(values, Mapping):
        raise PresetError(f"values must be a dict of preset keys, not {type(values).__name__}")
    for key, value in values.items():
        field = BY_KEY.get(key)
        if field is not None:
            _check_type(field, value)


def check_value(field, value):
    """`value` as the field's type, clamped to its range; PresetError when ill-typed."""
    if field.kind == "float":
        return _clamp(_number(value, field.key), field)
    if field.kind == "int":
        number = _number(value, field.key)
        if not math.isfinite(number) or number != int(number):
            raise PresetError(f"'{field.key}' must be a whole number, not {value}")
        return int(_clamp(number, field))
    if field.kind in ("bool", "choice"):
        return _check_type(field, value)
    numbers = tuple(_clamp(v, field) for v in _numbers(value, field))
    if field.kind == "vec2" and numbers[0] == 0.0 and numbers[1] == 0.0:
        return tuple(field.default)  # no direction at all: the reference's +Y
    return numbers


def check_values(values):
    """Every known value checked and clamped; unknown keys are returned apart.

    Returns (clean values, unknown keys). Missing keys are simply absent: the
    caller decides what they fall back to.
    """
    if not isinstance(values, dict):
        raise PresetError("'values' must be an object of name: value")
    clean, unknown = {}, []
    for key, value in values.items():
        field = BY_KEY.get(key)
        if field is None:
            unknown.append(key)
        else:
            clean[key] = check_value(field, value)
    return clean, unknown


def _in_range(number, field, default):
    """`number` clamped into the field's range; NaN becomes `default`, infinities a bound."""
    number = float(number)
    return default if math.isnan(number) else min(max(number, field.min), field.max)


def clamp_values(values):
    """Values from a caller (operator, command line) made safe: out of range or
    non-finite numbers fall back into range, a zero wind becomes +Y.

    Unlike `check_values` this never refuses a number: NaN becomes the default
    and an infinity the nearest bound.
    """
    safe = {}
    for key, value in values.items():
        field = BY_KEY[key]
        if field.kind in ("float", "int"):
            value = _in_range(value, field, field.default)
            value = round(value) if field.kind == "int" else value
        elif field.kind in ("vec2", "color"):
            value = [_in_range(v, field, default) for v, default in zip(value, field.default)]
        safe[key] = check_value(field, value)
    return safe
