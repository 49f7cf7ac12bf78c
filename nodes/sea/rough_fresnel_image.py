"""The rough Fresnel table as a Blender image: generated, packed (float), found by its mark."""

from .. import packed_image
from .rough_fresnel import SIZE, TABLE_VERSION, table_rgba

IMAGE_NAME = "Water Surface Rough Fresnel"
VERSION_KEY = "water_surface_rough_fresnel_version"


def ensure_rough_fresnel_image():
    """The packed table of water's reflectance over unresolved slopes, made if missing or stale."""
    return packed_image.ensure(
        IMAGE_NAME, VERSION_KEY, TABLE_VERSION, table_rgba, size=SIZE, float_buffer=True
    )
