"""The water a camera under the surface sees through: a hidden child of each water, its body.

`add` gives a water an object `"<water> Underwater"` (parented to it, in its collections) whose
`Water Underwater Shell` modifier makes the closed body of water under its evaluated surface,
filled with its own material's `Water Underwater Fog` (`nodes/under/`): light over d metres
keeps `exp(-c d)` and the water's colour fills in the rest, c the water's `Absorption`. The fog's
two values follow the water's by simple-expression drivers (the lake's Absorption and Scatter
Color, the ocean's Absorption and Deep Color), so the water looks the same from below as from
above, a saved file renders the same without the add-on, and the panel's colours change both.

The object is seen by camera rays only (Cycles' other rays and EEVEE's probes skip it); the body
is made only while the camera is within `Margin` of the surface or under it, so a camera that
never goes under pays nothing. The same modifier draws the waterline across the lens (the `Water
Meniscus` material, one for every water), its `Near` driven from the scene's camera's Clip Start.
A second child, `"<water> Caustic Light"`, patterns the sunlight on everything under the water
while the camera is there (`nodes/under/caustic_light.py`), and the light shafts too
(`set_light_shafts`: the fog's sunlight scattered towards the eye, off by default). The objects
and their materials carry `KEY` (the water's name when made) and the add-on's mark: `remove`
finds them among the water's children, `remove_lost` by their parent gone.

A camera over none of the water may be under a placement of it by a collection instance, which
Geometry Nodes cannot see: the body is then made for every placement, with a second fog
`"<water> Underwater Placed"` (`Each Placement` on) that each placement shuts in its shader while
the camera is over its level; the caustic light likewise, `"<water> Caustic Light Placed"`
(docs/MODEL.md section 16, "Placed by instances").
"""

import bpy

from ..nodes import SPECS
from ..nodes.builder import ensure_group
from ..nodes.material import drive_property, drive_socket, new_node_material
from ..nodes.ownership import is_original, mark, owned, role_of
from ..nodes.under import caustic_light, caustic_sheet, meniscus, underwater_fog, underwater_shell
from .editable import check_editable
from .errors import UnderwaterError
from .kind import HOLDS_WATER_MATERIAL, LAKE, shading_of, water_material
from .ledger import claim, release
from .ledger import holder as ledger_holder
from .users import unused
from .waves import get_wave_input, input_ids, input_property, set_wave_input

KEY = "water_surface_underwater"  # on the object and its material: the water's name
# The body and the caustic light: not waters, though they hold one's material.
ROLE, LIGHT_ROLE = HOLDS_WATER_MATERIAL
MATERIAL_ROLE = "Underwater Fog"
# The same with Each Placement on: the body made for every placement (a collection instance's).
PLACED_ROLE = "Underwater Fog Placed"
MENISCUS_ROLE = meniscus.NAME  # the one waterline material every water's body shares
LIGHT_MATERIAL_ROLE = "Caustic Light Material"
LIGHT_PLACED_ROLE = "Caustic Light Placed"
_MATERIAL_ROLES = (MATERIAL_ROLE, PLACED_ROLE, LIGHT_MATERIAL_ROLE, LIGHT_PLACED_ROLE)
# The caustic light's inputs follow the water shader's inputs of the same names.
_LIGHT_INPUTS = tuple(socket.name for socket in caustic_light.INPUTS)
# EEVEE's volume slices: at its default 64 over 0.1-100 m the fog 2 m away in murky water is
# 40% too thin; at 256 within 10% (docs/BENCHMARKS.md, Underwater fog).
EEVEE_VOLUME_SAMPLES = 256
# EEVEE's froxels are this many pixels across: at its default 8 the fog just under a waterline
# across the lens is thin over a band of up to 5 rows (of 90), the froxels straddling the surface;
# at 4, within a row of it (tests/test_waterline.py).
EEVEE_VOLUME_TILE = 4
TILE_PATH = "eevee.volumetric_tile_size"
# What far water looks like from above, per shading: the fog's `Scatter Color` follows it.
_FAR_COLOUR = {LAKE: "Scatter Color"}
_OCEAN_FAR_COLOUR = "Deep Color"


def find(water, role=ROLE):
    """The water's underwater object (its body; `role=LIGHT_ROLE`: its caustic light), or None."""
    return next(
        (o for o in water.children if o.get(KEY) is not None and role_of(o) == role and is_original(o)),
        None,
    )


def is_lost(obj):
    """Whether `obj` is an underwater object whose water is gone (deleted, or no longer water)."""
    if obj.get(KEY) is None or role_of(obj) not in (ROLE, LIGHT_ROLE) or not is_original(obj):
        return False
    water = obj.parent
    return water is None or water_material(water) is None or not water.users_scene


def _shader_node(material):
    from .values import _shader_node

    return _shader_node(material)


def _group_material(name, role, group_name, group_output, material_input):
    """A new material `name` marked as `role`: one node of the group `group_name` whose
    `group_output` feeds the material output's `material_input`. Returns (material, that node)."""
    material = new_node_material(name)
    mark(material, role, 1)
    tree = material.node_tree
    tree.nodes.clear()
    node = tree.nodes.new("ShaderNodeGroup")
    node.name = group_name
    node.node_tree = ensure_group(SPECS[group_name], SPECS)
    output = tree.nodes.new("ShaderNodeOutputMaterial")
    output.location = (300.0, 0.0)
    tree.links.new(node.outputs[group_output], output.inputs[material_input])
    return material, node


def _fog_material(water, material, plain=None):
    """The fog's material, its values driven by the water's `material`; with `plain` (the fog
    material made first), the fog for every placement: Each Placement on, its Light Shafts
    following `plain`'s."""
    name, role = (f"{water.name} Underwater", MATERIAL_ROLE)
    if plain is not None:
        name, role = (f"{name} Placed", PLACED_ROLE)
    fog, node = _group_material(name, role, underwater_fog.NAME, "Volume", "Volume")
    fog[KEY] = water.name
    far = _FAR_COLOUR.get(shading_of(material), _OCEAN_FAR_COLOUR)
    pairs = (("Absorption", "Absorption"), ("Scatter Color", far), ("Sun Direction", "Sun Direction"))
    _drive_like(node, material, pairs)
    if plain is not None:
        _placed(node, plain, ("Light Shafts",))
    return fog


def _placed(node, plain, names):
    """`node` (a group node of a material made for every placement) gets Each Placement 1, and its
    inputs `names` follow those of the same group's node in `plain` (simple-expression drivers)."""
    node.inputs["Each Placement"].default_value = 1.0
    group = bpy.utils.escape_identifier(node.name)
    for name in names:
        socket = node.inputs.get(name)
        if socket is None:
            continue
        path = f'node_tree.nodes["{group}"].inputs["{bpy.utils.escape_identifier(name)}"].default_value'
        drive_property(socket, "default_value", None, "v", [("v", "MATERIAL", plain, path)])


def _meniscus_material():
    """The waterline's material, made once and shared by every water's underwater body."""
    found = owned(bpy.data.materials, MENISCUS_ROLE)
    if found:
        return found[0]
    return _group_material(MENISCUS_ROLE, MENISCUS_ROLE, meniscus.NAME, "Shader", "Surface")[0]


def _drive_like(node, material, pairs):
    """Each (mine, theirs) of `pairs`: `node`'s input `mine` follows the input `theirs` of
    `material`'s water shader node, component by component (simple-expression drivers: the same
    values in a file opened without the add-on). Inputs either side lacks are left alone."""
    shade = _shader_node(material)
    if shade is None:
        return
    prefix = f'node_tree.nodes["{bpy.utils.escape_identifier(shade.name)}"].inputs'
    for name, their_name in pairs:
        mine, theirs = node.inputs.get(name), shade.inputs.get(their_name)
        if mine is None or theirs is None or not hasattr(theirs, "default_value"):
            continue
        path = f'{prefix}["{bpy.utils.escape_identifier(their_name)}"].default_value'
        if not hasattr(theirs.default_value, "__len__"):
            mine.default_value = theirs.default_value
            drive_property(mine, "default_value", None, "v", [("v", "MATERIAL", material, path)])
            continue
        for i in range(min(len(theirs.default_value), len(mine.default_value), 3)):
            mine.default_value[i] = theirs.default_value[i]
            drive_socket(mine, i, "v", [("v", "MATERIAL", material, f"{path}[{i}]")])


def _light_material(water, material, placed=False):
    """The caustic light's material: the `Water Caustic Light` shadow, its values the water's
    (`placed`: the one for every placement, Each Placement on)."""
    name, role = (f"{water.name} Caustic Light", LIGHT_MATERIAL_ROLE)
    if placed:
        name, role = (f"{name} Placed", LIGHT_PLACED_ROLE)
    light, node = _group_material(name, role, caustic_light.NAME, "Shadow", "Surface")
    if placed:
        node.inputs["Each Placement"].default_value = 1.0
    light[KEY] = water.name
    if hasattr(light, "use_transparent_shadow"):  # EEVEE: the shadow takes the shader's transparency
        light.use_transparent_shadow = True
    _drive_like(node, material, [(name, name) for name in _LIGHT_INPUTS])
    return light


_RAYS = ("camera", "diffuse", "glossy", "transmission", "volume_scatter", "shadow")


def _hidden_child(water, material, scene, suffix, role, seen_by, group_name):
    """A new object `"<water> <suffix>"` marked as `role`: the water's child in its collections,
    unselectable, seen only by the rays `seen_by` and by no probe, its mesh made by the Geometry
    Nodes group `group_name` from the water (`Water` input). Returns (object, its modifier).

    While the camera is above, its mesh is empty. An empty mesh with no material costs EEVEE a
    shader compile on every render (measured 3.7 s on top of a 1.9 s frame, this machine's CPU,
    docs/BENCHMARKS.md), one with a material already drawn costs nothing: it holds the water's own
    (`kind.HOLDS_WATER_MATERIAL` keeps it from being taken for a water); what its modifier makes
    carries that modifier's materials."""
    name = f"{water.name} {suffix}"
    obj = bpy.data.objects.new(name, bpy.data.meshes.new(name))
    obj.data.materials.append(material)
    obj[KEY] = water.name
    mark(obj, role, 1)
    for collection in water.users_collection or (scene.collection,):
        collection.objects.link(obj)
    obj.parent = water
    obj.hide_select = True
    obj.display_type = "BOUNDS"
    for ray in _RAYS:
        setattr(obj, f"visible_{ray}", ray in seen_by)
    for probe in ("volume", "sphere", "plane"):
        setattr(obj, f"hide_probe_{probe}", True)
    modifier = obj.modifiers.new(group_name, "NODES")
    modifier.node_group = ensure_group(SPECS[group_name], SPECS)
    set_wave_input(modifier, "Water", water)
    return obj, modifier


def _add_light(water, material, scene):
    """The water's caustic light: a sheet just under its surface that only shadow rays meet, made
    by `Water Caustic Sheet` while the camera is under the water (`nodes/under/caustic_light.py`)."""
    obj, modifier = _hidden_child(
        water, material, scene, "Caustic Light", LIGHT_ROLE, ("shadow",), caustic_sheet.NAME
    )
    set_wave_input(modifier, "Material", _light_material(water, material))
    _every_placement(modifier, _light_material(water, material, placed=True))
    return f"added '{obj.name}': the sunlight's caustic pattern on what lies under '{water.name}'"


def _every_placement(modifier, placed):
    """The body or sheet of `modifier` is made for every placement of its water, with `placed`
    (the material whose Each Placement is on) while the camera is beside the water itself."""
    set_wave_input(modifier, "Placed Material", placed)
    set_wave_input(modifier, "Every Placement", True)


NEAR_FALLBACK = 0.1  # Blender's default Clip Start: `Near` while the scene has no camera


def _drive_near(modifier, scene):
    """The body's `Near` follows the scene's camera's Clip Start (a simple-expression driver: no
    Python at render time), through a change of camera too: its variable reads the path
    `camera.data.clip_start` on the scene, so it follows whatever camera the scene has. A path
    that leads nowhere (no camera, or a deleted one) would mark the driver invalid, `Near` 0,
    until the file is reopened; the variable's fallback value (Blender's default Clip Start)
    stands in instead, and the next camera is followed at once. Made with or without a camera."""
    camera = scene.camera
    if camera is not None and camera.type == "CAMERA":
        set_wave_input(modifier, "Near", camera.data.clip_start)
    owner, path = input_property(modifier, "Near")
    driver = drive_property(owner, path, None, "near", [("near", "SCENE", scene, "camera.data.clip_start")])
    target = driver.variables["near"].targets[0]
    target.use_fallback_value, target.fallback_value = True, NEAR_FALLBACK


SAMPLES_PATH = "eevee.volumetric_samples"


def _claim_samples(water, scene, changes):
    """EEVEE's volume slices raised and its froxels made no wider than `EEVEE_VOLUME_TILE` pixels
    for the fog, held in the water's mirror set-up's name (put back with it, on Remove Water)."""
    holder = ledger_holder("mirror", water)
    claim(scene, SAMPLES_PATH, EEVEE_VOLUME_SAMPLES, holder, "volume samples", changes, at_least=True)
    tile = str(min(int(scene.eevee.volumetric_tile_size), EEVEE_VOLUME_TILE))
    claim(scene, TILE_PATH, tile, holder, "volume tile size", changes)


def add(water, scene=None):
    """Gives `water` its underwater fog (see the module's docstring) and `scene` EEVEE's volume
    samples for it, and its caustic light while it has caustics (`fit_light`); returns what it did,
    in words ([] when it has them already)."""
    material = water_material(water)
    if material is None:
        return []
    body = find(water)
    if body is not None:  # one made before Every Placement gets its fog for every placement
        plain = _modifier_input(body, "Material")
        placed = _fit_placed(water, body, lambda: _fog_material(water, material, plain=plain))
        return placed + fit_light(water, scene)
    changes = []
    if scene is not None:
        _claim_samples(water, scene, changes)
    fog = _fog_material(water, material)
    obj, modifier = _hidden_child(
        water, material, scene or bpy.context.scene, "Underwater", ROLE, ("camera",), underwater_shell.NAME
    )
    set_wave_input(modifier, "Material", fog)
    _every_placement(modifier, _fog_material(water, material, plain=fog))
    set_wave_input(modifier, "Meniscus Material", _meniscus_material())
    _drive_near(modifier, scene or bpy.context.scene)
    changes.append(f"added '{obj.name}': the water a camera under '{water.name}' sees through")
    return changes + fit_light(water, scene)


def _has_caustics(material):
    shade = _shader_node(material)
    socket = shade.inputs.get("Caustics") if shade is not None else None
    return socket is not None and socket.default_value > 0.0


def fit_light(water, scene=None):
    """Gives `water` its caustic light while it has both its underwater body and caustics
    (`Caustics` above 0), and takes it away otherwise: without caustics the light would only
    cost, and its tile would be packed into the file. Every entry point that changes Caustics
    calls this. Returns what it did, in words."""
    material = water_material(water)
    light = find(water, LIGHT_ROLE)
    wanted = material is not None and find(water) is not None and _has_caustics(material)
    if wanted and light is None:
        return [_add_light(water, material, scene or bpy.context.scene)]
    if light is not None and not wanted:
        return [_delete(light)]
    if light is not None:
        return _fit_placed(water, light, lambda: _light_material(water, material, placed=True))
    return []


def _modifier_input(obj, name):
    """The input `name` of `obj`'s shell or sheet modifier, or None."""
    modifier = obj.modifiers.get(underwater_shell.NAME) or obj.modifiers.get(caustic_sheet.NAME)
    if modifier is None or modifier.type != "NODES" or name not in input_ids(modifier):
        return None
    return get_wave_input(modifier, name)


def _fit_placed(water, obj, make):
    """A body or caustic light made before `Every Placement` gets its material for every placement
    (`make()`), its group upgraded first: a file from before renders under collection instances
    once the water is worked on again. Returns what it did, in words ([] for one that has it)."""
    modifier = obj.modifiers.get(underwater_shell.NAME) or obj.modifiers.get(caustic_sheet.NAME)
    if modifier is None or modifier.type != "NODES" or not is_original(obj):
        return []
    if modifier.node_group is not ensure_group(SPECS[modifier.name], SPECS):
        return []  # a group of the user's: theirs
    names = input_ids(modifier)
    if "Placed Material" not in names or "Every Placement" not in names:
        return []  # a newer group than this add-on's, left alone
    if _modifier_input(obj, "Placed Material") is not None or _modifier_input(obj, "Material") is None:
        return []
    _every_placement(modifier, make())
    return [f"'{obj.name}': made for every placement of '{water.name}' too (collection instances)"]


def fog_node(water):
    """The `Water Underwater Fog` node of `water`'s body's fog material, or None."""
    body = find(water)
    modifier = body.modifiers.get(underwater_shell.NAME) if body is not None else None
    fog = get_wave_input(modifier, "Material") if modifier is not None and modifier.type == "NODES" else None
    if fog is None or fog.node_tree is None:
        return None
    return fog.node_tree.nodes.get(underwater_fog.NAME)


def light_shafts(water):
    """`water`'s `Light Shafts` (0 without its underwater body: none)."""
    node = fog_node(water)
    socket = node.inputs.get("Light Shafts") if node is not None else None
    return socket.default_value if socket is not None else 0.0


def set_light_shafts(water, share):
    """Sets `water`'s `Light Shafts`, clamped to 0..1: the share of its fog's light taken by
    scattering, not absorption (`nodes/under/underwater_fog.py`). Returns what it did, in words.
    UnderwaterError (a ValueError) when the water has no underwater body (Underwater off) or its
    fog predates Light Shafts (`apply.apply_values` refuses both first)."""
    check_editable(water)
    node = fog_node(water)
    socket = node.inputs.get("Light Shafts") if node is not None else None
    if socket is None:
        why = "Underwater is off" if find(water) is None else "its underwater fog has no Light Shafts"
        raise UnderwaterError(
            f"'{water.name}' has no light shafts to set: {why} (switch Underwater off and on)"
        )
    share = min(max(float(share), 0.0), 1.0)
    if share > 0.0:  # a fog made before Light Shafts has its Sun Direction undriven
        material = water_material(water)
        if material is not None:
            _drive_like(node, material, (("Sun Direction", "Sun Direction"),))
    if socket.default_value == share:
        return []
    socket.default_value = share
    return [f"'{water.name}': Light Shafts {share:g}"]


def _delete(obj, why=""):
    mesh = obj.data
    modifier = obj.modifiers.get(underwater_shell.NAME) or obj.modifiers.get(caustic_sheet.NAME)
    names = input_ids(modifier) if modifier is not None and modifier.type == "NODES" else {}
    found = [get_wave_input(modifier, name) for name in ("Material", "Placed Material") if name in names]
    fogs = [fog for fog in found if fog is not None and role_of(fog) in _MATERIAL_ROLES]
    line = (
        get_wave_input(modifier, "Meniscus Material")
        if fogs and "Meniscus Material" in input_ids(modifier)
        else None
    )
    fogs += [line] if line is not None and role_of(line) == MENISCUS_ROLE else []
    change = f"removed '{obj.name}'{why}"
    bpy.data.objects.remove(obj)
    if mesh is not None and mesh.users == 0:
        bpy.data.meshes.remove(mesh)
    fogs = [fog for fog in fogs if is_original(fog)]
    while fogs:  # not `users`: a saved file counts the modifier's inputs once more
        gone = unused(fogs)  # the placed fog's drivers read the plain one: it goes first
        if not gone:
            break
        for fog in gone:
            fogs.remove(fog)
            bpy.data.materials.remove(fog)
    return change


def remove(water):
    """Removes `water`'s underwater object and its fog; returns what it did, in words."""
    changes = []
    for role in (ROLE, LIGHT_ROLE):
        obj = find(water, role)
        while obj is not None:
            changes.append(_delete(obj))
            obj = find(water, role)
    return changes


def switch(water, scene, on=True):
    """The `Underwater` switch: gives `water` its underwater fog or takes it away (and with it the
    volume samples it raised, when no other water needs them). Returns what it did, in words.
    NotEditableError for linked or overridden water."""
    check_editable(water)
    if on:
        return add(water, scene)
    changes = remove(water)
    if changes and scene is not None:
        holder = ledger_holder("mirror", water, stamp=False)
        release(scene, SAMPLES_PATH, holder, "volume samples", changes, _needs_samples)
        release(scene, TILE_PATH, holder, "volume tile size", changes, _needs_samples)
    return changes


def _needs_samples(holder):
    """Whether the water a ledger holder names still has its underwater fog."""
    from .ledger import holder_object

    water = holder_object(holder)
    return water is not None and find(water) is not None


def remove_lost():
    """Removes the underwater objects whose water is gone; returns what it did, in words."""
    return [_delete(o, " (its water was deleted)") for o in list(bpy.data.objects) if is_lost(o)]
