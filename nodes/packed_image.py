"""A generated image the add-on owns: packed into the .blend, found by its mark, made again when lost.

A user's image with the same name is never touched (ours gets another name). Ours is
made again when it is stale or its pixels are gone (unpacked to a file that no longer
exists): the new image takes the old one's place, and its name, wherever it was used.
"""

import os

import bpy

from .ownership import is_original, mark, owned, role_of

SIZE = 512


def find(name, version_key):
    """The add-on's own local image `name` (by its mark), or None."""
    found = owned(bpy.data.images, name, version_key)
    return found[0] if found else None


def is_owned_image(image, name, version_key):
    """Whether `image` is the add-on's image `name` (by its mark, not its name)."""
    return image is not None and role_of(image, version_key) == name and is_original(image, version_key)


def has_pixels(image):
    if image.packed_file is not None or image.has_data:
        return True
    if image.source == "FILE" and os.path.isfile(bpy.path.abspath(image.filepath, library=image.library)):
        return True
    return image.source == "GENERATED"


def ensure(name, version_key, version, rgba, size=SIZE, float_buffer=False):
    """The packed Non-Color image `name` at `version`; `rgba(size)` makes its pixels when needed
    (a float image, for a table whose values must stay exact, is packed as OpenEXR)."""
    image = find(name, version_key)
    if image is not None and image.get(version_key, 0) >= version and has_pixels(image):
        return image
    fresh = bpy.data.images.new(name, size, size, alpha=False, float_buffer=float_buffer)
    fresh.colorspace_settings.name = "Non-Color"
    fresh.pixels.foreach_set(rgba(size).ravel())
    fresh.update()
    # Packing writes the pixels into the .blend, so renders need neither the add-on nor a file on disk.
    fresh.pack()
    mark(fresh, name, version, version_key)
    if image is not None:
        old_name = image.name
        image.user_remap(fresh)
        bpy.data.images.remove(image)
        fresh.name = old_name
        mark(fresh, name, version, version_key)  # under the name it took over
    return fresh
