"""What the add-on made: a mark on each data-block, so it reuses or upgrades only its own.

Every node group, image, world and probe the add-on makes carries two ID
properties: `water_surface_version` (the add-on's identity in the key, the
version of what it built in the value) and `water_surface_role` (what it is:
"Water Surface", "Water Surface Bump", "Sky", ...). A data-block without the
mark is the user's: it is never changed, even when it has the name the add-on
would give, and the add-on's own is made under another name (Blender appends
.001). Library-linked or overridden data is never reused for new water.

Files saved before the role existed carry only the version key: their role is
their name without a " (image)" or ".001" suffix.

Blender copies ID properties with the data-block, so a copy the user makes of one of
ours (Shift+D on a group, a world or a collection) carries the mark too. The mark
therefore also holds the name the block had when the add-on stamped it
(`water_surface_name`): a block whose name differs is a copy, the user's. It still
reads as what it was copied from (`role_of`: a material using a copied group is still
a water), but the add-on never reuses (`owned`) or rebuilds it (`is_original`).
Marks made before the name existed are taken as the add-on's only while the block's
name is the role's (with Blender's ".001" or the image's " (...)" suffix at most), except
for the objects, probes and collections named after their water, which stay the add-on's.
"""

import re

VERSION_KEY = "water_surface_version"
ROLE_KEY = "water_surface_role"
NAME_KEY = "water_surface_name"

_NAMED_AFTER_THEIR_WATER = {"OBJECT", "COLLECTION", "LIGHT_PROBE"}
_SUFFIX = re.compile(r"( \(.*\))?(\.\d{3,})?$")


def is_local(block):
    """Whether `block` lives in this file and may be edited (not linked, not overridden)."""
    return block.library is None and getattr(block, "override_library", None) is None


def role_of(block, version_key=VERSION_KEY):
    """The role of a data-block the add-on made, or None for anyone else's."""
    if block.get(version_key) is None:
        return None
    role = block.get(ROLE_KEY)
    return role if isinstance(role, str) else _SUFFIX.sub("", block.name)


def is_original(block, version_key=VERSION_KEY):
    """Whether `block` is one the add-on made itself, not a copy of one the user made (its stamped
    name is its name), and local: the add-on may reuse, upgrade or remove it."""
    role = role_of(block, version_key)
    if role is None or not is_local(block):
        return False
    stamped = block.get(NAME_KEY)
    if isinstance(stamped, str):
        return stamped == block.name
    return _SUFFIX.sub("", block.name) == role or block.id_type in _NAMED_AFTER_THEIR_WATER


def mark(block, role, version, version_key=VERSION_KEY):
    """Stamps `block` as the add-on's `role`, built at `version`, under its current name (call
    again after renaming one of ours)."""
    block[version_key] = version
    block[ROLE_KEY] = role
    block[NAME_KEY] = block.name


def owned(blocks, role, version_key=VERSION_KEY):
    """The local data-blocks among `blocks` the add-on made as `role` (never a user's copy of one),
    exact names first."""
    found = [b for b in blocks if role_of(b, version_key) == role and is_original(b, version_key)]
    return sorted(found, key=lambda b: (b.name != role, b.name))
