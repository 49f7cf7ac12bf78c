"""The default bump map as a Blender image: generated, packed, found by its mark (`packed_image`)."""

from . import packed_image
from .bump_map import BUMP_MAP_VERSION, water_normal_map

IMAGE_NAME = "Water Surface Bump"
VERSION_KEY = "water_surface_bump_version"


def find_bump_image():
    """The add-on's own local bump image, or None."""
    return packed_image.find(IMAGE_NAME, VERSION_KEY)


def is_bump_image(image):
    """Whether `image` is the add-on's bump image (by its mark, not its name)."""
    return packed_image.is_owned_image(image, IMAGE_NAME, VERSION_KEY)


def ensure_bump_image():
    """The packed default water normal map (a seamless tile), made if missing, stale or broken."""
    return packed_image.ensure(IMAGE_NAME, VERSION_KEY, BUMP_MAP_VERSION, water_normal_map)
