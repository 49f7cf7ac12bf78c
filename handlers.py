"""The add-on's handlers, all at edit time: what deleted waters and hulls leave behind goes at once.

Deleting a water the ordinary way (X, Delete) only takes it out of the scene: its underwater
body's modifier still refers to it, so Blender keeps it, and its hidden children, and a camera
under where it was would still see its fog and waterline; a deleted hull keeps its dry hole in the
water. No node can see that an object left the scene (an Object Info or Texture Coordinate node
still reads it), so `_after_update` takes them apart (`removal.remove_leftovers`) at the first
update after objects left the scenes, and `_before_save` once more before every save, so no saved
file holds any of it.

`_after_update` costs nothing while objects only move or change (it looks only when a collection
or scene changed, and then only counts objects), never acts in a render's depsgraph or while a
render runs, nor in the middle of the add-on's own work, and never touches linked or overridden
data. None runs at render time or per frame: a saved file renders the same without the add-on.
"""

import sys

import bpy

from .water import removal

_PACKAGE = __package__
# At the last look: (objects in the file, objects in the scenes, each scene's counted); None: none
# yet (a file just opened: only its later changes count). `force`: look after an undo or redo,
# which may bring back a state from before the clean-up.
_seen = {"counts": None, "force": False}


def _counts():
    return len(bpy.data.objects), sum(len(scene.objects) for scene in bpy.data.scenes)


def _inside_add_on():
    """Whether the add-on's own code runs below this handler: it evaluates the depsgraph as it
    goes, half its work done, and takes apart what it removes itself."""
    try:
        frame = sys._getframe(2)  # below `_after_update`
    except ValueError:  # called by Blender itself (the interface's update): no Python below
        return False
    while frame is not None:
        name = frame.f_globals.get("__name__", "")
        if name == _PACKAGE or name.startswith(_PACKAGE + "."):
            return True
        frame = frame.f_back
    return False


@bpy.app.handlers.persistent
def _after_update(_scene, depsgraph):
    """Objects left the scenes (deleted, or a scene deleted): what the add-on made for them goes."""
    if depsgraph.mode != "VIEWPORT" or bpy.app.is_job_running("RENDER"):
        return
    if not (_seen["force"] or depsgraph.id_type_updated("COLLECTION") or depsgraph.id_type_updated("SCENE")):
        return
    counts = _counts()
    before, _seen["counts"] = _seen["counts"], counts
    left = before is not None and (counts[0] < before[0] or counts[1] < before[1])
    if not (left or _seen["force"]) or _inside_add_on():
        return
    _seen["force"] = False
    removal.remove_leftovers()
    _seen["counts"] = _counts()


@bpy.app.handlers.persistent
def _after_load(*_args):
    _seen["counts"], _seen["force"] = None, False


@bpy.app.handlers.persistent
def _after_undo(*_args):
    _seen["force"] = True


@bpy.app.handlers.persistent
def _before_save(_path, *_args):
    """A water deleted the ordinary way (X, Delete) leaves nothing of the add-on's in the file."""
    removal.remove_leftovers()


_HANDLERS = (
    ("depsgraph_update_post", _after_update),
    ("load_post", _after_load),
    ("undo_post", _after_undo),
    ("redo_post", _after_undo),
    ("save_pre", _before_save),
)


def register():
    _after_load()
    for name, handler in _HANDLERS:
        if handler not in getattr(bpy.app.handlers, name):
            getattr(bpy.app.handlers, name).append(handler)


def unregister():
    for name, handler in _HANDLERS:
        if handler in getattr(bpy.app.handlers, name):
            getattr(bpy.app.handlers, name).remove(handler)
