"""The foam tile as a Blender image: generated, packed, found by its mark (`packed_image`).

A group whose foam image was deleted outright is given the new one by the builder.
"""

from . import packed_image
from .foam_map import FOAM_MAP_VERSION, foam_map_rgba

IMAGE_NAME = "Water Surface Foam"
VERSION_KEY = "water_surface_foam_version"


def find_foam_image():
    """The add-on's own local foam image, or None."""
    return packed_image.find(IMAGE_NAME, VERSION_KEY)


def is_foam_image(image):
    """Whether `image` is the add-on's foam image (by its mark, not its name)."""
    return packed_image.is_owned_image(image, IMAGE_NAME, VERSION_KEY)


def ensure_foam_image():
    """The packed foam tile (grey, Non-Color, seamless), made if missing, stale or broken."""
    return packed_image.ensure(IMAGE_NAME, VERSION_KEY, FOAM_MAP_VERSION, foam_map_rgba)
