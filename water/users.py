"""Whether anything still uses a data-block, by what refers to it, not by its user count.

Blender 5.x adds a user to each data-block a Geometry Nodes modifier's input points to every time
the file is saved, and never takes it back (5.2.3: a material read by a modifier reads 2 users
after one save, 1 after its object is removed; 4.2 and 4.5 keep the count right). The underwater
body's fog and waterline materials are such inputs, so after a save `users == 0` never held for
them: Remove Water left them, and the groups and images they use, for two more saves. Blender's
own `user_map` walks the references themselves.
"""

import bpy


def unused(blocks):
    """Those of `blocks` (None skipped) that no data-block refers to and that have no fake user."""
    blocks = [block for block in blocks if block is not None]
    if not blocks:
        return []
    users = bpy.data.user_map(subset=blocks)
    return [block for block in blocks if not block.use_fake_user and not users.get(block)]
