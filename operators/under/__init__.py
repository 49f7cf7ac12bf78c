"""The view from below the surface: the `Underwater` switch (`water/underwater.py`)."""

from .underwater import OBJECT_OT_water_underwater

classes = (OBJECT_OT_water_underwater,)
