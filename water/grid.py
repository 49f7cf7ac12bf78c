"""A flat grid mesh from an axis of coordinates: the one builder of the water meshes."""

import bpy
import numpy as np

from ..presets import schema

BYTES_PER_VERTEX = 400  # mesh, wave attribute and evaluated copy, measured with margin


def max_resolution():
    """Vertices per side a grid may have: the schema's cap, or less on a machine short of memory."""
    try:
        with open("/proc/meminfo", encoding="ascii") as meminfo:
            available = next(
                int(line.split()[1]) * 1024 for line in meminfo if line.startswith("MemAvailable")
            )
    except (OSError, StopIteration, ValueError):
        return schema.RESOLUTION.max
    return int(min(schema.RESOLUTION.max, max(schema.RESOLUTION.min, (available / BYTES_PER_VERTEX) ** 0.5)))


def grid_mesh(name, axis, uv_metres):
    """A smooth-shaded grid with vertices at `axis` x `axis` (XY plane), quads facing +Z, and UVs
    = position / `uv_metres` + 0.5. The lake's even grid and the open sea's graded one."""
    n = len(axis)
    x, y = np.meshgrid(axis, axis)
    co = np.column_stack([x.ravel(), y.ravel(), np.zeros(n * n)])
    corner = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    quads = np.column_stack([corner, corner + 1, corner + n + 1, corner + n])  # counter-clockwise: +Z up
    mesh = bpy.data.meshes.new(name)
    mesh.vertices.add(n * n)
    mesh.vertices.foreach_set("co", co.astype(np.float32).ravel())
    mesh.loops.add(quads.size)
    mesh.loops.foreach_set("vertex_index", quads.astype(np.int32).ravel())
    mesh.polygons.add(len(quads))
    mesh.polygons.foreach_set("loop_start", (np.arange(len(quads)) * 4).astype(np.int32))
    uv = mesh.uv_layers.new(name="UVMap")
    uv.data.foreach_set("uv", (co[quads.ravel(), :2] / uv_metres + 0.5).astype(np.float32).ravel())
    mesh.update(calc_edges=True)
    mesh.polygons.foreach_set("use_smooth", np.ones(len(quads), dtype=bool))
    return mesh
