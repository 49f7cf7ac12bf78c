"""A scene's settings as they were, to put back when adding water fails half-way.

Adding water may touch the render engine, EEVEE's and Cycles' settings, the world and the
add-on's ledger (`ledger.py`). `snapshot` keeps every plain setting (numbers, switches,
choices, vectors) of those structs and the scene's own ID properties; `restore` writes back
the ones that differ, so a failed add leaves the scene as it found it, whatever step failed.
"""

# The scene's setting structs a water may change, by RNA path from the scene.
STRUCTS = (
    "render",
    "eevee",
    "eevee.ray_tracing_options",
    "cycles",
    "display",
    "view_settings",
    "display_settings",
)
_PLAIN = {"BOOLEAN", "INT", "FLOAT", "STRING", "ENUM"}


def _settings(struct):
    found = {}
    for prop in struct.bl_rna.properties:
        if prop.type not in _PLAIN or prop.is_readonly or prop.identifier == "rna_type":
            continue
        value = getattr(struct, prop.identifier)
        found[prop.identifier] = value[:] if getattr(prop, "is_array", False) else value
    return found


def _structs(scene):
    owners = {}
    for path in STRUCTS:
        try:
            owners[path] = scene.path_resolve(path)
        except ValueError:  # not in this Blender (or Cycles not enabled)
            continue
    if scene.world is not None:
        owners["world"] = scene.world
    return owners


def _own_props(scene):
    """The scene's ID properties the add-on writes (the ledger), by key."""
    return {key: scene[key] for key in scene.keys() if key.startswith("water_surface")}


def snapshot(scene):
    """Every plain setting of the scene's structs, its world and its ID properties."""
    settings = {path: _settings(owner) for path, owner in _structs(scene).items()}
    return scene.world, settings, _own_props(scene)


def restore(scene, before):
    """Writes back what differs from `before` (a `snapshot`); returns the paths put back."""
    world, settings, props = before
    changed = []
    if scene.world != world:
        scene.world = world
        changed.append("world")
    for path, owner in _structs(scene).items():
        for name, value in settings.get(path, {}).items():
            now = getattr(owner, name)
            now = now[:] if hasattr(now, "__len__") and not isinstance(now, str) else now
            if now != value:
                try:
                    setattr(owner, name, value)
                    changed.append(f"{path}.{name}")
                except (AttributeError, TypeError, ValueError):
                    continue
    for key in [k for k in _own_props(scene) if k not in props]:
        del scene[key]
        changed.append(f'["{key}"]')
    for key, value in props.items():
        if scene.get(key) != value:
            scene[key] = value
            changed.append(f'["{key}"]')
    return changed
