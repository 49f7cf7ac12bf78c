"""The add-on's one handler: before a file is saved, what deleted waters left behind goes.

No handler runs at render time or per frame: a saved file renders the same without the add-on.
"""

import bpy

from .water import removal


@bpy.app.handlers.persistent
def _before_save(_path, *_args):
    """A water deleted the ordinary way (X, Delete) leaves nothing of the add-on's in the file."""
    removal.remove_leftovers()


def register():
    if _before_save not in bpy.app.handlers.save_pre:
        bpy.app.handlers.save_pre.append(_before_save)


def unregister():
    if _before_save in bpy.app.handlers.save_pre:
        bpy.app.handlers.save_pre.remove(_before_save)
