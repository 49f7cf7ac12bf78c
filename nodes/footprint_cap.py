"""Where a pixel sees the surface edge-on, a tiled read's coordinates capped so that one pixel
never spans thousands of tiles.

On a folded crest the eye meets some triangles edge-on (|cos i| ~ 0 between the eye and the
triangle's own normal), and there a texture's coordinates step by thousands of tiles from one
pixel to the next. Software OpenGL (Mesa's llvmpipe, as on CI and GPU-less farm nodes) filters a
mipmapped read by walking every texel of its footprint's box on the smallest mip, so such a pixel
costs seconds and its frame 7 to 100 times its neighbours (issue 57, BENCHMARKS#gale-frames).
The coordinates are scaled by min(1, REACH |cos i| / (distance x tiles per metre)): a pixel is
left alone unless, even in a frame 100,000 pixels across, it would span FOOTPRINT_MAX tiles, where
its read is the tile's mean either way.
"""

from .spec import Node, math, vmath

PIXEL_ANGLE_MIN = 1.0e-5  # radians a pixel: a frame 100,000 pixels across
FOOTPRINT_MAX = 5.0  # tiles a pixel may span at PIXEL_ANGLE_MIN
REACH = FOOTPRINT_MAX / PIXEL_ANGLE_MIN


def capped(key, column, vector, tiles_per_metre):
    """Nodes and links scaling the read coordinates `vector` (a "node:socket" in tiles) where a
    pixel would span more than FOOTPRINT_MAX tiles of `tiles_per_metre` ("node:socket");
    the capped coordinates are `{key}:Vector`."""
    nodes = {
        f"{key}_camera": Node("ShaderNodeCameraData", column),
        f"{key}_geometry": Node("ShaderNodeNewGeometry", column),
        f"{key}_facing": vmath("DOT_PRODUCT", column + 1, "cos i: eye . triangle's normal"),
        f"{key}_facing_abs": math("ABSOLUTE", column + 2, "|cos i|"),
        f"{key}_reach": math("MULTIPLY", column + 3, "REACH |cos i|", b=REACH),
        f"{key}_slant": math("MULTIPLY", column + 2, "distance x tiles per metre"),
        f"{key}_scale": math("DIVIDE", column + 4, "min(1, REACH |cos i| / slant)", clamp=True),
        key: vmath("SCALE", column + 5, "read where a pixel spans few tiles"),
    }
    links = (
        (f"{key}_geometry:Incoming", f"{key}_facing:#0"),
        (f"{key}_geometry:True Normal", f"{key}_facing:#1"),
        (f"{key}_facing:Value", f"{key}_facing_abs:#0"),
        (f"{key}_facing_abs:Value", f"{key}_reach:#0"),
        (f"{key}_camera:View Distance", f"{key}_slant:#0"),
        (tiles_per_metre, f"{key}_slant:#1"),
        (f"{key}_reach:Value", f"{key}_scale:#0"),
        (f"{key}_slant:Value", f"{key}_scale:#1"),
        (vector, f"{key}:#0"),
        (f"{key}_scale:Value", f"{key}:Scale"),
    )
    return nodes, links
