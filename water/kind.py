"""What a water is, and what it may do: the one place that decides.

A water is an object whose material the add-on made. Its kind comes from the data: lake
shading (the `Water Surface` group node) is a lake; ocean shading (the `Water Ocean Shade` and
`Water Ocean Normal` nodes) is the seeds' ocean, or an open sea when Blender's Ocean modifier
drives it (`open_sea.is_open_sea`). What each kind allows is the table `FEATURES`; the polls,
the panel, the operators, the API and the water functions they call ask `allows` or `refusal`
and nowhere else decides (the add pipeline and repair read the kind only to build its material).
"""

from ..nodes.material import water_node
from ..nodes.ownership import role_of
from ..nodes.sea.ocean_material import ocean_nodes
from .sea import open_sea

LAKE = "lake"
OCEAN = "ocean"
OPEN_SEA = "open_sea"

# What each kind of water allows, the only place that says it: every key is asked somewhere
# (`allows`, `refusal` or a poll's `water_allowing`; `tests/plain/test_features_once.py`). The
# mirror set-up's probe and light linking, the sun and bump choices, lake presets and Cycles'
# physical caustics are the lake shading's; every kind has ray tracing, surroundings, switched
# shader parts (the caustics; the lake's depth colour and foam too), floating, a wake, keep-out,
# repair and the underwater fog. Four-sine waves are the lake's and the seeds' ocean's (the open
# sea's are its Ocean modifier); whitecaps and a swell are the open sea's. The seeds' ocean
# shades with the normal its waves store (`stored_normal`): a wake on it tilts that one too.
_EVERY_KIND = {
    "ray_tracing",
    "surroundings",
    "shader_parts",
    "floating",
    "wake",
    "keep_out",
    "repair",
    "underwater",
}
FEATURES = {
    LAKE: frozenset(
        _EVERY_KIND | {"waves", "mirror", "physical_caustics", "presets", "sun_choice", "bump_choice"}
    ),
    OCEAN: frozenset(_EVERY_KIND | {"waves", "stored_normal"}),
    OPEN_SEA: frozenset(_EVERY_KIND | {"whitecaps", "swell"}),
}

# Why a kind refuses a feature, in words for a poll message or an error.
_WHY = {
    "mirror": "it reflects the world's sky and needs no mirror probe",
    "presets": "presets hold lake water values (edit it in the panel)",
    "physical_caustics": "physical caustics are set up for lake water",
    "sun_choice": "this choice is for lake water",
    "bump_choice": "this choice is for lake water",
    "waves": "its waves are Blender's Ocean modifier (set them in the panel)",
    "whitecaps": "whitecaps are the open sea's",
    "swell": "a swell is the open sea's (add one with Open Sea)",
}
_NAMES = {LAKE: "lake", OCEAN: "ocean shading", OPEN_SEA: "an open sea"}


def shading_of(material):
    """LAKE or OCEAN for a material the add-on made (its group nodes), else None."""
    if material is None:
        return None
    if water_node(material) is not None:
        return LAKE
    return OCEAN if ocean_nodes(material) is not None else None


# The add-on's hidden children that hold their water's material in a slot (`underwater.py`: an
# empty mesh with no material costs EEVEE a shader compile on every render): not waters.
HOLDS_WATER_MATERIAL = ("Underwater", "Caustic Light")


def water_material(obj):
    """The first material of `obj` made by the add-on (lake or ocean shading), or None."""
    if obj is None or getattr(obj, "type", None) != "MESH" or role_of(obj) in HOLDS_WATER_MATERIAL:
        return None
    for slot in obj.material_slots:
        if shading_of(slot.material) is not None:
            return slot.material
    return None


def kind_of(obj):
    """LAKE, OCEAN or OPEN_SEA for a water object, None for anything else."""
    shading = shading_of(water_material(obj))
    if shading == OCEAN and open_sea.is_open_sea(obj):
        return OPEN_SEA
    return shading


def kind_of_values(values):
    """The kind a water added from preset `values` will be."""
    if values.get("sea"):
        return OPEN_SEA
    return OCEAN if values.get("shading", LAKE) == "ocean" else LAKE


def preset_refusal(preset_name, values):
    """Why a preset's `values` cannot be applied to an existing lake (they build their own mesh and
    shading), one line, or None when they can."""
    if kind_of_values(values) == LAKE:
        return None
    return f"'{preset_name}' builds its own mesh and shading: add it from Add > Mesh"


def allows(obj, feature):
    """Whether water `obj` has or may be given `feature` (a key of FEATURES' sets)."""
    kind = kind_of(obj)
    return kind is not None and feature in FEATURES[kind]


def refusal(obj, feature, subject="The active object"):
    """Why `obj` may not have `feature`, one line starting with `subject`, or None when it may."""
    kind = kind_of(obj)
    if kind is None:
        return f"{subject} is not water (no Water Surface material)"
    if feature in FEATURES[kind]:
        return None
    return f"{subject} is {_NAMES[kind]}: {_WHY.get(feature, f'{feature} is not for it')}"
