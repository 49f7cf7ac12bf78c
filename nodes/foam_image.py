"""The foam tile as a Blender image: generated, packed into the .blend, found by its mark.

Like the bump image (`bump_image.py`): a user's image named `Water Surface Foam` is never touched
(ours gets another name), and ours is made again when it is stale or its pixels are gone; the new
one takes the old one's place (and name) in every group that sampled it. A group whose foam image
was deleted outright is given the new one by the builder.
"""

import bpy

from .bump_image import _has_pixels
from .foam_map import FOAM_MAP_VERSION, foam_map_rgba
from .ownership import is_local, mark, owned, role_of

IMAGE_NAME = "Water Surface Foam"
VERSION_KEY = "water_surface_foam_version"
SIZE = 512


def find_foam_image():
    """The add-on's own local foam image, or None."""
    found = owned(bpy.data.images, IMAGE_NAME, VERSION_KEY)
    return found[0] if found else None


def is_foam_image(image):
    """Whether `image` is the add-on's foam image (by its mark, not its name)."""
    return image is not None and is_local(image) and role_of(image, VERSION_KEY) == IMAGE_NAME


def ensure_foam_image():
    """The packed foam tile (grey, Non-Color, seamless), made if missing, stale or broken."""
    image = find_foam_image()
    if image is not None and image.get(VERSION_KEY, 0) >= FOAM_MAP_VERSION and _has_pixels(image):
        return image
    fresh = bpy.data.images.new(IMAGE_NAME, SIZE, SIZE, alpha=False, float_buffer=False)
    fresh.colorspace_settings.name = "Non-Color"
    fresh.pixels.foreach_set(foam_map_rgba(SIZE).ravel())
    fresh.update()
    fresh.pack()
    mark(fresh, IMAGE_NAME, FOAM_MAP_VERSION, VERSION_KEY)
    if image is not None:
        name = image.name
        image.user_remap(fresh)
        bpy.data.images.remove(image)
        fresh.name = name
    return fresh
