"""Node groups and materials, each described as data and built by one builder."""


def register():
    pass


def unregister():
    pass
