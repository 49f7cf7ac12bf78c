"""The default bump map as a Blender image: generated once, packed into the .blend, reused by name."""

import bpy

from .bump_map import BUMP_MAP_VERSION, water_normal_map

IMAGE_NAME = "Water Surface Bump"
VERSION_KEY = "water_surface_bump_version"
SIZE = 512


def ensure_bump_image():
    """The packed default water normal map (a seamless tile), made if missing or stale."""
    image = bpy.data.images.get(IMAGE_NAME)
    if image is not None and image.get(VERSION_KEY, 0) >= BUMP_MAP_VERSION and image.has_data:
        return image
    if image is None:
        image = bpy.data.images.new(IMAGE_NAME, SIZE, SIZE, alpha=False, float_buffer=False)
    else:
        image.scale(SIZE, SIZE)
    image.colorspace_settings.name = "Non-Color"
    image.pixels.foreach_set(water_normal_map(SIZE).ravel())
    image.update()
    # Packing writes the pixels into the .blend, so renders need neither the add-on nor a file on disk.
    image.pack()
    image[VERSION_KEY] = BUMP_MAP_VERSION
    return image
