"""The default bump map as a Blender image: generated, packed into the .blend, found by its mark.

A user's image with the same name is never touched (ours gets another name).
Ours is made again when it is stale or its pixels are gone (unpacked to a file
that no longer exists): the new image takes the old one's place in every
material and group that used it, and its name.
"""

import os

import bpy

from .bump_map import BUMP_MAP_VERSION, water_normal_map
from .ownership import is_local, mark, owned, role_of

IMAGE_NAME = "Water Surface Bump"
VERSION_KEY = "water_surface_bump_version"
SIZE = 512


def find_bump_image():
    """The add-on's own local bump image, or None."""
    found = owned(bpy.data.images, IMAGE_NAME, VERSION_KEY)
    return found[0] if found else None


def is_bump_image(image):
    """Whether `image` is the add-on's bump image (by its mark, not its name)."""
    return image is not None and is_local(image) and role_of(image, VERSION_KEY) == IMAGE_NAME


def _has_pixels(image):
    if image.packed_file is not None or image.has_data:
        return True
    if image.source == "FILE" and os.path.isfile(bpy.path.abspath(image.filepath, library=image.library)):
        return True
    return image.source == "GENERATED"


def ensure_bump_image():
    """The packed default water normal map (a seamless tile), made if missing, stale or broken."""
    image = find_bump_image()
    if image is not None and image.get(VERSION_KEY, 0) >= BUMP_MAP_VERSION and _has_pixels(image):
        return image
    fresh = bpy.data.images.new(IMAGE_NAME, SIZE, SIZE, alpha=False, float_buffer=False)
    fresh.colorspace_settings.name = "Non-Color"
    fresh.pixels.foreach_set(water_normal_map(SIZE).ravel())
    fresh.update()
    # Packing writes the pixels into the .blend, so renders need neither the add-on nor a file on disk.
    fresh.pack()
    mark(fresh, IMAGE_NAME, BUMP_MAP_VERSION, VERSION_KEY)
    if image is not None:
        name = image.name
        image.user_remap(fresh)
        bpy.data.images.remove(image)
        fresh.name = name
    return fresh
