"""The open sea's operators (`water/sea/`): its swell."""

from .swell import OBJECT_OT_water_sea_swell

classes = (OBJECT_OT_water_sea_swell,)
