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
"""

import re

VERSION_KEY = "water_surface_version"
ROLE_KEY = "water_surface_role"

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


def mark(block, role, version, version_key=VERSION_KEY):
    """Stamps `block` as the add-on's `role`, built at `version`."""
    block[version_key] = version
    block[ROLE_KEY] = role


def owned(blocks, role, version_key=VERSION_KEY):
    """The local data-blocks among `blocks` the add-on made as `role`, exact names first."""
    found = [b for b in blocks if is_local(b) and role_of(b, version_key) == role]
    return sorted(found, key=lambda b: (b.name != role, b.name))
