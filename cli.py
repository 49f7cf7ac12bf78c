"""Command-line commands (`blender -c water_surface ...`)."""


def register():
    pass


def unregister():
    pass
