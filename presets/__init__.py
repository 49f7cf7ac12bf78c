"""Water presets: JSON data, validated when read, never executed."""


def register():
    pass


def unregister():
    pass
