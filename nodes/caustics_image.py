"""The caustic tile as a Blender image: generated, packed, found by its mark (`packed_image`)."""

from . import packed_image
from .caustics_map import CAUSTICS_MAP_VERSION, caustics_map_rgba

IMAGE_NAME = "Water Surface Caustics"
VERSION_KEY = "water_surface_caustics_version"


def find_caustics_image():
    """The add-on's own local caustic image, or None."""
    return packed_image.find(IMAGE_NAME, VERSION_KEY)


def is_caustics_image(image):
    """Whether `image` is the add-on's caustic image (by its mark, not its name)."""
    return packed_image.is_owned_image(image, IMAGE_NAME, VERSION_KEY)


def ensure_caustics_image():
    """The packed caustic tile (grey, Non-Color, seamless, mean 1 / PEAK), made if missing or stale."""
    return packed_image.ensure(IMAGE_NAME, VERSION_KEY, CAUSTICS_MAP_VERSION, caustics_map_rgba)
